#include "spacetime/jacobi.h"

#include "spacetime/metric.h"

namespace geovis {

void optical_tidal_matrix(const Metric& m, const Vec4& x, const Vec4& k, const Vec4& s1, const Vec4& s2,
                          double T[4]) {
  Riemann R;
  m.riemann(x, R);
  Mat4 g;
  m.metric_tensor(x, g);
  // W^α = R^α_{νρσ} k^ν s_b^ρ k^σ for b = 1, 2; then T_ab = −g_{μα} s_a^μ W_b^α.
  const Vec4* s[2] = {&s1, &s2};
  for (int b = 0; b < 2; ++b) {
    Vec4 W{{0, 0, 0, 0}};
    for (int al = 0; al < 4; ++al)
      for (int nu = 0; nu < 4; ++nu)
        for (int rho = 0; rho < 4; ++rho)
          for (int sg = 0; sg < 4; ++sg) W[al] += R.R[al][nu][rho][sg] * k[nu] * (*s[b])[rho] * k[sg];
    for (int a = 0; a < 2; ++a) T[2 * a + b] = -dot(g, *s[a], W);
  }
}

JacobiParams jacobi_params(const double J[4], double lambda) {
  // Singular values of a 2x2 matrix in closed form (Blinn, "Consider the lowly 2x2 matrix").
  const double E = 0.5 * (J[0] + J[3]), F = 0.5 * (J[0] - J[3]);
  const double G = 0.5 * (J[2] + J[1]), H = 0.5 * (J[2] - J[1]);
  const double Q = std::sqrt(E * E + H * H), Rr = std::sqrt(F * F + G * G);
  JacobiParams p;
  p.d_plus = Q + Rr;
  p.d_minus = std::fabs(Q - Rr);
  const double a1 = std::atan2(G, F), a2 = std::atan2(H, E);
  p.angle = 0.5 * (a2 + a1);
  const double prod = p.d_plus * p.d_minus;
  p.mu = prod > 0 ? lambda * lambda / prod : 0.0;
  const double sum = p.d_plus + p.d_minus;
  p.ellipticity = sum > 0 ? std::fabs(p.d_plus - p.d_minus) / sum : 0.0;
  return p;
}

}  // namespace geovis
