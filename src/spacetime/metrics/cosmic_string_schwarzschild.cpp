// Schwarzschild black hole pierced by a straight cosmic string along the axis (Motion4D
// "CosmicStringSchwarzschild"; Aryal, Ford & Vilenkin, Phys. Rev. D 34 (1986) 2263; Müller &
// Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Cosmic string in Schwarzschild spacetime"):
//   ds² = −(1 − r_s/r) dt² + dr²/(1 − r_s/r) + r² (dθ² + β² sin²θ dφ²),  r_s = 2M,
// i.e. Schwarzschild with the azimuth φ ∈ [0, 2π) covering only the angle 2πβ: a conical deficit
// 2π(1 − β) around the axis (β = 1 − 4μ for a string of linear mass density μ). Locally it is
// Schwarzschild (vacuum, the same curvature); globally light is deflected at the string.
// Christoffel symbols: those of Schwarzschild with g_φφ multiplied by β² (diagonal_metric.h; the
// factor cancels in every Γ^φ and gives Γ^r_φφ, Γ^θ_φφ a factor β²). Natural tetrad: static,
// e_(3) = ∂_φ/(β r sin θ). Stop at the horizon break radius r_s (1 + horizon_eps).
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// cosmic_string_schwarzschild_packet_acceleration below): g_μμ and −Γkk are the templates of
// cosmic_string_schwarzschild_accel.h.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/cosmic_string_schwarzschild.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_COSMIC_STRING_SCHWARZSCHILD_ONCE_
#define GEOVIS_METRICS_COSMIC_STRING_SCHWARZSCHILD_ONCE_
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"
#include "spacetime/metrics/static_spherical.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/cosmic_string_schwarzschild_accel.h"
}  // namespace scalar

class CosmicStringSchwarzschild final : public MetricCRTP<CosmicStringSchwarzschild> {
 public:
  CosmicStringSchwarzschild()
      : MetricCRTP({"CosmicStringSchwarzschild",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"beta", 0.5, 0.0, 1.0, true, false,
                      "cone factor beta in (0, 1]: the azimuth covers 2 pi beta (beta = 1: Schwarzschild)"},
                     {"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0 of the black hole (r_s = 2M)"}},
                    {TetradKind::Default},
                    "Schwarzschild black hole with a cosmic string (Aryal, Ford & Vilenkin, PRD 34 (1986) 2263; "
                    "Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 10, M_PI / 2, 0}},
                    {{"beta", 1.0}, {"mass", 0.0}}}) {
    on_params_changed();
  }

  /// The line element (cosmic_string_schwarzschild_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::cosmic_string_schwarzschild_metric_tensor(rs_, b2_, x, g);
  }

  /// g_μμ and their derivatives (cosmic_string_schwarzschild_accel.h).
  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    scalar::cosmic_string_schwarzschild_diagonal(rs_, b2_, x, d);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  /// −Γ^μ_{ab} k^a k^b of the diagonal metric (cosmic_string_schwarzschild_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    scalar::cosmic_string_schwarzschild_accel(rs_, b2_, x, k, a);
  }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel([this](const auto& xx, const auto& kk,
                                   auto& a) { scalar::cosmic_string_schwarzschild_accel(rs_, b2_, xx, kk, a); },
                            x, k, Y, t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// Outside the horizon break radius r_s (1 + horizon_eps), off the axis (the string).
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_break_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  /// Effective potential, circular orbits and embedding of the equatorial plane, where g_φφ = β² r²
  /// (static_spherical.h with C = β² r²: the cone z' = √(1 − β²) in flat space for M = 0).
  std::vector<MetricFunction> functions() const override {
    const double rs = rs_, b2 = b2_;
    return static_spherical_functions(
        [rs, b2](double r) {
          return StaticSphericalFunctions{1.0 - rs / r, rs / (r * r), 1.0 / (1.0 - rs / r), b2 * r * r, 2.0 * b2 * r};
        },
        rs, rs + 20.0 * std::max(0.5 * rs, 0.5));
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (x[1] > rs_) diagonal(x, d);
    if (!(x[1] > rs_) || !diagonal_static_tetrad(d.h, e))
      throw Error("CosmicStringSchwarzschild: no static observer at r = " + std::to_string(x[1]) +
                  " (needs r > r_s = " + std::to_string(rs_) + " and sin(theta) != 0)");
    return e;
  }

 protected:
  void on_params_changed() override {
    b2_ = p(0) * p(0);
    rs_ = 2.0 * p(1);
    r_break_ = rs_ > 0.0 ? rs_ * (1.0 + horizon_eps_) : 1e-300;
  }

 private:
  double b2_ = 0.25, rs_ = 2.0, r_break_ = 2.0;
};

std::unique_ptr<Metric> make_metric_CosmicStringSchwarzschild() {
  return std::make_unique<CosmicStringSchwarzschild>();
}

}  // namespace geovis
#endif  // GEOVIS_METRICS_COSMIC_STRING_SCHWARZSCHILD_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/diagonal_metric_accel.h"
#include "spacetime/metrics/cosmic_string_schwarzschild_accel.h"

void cosmic_string_schwarzschild_packet_acceleration(double rs, double b2, const double* y, double* a) {
  packet_acceleration_simd([=](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k,
                               Vec4T<SimdD>& acc) { cosmic_string_schwarzschild_accel(rs, b2, x, k, acc); },
                           y, a, kPacketLanes);
}
void cosmic_string_schwarzschild_packet_jacobi_terms(double rs, double b2, const double* y, double* t) {
  packet_jacobi_terms_simd(
      [&](const auto& x, const auto& k, auto& a) { cosmic_string_schwarzschild_accel(rs, b2, x, k, a); }, y, t,
      kPacketLanes);
}
void cosmic_string_schwarzschild_packet_constraint(double rs, double b2, const double* y, double target, double* value,
                                                   double* scale) {
  packet_constraint_simd(
      [rs, b2](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { cosmic_string_schwarzschild_metric_tensor(rs, b2, x, g); }, y,
      target, value, scale, kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(cosmic_string_schwarzschild_packet_acceleration);
void CosmicStringSchwarzschild::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(cosmic_string_schwarzschild_packet_acceleration)(rs_, b2_, y, a);
}
HWY_EXPORT(cosmic_string_schwarzschild_packet_jacobi_terms);
void CosmicStringSchwarzschild::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(cosmic_string_schwarzschild_packet_jacobi_terms)(rs_, b2_, y, t);
}
HWY_EXPORT(cosmic_string_schwarzschild_packet_constraint);
void CosmicStringSchwarzschild::packet_constraint_simd(const double* y, double target, double* value,
                                                       double* scale) const {
  HWY_DYNAMIC_DISPATCH(cosmic_string_schwarzschild_packet_constraint)(rs_, b2_, y, target, value, scale);
}
}  // namespace geovis
#endif
