// Ernst spacetime (Schwarzschild black hole immersed in a Melvin magnetic universe) in
// (t, r, θ, φ), G = c = 1:
//   ds² = Λ² [−f dt² + dr²/f + r² dθ²] + r² sin²θ / Λ² dφ²,   f = 1 − 2M/r,  Λ = 1 + B² r² sin²θ
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Ernst spacetime";
// F. J. Ernst, J. Math. Phys. 17 (1976) 54. B is the magnetic field strength; only B² enters.
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// ernst_packet_acceleration below): g_μμ and −Γkk are the templates of ernst_accel.h.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/ernst.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_ERNST_ONCE_
#define GEOVIS_METRICS_ERNST_ONCE_
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/ernst_accel.h"
}  // namespace scalar

class Ernst final : public MetricCRTP<Ernst> {
 public:
  Ernst()
      : MetricCRTP({"Ernst",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"b", 0.1, -1e300, 1e300, false, false,
                      "magnetic field strength B (any real; only B^2 enters the metric)"},
                     {"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0 of the black hole (r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "black hole in a Melvin magnetic universe (Ernst, J. Math. Phys. 17 (1976) 54; Mueller & Grave, "
                    "Catalogue of Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"b", 0.0}, {"mass", 0.0}}}) {
    on_params_changed();
  }

  /// The line element (ernst_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::ernst_metric_tensor(B2_, rs_, x, g);
  }

  /// g_μμ and their derivatives (ernst_accel.h).
  void diagonal(const Vec4& x, DiagonalMetric& d) const { scalar::ernst_diagonal(B2_, rs_, x, d); }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  /// −Γ^μ_{ab} k^a k^b of the diagonal metric (ernst_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const { scalar::ernst_accel(B2_, rs_, x, k, a); }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::ernst_accel(B2_, rs_, xx, kk, a); }, x, k, Y, t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// Outside the horizon r = 2M and off the polar axis.
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_min_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (x[1] > rs_ && x[1] > 0.0) diagonal(x, d);
    if (!(x[1] > rs_ && x[1] > 0.0) || !diagonal_static_tetrad(d.h, e))
      throw Error("Ernst: no static observer at r = " + std::to_string(x[1]) +
                  " (needs r > 2M = " + std::to_string(rs_) + " and sin(theta) != 0)");
    return e;
  }

 protected:
  void on_params_changed() override {
    B2_ = p(0) * p(0);
    rs_ = 2.0 * p(1);
    r_min_ = rs_ > 0.0 ? rs_ * (1.0 + horizon_eps_) : 1e-300;  // Metric::horizon_eps
  }

 private:
  double B2_ = 0.01, rs_ = 2.0, r_min_ = 2.0;
};

std::unique_ptr<Metric> make_metric_Ernst() { return std::make_unique<Ernst>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_ERNST_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/diagonal_metric_accel.h"
#include "spacetime/metrics/ernst_accel.h"

void ernst_packet_acceleration(double B2, double rs, const double* y, double* a) {
  packet_acceleration_simd(
      [=](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k, Vec4T<SimdD>& acc) { ernst_accel(B2, rs, x, k, acc); }, y, a,
      kPacketLanes);
}
void ernst_packet_jacobi_terms(double B2, double rs, const double* y, double* t) {
  packet_jacobi_terms_simd([&](const auto& x, const auto& k, auto& a) { ernst_accel(B2, rs, x, k, a); }, y, t,
                           kPacketLanes);
}
void ernst_packet_constraint(double B2, double rs, const double* y, double target, double* value, double* scale) {
  packet_constraint_simd([B2, rs](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { ernst_metric_tensor(B2, rs, x, g); }, y,
                         target, value, scale, kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(ernst_packet_acceleration);
void Ernst::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(ernst_packet_acceleration)(B2_, rs_, y, a);
}
HWY_EXPORT(ernst_packet_jacobi_terms);
void Ernst::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(ernst_packet_jacobi_terms)(B2_, rs_, y, t);
}
HWY_EXPORT(ernst_packet_constraint);
void Ernst::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(ernst_packet_constraint)(B2_, rs_, y, target, value, scale);
}
}  // namespace geovis
#endif
