// Barriola-Vilenkin spacetime (global monopole) in (t, r, θ, φ):
//   ds² = −dt² + dr² + k² r² (dθ² + sin²θ dφ²)
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Barriola-Vilenkin monopole";
// M. Barriola, A. Vilenkin, Phys. Rev. Lett. 63 (1989) 341, with k² = 1 − 8πGη².
// Space is a cone: on the equator dr² + k² r² dφ² is flat in the angle ψ = kφ.
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// barriola_vilenkin_packet_acceleration below): g_μμ and −Γkk are the templates of barriola_vilenkin_accel.h.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/barriola_vilenkin.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_BARRIOLA_VILENKIN_ONCE_
#define GEOVIS_METRICS_BARRIOLA_VILENKIN_ONCE_
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/static_spherical.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/barriola_vilenkin_accel.h"
}  // namespace scalar

class BarriolaVilenkin final : public MetricCRTP<BarriolaVilenkin> {
 public:
  BarriolaVilenkin()
      : MetricCRTP({"BarriolaVilenkin",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"k", 0.8, 0.0, 1.0, true, false,
                      "solid-angle factor k in (0, 1] (k^2 = 1 - 8 pi G eta^2; k = 1 is flat space)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "global monopole (Barriola & Vilenkin, PRL 63 (1989) 341; Mueller & Grave, Catalogue of "
                    "Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"k", 1.0}}}) {
    on_params_changed();
  }

  /// The line element (barriola_vilenkin_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::barriola_vilenkin_metric_tensor(k2_, x, g);
  }

  /// g_μμ and their derivatives (barriola_vilenkin_accel.h).
  void diagonal(const Vec4& x, DiagonalMetric& d) const { scalar::barriola_vilenkin_diagonal(k2_, x, d); }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  /// −Γ^μ_{ab} k^a k^b of the diagonal metric (barriola_vilenkin_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const { scalar::barriola_vilenkin_accel(k2_, x, k, a); }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::barriola_vilenkin_accel(k2_, xx, kk, a); }, x, k, Y,
        t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// r > 0 (the conical singularity at the origin) and off the polar axis.
  bool is_valid(const Vec4& x) const override {
    return x[1] > 1e-12 && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) &&
           x[2] != 0.0;  // sin θ == 0 iff θ == 0 (double θ)
  }

  /// Effective potential, circular orbits and the embedding cone z = √(1 − k²) r (static_spherical.h).
  std::vector<MetricFunction> functions() const override { return static_spherical_functions_of(*this, 0.0, 20.0); }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (x[1] > 0.0) diagonal(x, d);
    if (!(x[1] > 0.0) || !diagonal_static_tetrad(d.h, e))
      throw Error("BarriolaVilenkin: no local tetrad at r = " + std::to_string(x[1]) +
                  " or on the polar axis (the chart needs r > 0, sin(theta) != 0)");
    return e;
  }

 protected:
  void on_params_changed() override { k2_ = p(0) * p(0); }

 private:
  double k2_ = 0.64;
};

std::unique_ptr<Metric> make_metric_BarriolaVilenkin() { return std::make_unique<BarriolaVilenkin>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_BARRIOLA_VILENKIN_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/diagonal_metric_accel.h"
#include "spacetime/metrics/barriola_vilenkin_accel.h"

void barriola_vilenkin_packet_acceleration(double k2, const double* y, double* a) {
  packet_acceleration_simd(
      [=](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k, Vec4T<SimdD>& acc) { barriola_vilenkin_accel(k2, x, k, acc); },
      y, a, kPacketLanes);
}
void barriola_vilenkin_packet_jacobi_terms(double k2, const double* y, double* t) {
  packet_jacobi_terms_simd([&](const auto& x, const auto& k, auto& a) { barriola_vilenkin_accel(k2, x, k, a); }, y, t,
                           kPacketLanes);
}
void barriola_vilenkin_packet_constraint(double k2, const double* y, double target, double* value, double* scale) {
  packet_constraint_simd([k2](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { barriola_vilenkin_metric_tensor(k2, x, g); }, y,
                         target, value, scale, kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(barriola_vilenkin_packet_acceleration);
void BarriolaVilenkin::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(barriola_vilenkin_packet_acceleration)(k2_, y, a);
}
HWY_EXPORT(barriola_vilenkin_packet_jacobi_terms);
void BarriolaVilenkin::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(barriola_vilenkin_packet_jacobi_terms)(k2_, y, t);
}
HWY_EXPORT(barriola_vilenkin_packet_constraint);
void BarriolaVilenkin::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(barriola_vilenkin_packet_constraint)(k2_, y, target, value, scale);
}
}  // namespace geovis
#endif
