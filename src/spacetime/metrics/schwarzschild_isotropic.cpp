// Schwarzschild spacetime in isotropic Cartesian coordinates (t, x, y, z), G = c = 1:
//   ds² = −((1 − ρ_s/ρ)/(1 + ρ_s/ρ))² dt² + (1 + ρ_s/ρ)⁴ (dx² + dy² + dz²),
//   ρ = sqrt(x² + y² + z²),  ρ_s = M/2
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Schwarzschild spacetime /
// Isotropic coordinates". Schwarzschild radius: r = ρ (1 + ρ_s/ρ)²; the horizon r = 2M is ρ = ρ_s.
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// schwarzschild_isotropic_packet_acceleration below): g_μμ and −Γkk are the templates of
// schwarzschild_isotropic_accel.h.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/schwarzschild_isotropic.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_SCHWARZSCHILD_ISOTROPIC_ONCE_
#define GEOVIS_METRICS_SCHWARZSCHILD_ISOTROPIC_ONCE_
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/schwarzschild_isotropic_accel.h"
}  // namespace scalar

class SchwarzschildIsotropic final : public MetricCRTP<SchwarzschildIsotropic> {
 public:
  SchwarzschildIsotropic()
      : MetricCRTP({"SchwarzschildIsotropic",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0 of the black hole (horizon at rho = M/2)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Schwarzschild black hole in isotropic coordinates (Mueller & Grave, Catalogue of Spacetimes, "
                    "arXiv:0904.4184)",
                    Vec4{{0, 6, 0, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  /// The line element (schwarzschild_isotropic_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::schwarzschild_isotropic_metric_tensor(rho_s_, x, g);
  }

  /// g_μμ and their derivatives (schwarzschild_isotropic_accel.h).
  void diagonal(const Vec4& x, DiagonalMetric& d) const { scalar::schwarzschild_isotropic_diagonal(rho_s_, x, d); }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  /// −Γ^μ_{ab} k^a k^b of the diagonal metric (schwarzschild_isotropic_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    scalar::schwarzschild_isotropic_accel(rho_s_, x, k, a);
  }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::schwarzschild_isotropic_accel(rho_s_, xx, kk, a); },
        x, k, Y, t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// Outside the horizon ρ = ρ_s (margin 1e-8 as Schwarzschild). The isotropic chart also covers
  /// the second exterior ρ < ρ_s, which a ray cannot reach without crossing the horizon.
  bool is_valid(const Vec4& x) const override {
    const double rho = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    return rho > rho_min_ && std::isfinite(x[0]) && std::isfinite(rho);
  }

  /// Static observer: e_(0) = ∂_t/α, e_(i) = ∂_i/ψ².
  /// Escape (escape.h): Schwarzschild's photon sphere r = 3M is ρ + M + M²/(4ρ) = 3M, i.e.
  /// ρ_ph = (1 + √3/2) M = (2 + √3) ρ_s; r(ρ) increases for ρ > ρ_s, so h² grows with ρ beyond
  /// ρ_ph; ρ = |x| = |p|, dρ/dλ ∝ x·k.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    const double rho = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    return escapes_spherical(rho, x[1] * k[1] + x[2] * k[2] + x[3] * k[3], (2.0 + std::sqrt(3.0)) * rho_s_, r_min, rho,
                             radius);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double rho = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    if (!(rho > rho_s_))
      throw Error("SchwarzschildIsotropic: no static observer at rho = " + std::to_string(rho) +
                  " (needs rho > M/2 = " + std::to_string(rho_s_) + ")");
    DiagonalMetric d;
    diagonal(x, d);
    Tetrad e;
    diagonal_static_tetrad(d.h, e);
    return e;
  }

 protected:
  void on_params_changed() override {
    rho_s_ = 0.5 * p(0);
    // Metric::horizon_eps in terms of 1 − r_s/r = ((ρ − ρ_s)/(ρ + ρ_s))² (areal radius r), as in
    // the Schwarzschild chart: ρ_break = ρ_s (1 + √eps)/(1 − √eps).
    const double se = std::sqrt(horizon_eps_);
    rho_min_ = rho_s_ > 0.0 ? rho_s_ * (1.0 + se) / (1.0 - se) : 1e-300;
  }

 private:
  double rho_s_ = 0.5, rho_min_ = 0.5;
};

std::unique_ptr<Metric> make_metric_SchwarzschildIsotropic() { return std::make_unique<SchwarzschildIsotropic>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_SCHWARZSCHILD_ISOTROPIC_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/diagonal_metric_accel.h"
#include "spacetime/metrics/schwarzschild_isotropic_accel.h"

void schwarzschild_isotropic_packet_acceleration(double rho_s, const double* y, double* a) {
  packet_acceleration_simd([=](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k,
                               Vec4T<SimdD>& acc) { schwarzschild_isotropic_accel(rho_s, x, k, acc); },
                           y, a, kPacketLanes);
}
void schwarzschild_isotropic_packet_jacobi_terms(double rho_s, const double* y, double* t) {
  packet_jacobi_terms_simd(
      [&](const auto& x, const auto& k, auto& a) { schwarzschild_isotropic_accel(rho_s, x, k, a); }, y, t,
      kPacketLanes);
}
void schwarzschild_isotropic_packet_constraint(double rho_s, const double* y, double target, double* value,
                                               double* scale) {
  packet_constraint_simd(
      [rho_s](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { schwarzschild_isotropic_metric_tensor(rho_s, x, g); }, y,
      target, value, scale, kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(schwarzschild_isotropic_packet_acceleration);
void SchwarzschildIsotropic::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(schwarzschild_isotropic_packet_acceleration)(rho_s_, y, a);
}
HWY_EXPORT(schwarzschild_isotropic_packet_jacobi_terms);
void SchwarzschildIsotropic::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(schwarzschild_isotropic_packet_jacobi_terms)(rho_s_, y, t);
}
HWY_EXPORT(schwarzschild_isotropic_packet_constraint);
void SchwarzschildIsotropic::packet_constraint_simd(const double* y, double target, double* value,
                                                    double* scale) const {
  HWY_DYNAMIC_DISPATCH(schwarzschild_isotropic_packet_constraint)(rho_s_, y, target, value, scale);
}
}  // namespace geovis
#endif
