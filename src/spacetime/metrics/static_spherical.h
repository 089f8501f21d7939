// Motion4D's extras for a static, spherically symmetric line element in (t, r, θ, φ)
//   ds² = −A(r) dt² + B(r) dr² + C(r) (dθ² + sin²θ dφ²):
// the effective potential of light, the velocity of circular orbits and the embedding function
// (`geovis metrics --info`). Formulas from the geodesic equations in the plane θ = π/2 with the
// constants of motion E = A ṫ, L = C φ̇ (Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184,
// and Motion4D's effPotentialValue / getCircularVelocity / calcEmbeddingZ of each metric):
//   light:    A B ṙ² + L² A/C = E²,  so V(r) = A/C (per unit L², the ray has E²/L² >= V);
//   circular: Ω² = (dφ/dt)² = A'/C', measured by the static observer β = √C Ω/√A, i.e.
//             β² = C A'/(A C'), a timelike circular geodesic where 0 <= β² < 1;
//   embedding of t = const, θ = π/2 as a surface of revolution z(ρ) in Euclidean space with
//             ρ² = C: dz/dr = √(B − C'²/(4C)), z(r0) = 0 at the lower end r0 of the range.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "spacetime/metric.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

/// A, A', B, C, C' of the line element above at r.
struct StaticSphericalFunctions {
  double A, dA, B, C, dC;
};

/// The three extras over r in [r0, r1] (r0: the inner edge, e.g. the horizon; the embedding
/// starts there). `abc` must be callable on [r0, r1]; it may return NaN outside its domain.
inline std::vector<MetricFunction> static_spherical_functions(std::function<StaticSphericalFunctions(double)> abc,
                                                              double r0, double r1) {
  std::vector<MetricFunction> out;
  out.push_back({"effective potential of light V(r) = -g_tt/g_phiphi at theta = pi/2 (E^2/L^2 >= V)", "r", r0, r1,
                 [abc](double r) -> double {
                   const StaticSphericalFunctions s = abc(r);
                   return s.A / s.C;
                 }});
  out.push_back({"velocity of circular timelike geodesics for the static observer, beta = sqrt(C A'/(A C'))", "r", r0,
                 r1, [abc](double r) -> double {
                   const StaticSphericalFunctions s = abc(r);
                   const double b2 = s.C * s.dA / (s.A * s.dC);
                   return b2 >= 0.0 && b2 < 1.0 ? std::sqrt(b2) : NAN;
                 }});
  out.push_back({"embedding function z(r) with dz/dr = sqrt(B - C'^2/(4C)), z(r0) = 0", "r", r0, r1,
                 [abc, r0](double r) -> double {
                   // Substitution r = r0 + u² (dr = 2u du) removes the 1/√(r − r0) singularity of
                   // dz/dr at a horizon; then composite 5-point Gauss–Legendre in u.
                   if (!(r >= r0)) return NAN;
                   if (r == r0) return 0.0;
                   const double U = std::sqrt(r - r0);
                   constexpr int kPanels = 64;
                   static constexpr double xg[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                                    0.9061798459386640};
                   static constexpr double wg[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                                    0.2369268850561891, 0.2369268850561891};
                   double z = 0;
                   const double hu = U / kPanels;
                   for (int p = 0; p < kPanels; ++p)
                     for (int i = 0; i < 5; ++i) {
                       const double u = hu * (p + 0.5 + 0.5 * xg[i]);
                       const StaticSphericalFunctions s = abc(r0 + u * u);
                       const double q = s.B - s.dC * s.dC / (4.0 * s.C);
                       if (!(q >= 0.0)) return NAN;  // not embeddable in Euclidean space here
                       z += 0.5 * hu * wg[i] * std::sqrt(q) * 2.0 * u;
                     }
                   return z;
                 }});
  return out;
}

/// The extras of a metric that provides `void diagonal(const Vec4& x, DiagonalMetric& d) const` in
/// the form of spherical_diagonal (diagonal_metric.h): A = −h_0, B = h_1, C = h_2 on the equator.
template <class M>
std::vector<MetricFunction> static_spherical_functions_of(const M& m, double r0, double r1) {
  return static_spherical_functions(
      [m](double r) {
        DiagonalMetric d;
        m.diagonal(Vec4{{0.0, r, M_PI / 2, 0.0}}, d);
        return StaticSphericalFunctions{-d.h[0], -d.dh[1][0], d.h[1], d.h[2], d.dh[1][2]};
      },
      r0, r1);
}

}  // namespace geovis
