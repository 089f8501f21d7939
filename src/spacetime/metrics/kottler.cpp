// Kottler (Schwarzschild-de Sitter / -anti-de Sitter) spacetime in (t, r, θ, φ), G = c = 1:
//   ds² = −f dt² + dr²/f + r² (dθ² + sin²θ dφ²),   f(r) = 1 − 2M/r − Λ r²/3
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Kottler".
// The static region is where f > 0: r ∈ (r_bh, r_cosmo) for Λ > 0 (requires 9ΛM² < 1),
// r > r_bh for Λ ≤ 0. Rays stop at both horizons (the t-coordinate is singular there).
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// kottler_packet_acceleration below): g_μμ and −Γkk are the templates of kottler_accel.h.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/kottler.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_KOTTLER_ONCE_
#define GEOVIS_METRICS_KOTTLER_ONCE_
#include <cmath>
#include <sstream>
#include <string>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/kottler_accel.h"
}  // namespace scalar

class Kottler final : public MetricCRTP<Kottler> {
 public:
  Kottler()
      : MetricCRTP(
            {"Kottler",
             {"t", "r", "theta", "phi"},
             CoordType::Spherical,
             {{"lambda", 0.05, -1e300, 1e300, false, false,
               "cosmological constant Lambda (any sign; for Lambda > 0 a static region needs "
               "9 Lambda M^2 < 1)"},
              {"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0"}},
             {TetradKind::Default, TetradKind::Static},
             "Schwarzschild-(anti-)de Sitter (Kottler) (Mueller & Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
             Vec4{{0, 4, M_PI / 2, 0}},
             {{"lambda", 0.0}, {"mass", 0.0}}}) {
    on_params_changed();
  }

  /// The line element (kottler_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::kottler_metric_tensor(M_, L_, x, g);
  }

  double f_of(double r) const { return 1.0 - 2.0 * M_ / r - (L_ / 3.0) * r * r; }

  /// g_μμ and their derivatives (kottler_accel.h).
  void diagonal(const Vec4& x, DiagonalMetric& d) const { scalar::kottler_diagonal(M_, L_, x, d); }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  /// −Γ^μ_{ab} k^a k^b of the diagonal metric (kottler_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const { scalar::kottler_accel(M_, L_, x, k, a); }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::kottler_accel(M_, L_, xx, kk, a); }, x, k, Y, t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// Inside the static region f > 0 (between the horizons), r > 0, off the polar axis. The
  /// margin 1e-8 on f corresponds to Schwarzschild's r > r_s (1 + 1e-8).
  bool is_valid(const Vec4& x) const override {
    // Both horizons (f = 0) with the break margin f > Metric::horizon_eps.
    return x[1] > 0.0 && f_of(x[1]) > horizon_eps_ && std::isfinite(x[0]) && std::isfinite(x[2]) &&
           std::isfinite(x[3]) && x[2] != 0.0;
  }

  /// Escape (escape.h) only for Λ = 0 (Schwarzschild): for Λ ≠ 0 the spacetime is not
  /// asymptotically flat (de Sitter / anti-de Sitter at large r), and with Λ < 0 light rays
  /// return from r = ∞ in finite coordinate time.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    return L_ == 0.0 && escapes_spherical(x[1], k[1], 3.0 * M_, r_min, x[1], radius);
  }
  bool asymptotically_flat() const override { return L_ == 0.0; }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (x[1] > 0.0) diagonal(x, d);
    if (!(x[1] > 0.0) || !diagonal_static_tetrad(d.h, e))
      throw Error("Kottler: no static observer at r = " + std::to_string(x[1]) +
                  " (static observers exist only where 1 - 2M/r - Lambda r^2/3 > 0)");
    return e;
  }

 protected:
  void on_params_changed() override {
    L_ = p(0);
    M_ = p(1);
    // For Λ > 0, f has positive values (a static region) only if 9ΛM² < 1 (Catalogue of
    // Spacetimes, Kottler: the horizons are the real roots of r − 2M − Λr³/3 = 0).
    if (L_ > 0.0 && 9.0 * L_ * M_ * M_ >= 1.0) {
      std::ostringstream os;
      os << "metric Kottler: parameters mass = " << M_ << ", lambda = " << L_
         << " leave no static region; expected 9 * lambda * mass^2 < 1 (here " << 9.0 * L_ * M_ * M_ << ")";
      throw Error(os.str());
    }
  }

 private:
  double M_ = 1.0, L_ = 0.05;
};

std::unique_ptr<Metric> make_metric_Kottler() { return std::make_unique<Kottler>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_KOTTLER_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/diagonal_metric_accel.h"
#include "spacetime/metrics/kottler_accel.h"

void kottler_packet_acceleration(double M, double L, const double* y, double* a) {
  packet_acceleration_simd(
      [=](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k, Vec4T<SimdD>& acc) { kottler_accel(M, L, x, k, acc); }, y, a,
      kPacketLanes);
}
void kottler_packet_jacobi_terms(double M, double L, const double* y, double* t) {
  packet_jacobi_terms_simd([&](const auto& x, const auto& k, auto& a) { kottler_accel(M, L, x, k, a); }, y, t,
                           kPacketLanes);
}
void kottler_packet_constraint(double M, double L, const double* y, double target, double* value, double* scale) {
  packet_constraint_simd([M, L](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { kottler_metric_tensor(M, L, x, g); }, y,
                         target, value, scale, kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(kottler_packet_acceleration);
void Kottler::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(kottler_packet_acceleration)(M_, L_, y, a);
}
HWY_EXPORT(kottler_packet_jacobi_terms);
void Kottler::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(kottler_packet_jacobi_terms)(M_, L_, y, t);
}
HWY_EXPORT(kottler_packet_constraint);
void Kottler::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(kottler_packet_constraint)(M_, L_, y, target, value, scale);
}
}  // namespace geovis
#endif
