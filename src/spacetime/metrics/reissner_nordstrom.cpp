// Reissner-Nordström spacetime (charged, non-rotating black hole) in Schwarzschild-like
// coordinates (t, r, θ, φ), geometrized units G = c = 1, Gaussian charge:
//   ds² = −f dt² + dr²/f + r² (dθ² + sin²θ dφ²),   f(r) = 1 − 2M/r + Q²/r²
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Reissner-Nordström".
// Horizons r± = M ± sqrt(M² − Q²) for |Q| ≤ M; for |Q| > M the singularity r = 0 is naked.
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// reissner_nordstrom_packet_acceleration below): g_μμ and −Γkk are the templates of reissner_nordstrom_accel.h.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/reissner_nordstrom.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_REISSNER_NORDSTROM_ONCE_
#define GEOVIS_METRICS_REISSNER_NORDSTROM_ONCE_
#include <algorithm>
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/static_spherical.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/reissner_nordstrom_accel.h"
}  // namespace scalar

class ReissnerNordstrom final : public MetricCRTP<ReissnerNordstrom> {
 public:
  ReissnerNordstrom()
      : MetricCRTP(
            {"ReissnerNordstrom",
             {"t", "r", "theta", "phi"},
             CoordType::Spherical,
             {{"charge", 0.1, -1e300, 1e300, false, false,
               "electric charge Q (geometrized units); |Q| <= M: black hole with horizon "
               "r+ = M + sqrt(M^2 - Q^2), |Q| > M: naked singularity at r = 0"},
              {"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0"}},
             {TetradKind::Default, TetradKind::Static},
             "charged black hole (Reissner-Nordstrom) (Mueller & Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
             Vec4{{0, 6, M_PI / 2, 0}},
             {{"charge", 0.0}, {"mass", 0.0}}}) {
    on_params_changed();
  }

  /// The line element (reissner_nordstrom_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::reissner_nordstrom_metric_tensor(M_, Q2_, x, g);
  }

  /// g_μμ and their derivatives (reissner_nordstrom_accel.h).
  void diagonal(const Vec4& x, DiagonalMetric& d) const { scalar::reissner_nordstrom_diagonal(M_, Q2_, x, d); }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  /// −Γ^μ_{ab} k^a k^b of the diagonal metric (reissner_nordstrom_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const { scalar::reissner_nordstrom_accel(M_, Q2_, x, k, a); }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::reissner_nordstrom_accel(M_, Q2_, xx, kk, a); }, x, k,
        Y, t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// Outside the outer horizon (or r > 0 for a naked singularity) and off the polar axis.
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_min_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  /// Escape (escape.h): h² = r²/f, (h²)' = 2r³(r² − 3Mr + 2Q²)/(r² f)², so h grows beyond the
  /// outer photon sphere r = (3M + √(9M² − 8Q²))/2 (for 8Q² > 9M² there is none and h grows
  /// everywhere); f > 0 there (it lies outside r+). r is |p|.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    const double disc = 9.0 * M_ * M_ - 8.0 * Q2_;
    const double r_photon = disc >= 0.0 ? 0.5 * (3.0 * M_ + std::sqrt(disc)) : 0.0;
    return escapes_spherical(x[1], k[1], r_photon, r_min, x[1], radius);
  }

  /// Capture (capture.h), only with a horizon (|Q| ≤ M): (h²)' above has the roots
  /// (3M ± √(9M² − 8Q²))/2, the smaller one at or below r+ (equal for |Q| = M), so h decreases on
  /// (r+, outer photon sphere); A B = 1. r is |p|.
  bool captures(const Vec4& x, const Vec4& k, const SolverConfig& c) const {
    if (!(r_plus_ > 0.0)) return false;
    const double r_photon = 0.5 * (3.0 * M_ + std::sqrt(9.0 * M_ * M_ - 8.0 * Q2_));
    return captured_spherical(x[1], k[1], r_photon, c.capture_radius) && capture_unobstructed(c, r_min_);
  }

  /// Effective potential, circular orbits and embedding (static_spherical.h) from r_+ (or, for a
  /// naked singularity, from r_min) outwards.
  std::vector<MetricFunction> functions() const override {
    return static_spherical_functions_of(*this, r_plus_ > 0.0 ? r_plus_ : r_min_, 20.0 * std::max(M_, 0.5));
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    diagonal(x, d);
    Tetrad e;
    if (!(x[1] > r_plus_) || !diagonal_static_tetrad(d.h, e))
      throw Error("ReissnerNordstrom: no static observer at r = " + std::to_string(x[1]) +
                  " (static observers exist only outside the horizon r+ = " + std::to_string(r_plus_) + ")");
    return e;
  }

 protected:
  void on_params_changed() override {
    const double Q = p(0);
    M_ = p(1);
    Q2_ = Q * Q;
    // Outer horizon r+ = M + sqrt(M² − Q²) (Catalogue of Spacetimes, Reissner-Nordström);
    // no horizon when |Q| > M.
    r_plus_ = Q2_ <= M_ * M_ ? M_ + std::sqrt(M_ * M_ - Q2_) : 0.0;
    r_min_ =
        r_plus_ > 0.0 ? r_plus_ * (1.0 + horizon_eps_) : 1e-8 * std::max(M_, std::sqrt(Q2_));  // Metric::horizon_eps
    if (!(r_min_ > 0.0)) r_min_ = 1e-300;  // M = Q = 0: Minkowski, only r > 0 required
  }

 private:
  double M_ = 1.0, Q2_ = 0.01, r_plus_ = 2.0, r_min_ = 2.0;
};

std::unique_ptr<Metric> make_metric_ReissnerNordstrom() { return std::make_unique<ReissnerNordstrom>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_REISSNER_NORDSTROM_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/diagonal_metric_accel.h"
#include "spacetime/metrics/reissner_nordstrom_accel.h"

void reissner_nordstrom_packet_acceleration(double M, double Q2, const double* y, double* a) {
  packet_acceleration_simd([=](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k,
                               Vec4T<SimdD>& acc) { reissner_nordstrom_accel(M, Q2, x, k, acc); },
                           y, a, kPacketLanes);
}
void reissner_nordstrom_packet_jacobi_terms(double M, double Q2, const double* y, double* t) {
  packet_jacobi_terms_simd([&](const auto& x, const auto& k, auto& a) { reissner_nordstrom_accel(M, Q2, x, k, a); }, y,
                           t, kPacketLanes);
}
void reissner_nordstrom_packet_constraint(double M, double Q2, const double* y, double target, double* value,
                                          double* scale) {
  packet_constraint_simd(
      [M, Q2](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { reissner_nordstrom_metric_tensor(M, Q2, x, g); }, y, target,
      value, scale, kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(reissner_nordstrom_packet_acceleration);
void ReissnerNordstrom::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(reissner_nordstrom_packet_acceleration)(M_, Q2_, y, a);
}
HWY_EXPORT(reissner_nordstrom_packet_jacobi_terms);
void ReissnerNordstrom::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(reissner_nordstrom_packet_jacobi_terms)(M_, Q2_, y, t);
}
HWY_EXPORT(reissner_nordstrom_packet_constraint);
void ReissnerNordstrom::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(reissner_nordstrom_packet_constraint)(M_, Q2_, y, target, value, scale);
}
}  // namespace geovis
#endif
