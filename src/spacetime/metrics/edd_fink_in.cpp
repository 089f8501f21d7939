// Schwarzschild spacetime in ingoing Eddington-Finkelstein coordinates (v, r, θ, φ), G = c = 1:
//   ds² = −(1 − r_s/r) dv² + 2 dv dr + r² (dθ² + sin²θ dφ²),   v = t + r + r_s ln|r/r_s − 1|
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Schwarzschild spacetime /
// Eddington-Finkelstein coordinates". The chart is regular across the horizon: ingoing radial
// light rays have v = const and reach r → 0.
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// edd_fink_in_packet_acceleration below).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/edd_fink_in.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_EDD_FINK_IN_ONCE_
#define GEOVIS_METRICS_EDD_FINK_IN_ONCE_
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/edd_fink_in_accel.h"
}  // namespace scalar

class EddFinkIn final : public MetricCRTP<EddFinkIn> {
 public:
  EddFinkIn()
      : MetricCRTP({"EddFinkIn",
                    {"v", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0 of the black hole (r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static, TetradKind::Freefall},
                    "Schwarzschild black hole in ingoing Eddington-Finkelstein coordinates (Mueller & Grave, Catalogue "
                    "of Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  /// The line element in the file comment (edd_fink_in_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::edd_fink_in_metric_tensor(rs_, x, g);
  }

  /// Non-zero symbols (Catalogue of Spacetimes, Eddington-Finkelstein coordinates):
  ///   Γ^v_vv = r_s/(2r²), Γ^v_θθ = −r, Γ^v_φφ = −r sin²θ,
  ///   Γ^r_vv = r_s (r − r_s)/(2r³), Γ^r_vr = −r_s/(2r²), Γ^r_θθ = −(r − r_s), Γ^r_φφ = −(r − r_s) sin²θ,
  ///   Γ^θ_rθ = Γ^φ_rφ = 1/r, Γ^θ_φφ = −sinθ cosθ, Γ^φ_θφ = cotθ.
  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double r = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double rmrs = r - rs_;
    G.G[0][0][0] = rs_ / (2.0 * r * r);
    G.G[0][2][2] = -r;
    G.G[0][3][3] = -r * st * st;
    G.G[1][0][0] = rs_ * rmrs / (2.0 * r * r * r);
    G.G[1][0][1] = G.G[1][1][0] = -rs_ / (2.0 * r * r);
    G.G[1][2][2] = -rmrs;
    G.G[1][3][3] = -rmrs * st * st;
    G.G[2][1][2] = G.G[2][2][1] = 1.0 / r;
    G.G[2][3][3] = -st * ct;
    G.G[3][1][3] = G.G[3][3][1] = 1.0 / r;
    G.G[3][2][3] = G.G[3][3][2] = ct / st;
  }

  /// −Γ^μ_{ab} k^a k^b with the symbols above written out (edd_fink_in_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const { scalar::edd_fink_in_accel(rs_, x, k, a); }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::edd_fink_in_accel(rs_, xx, kk, a); }, x, k, Y, t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;
  /// is_valid on every lane of a packet, SIMD (bit l: lane l); the packet's validity test was
  /// lane by lane before (~38 instructions per step and lane on fallEddFinkIn, callgrind, issue 13).
  unsigned packet_is_valid_simd(const double* y) const;
  /// escapes(x, sign·k, r_min, radius) on every lane of a packet, SIMD (bit l: lane l).
  unsigned packet_escapes_simd(const double* y, double sign, double r_min, double* radius) const;

  /// The chart is regular across the horizon: valid for r > 0 (curvature singularity; small
  /// margin) and off the polar axis.
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_min_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) &&
           x[2] != 0.0;  // sin θ == 0 iff θ == 0 (double θ)
  }

  /// Break condition by direction (integrators.h, MetricSystem::valid): a backward-traced
  /// (past-directed) ray that can reach r_s only asymptotically, with k^0 → −∞, towards the
  /// white-hole horizon or the other universe that this chart does not cover (MTW §31.5, Kruskal
  /// diagram), is stopped at the break margin |r − r_s| < r_s·horizon_eps of the static metrics'
  /// horizons instead of burning the step budget. E = g_{0μ} k^μ is the conserved Killing energy
  /// of the future-directed photon −k.
  ///  * inside (r < r_s) r is a time function, so k^r > 0 means past-directed; on the future
  ///    horizon ξ = ∂_0 is null and future-directed, so light that crosses it has E ≥ 0: with
  ///    E < 0 the ray never leaves the hole backwards.
  ///  * outside, ξ is timelike and future-directed, so E > 0 means past-directed; a past-directed
  ///    ray cannot enter the hole (which lies to the future of the horizon), so with k^r < 0 near
  ///    r_s it approaches the past horizon.
  bool leaves_chart(const Vec4& x, const Vec4& k) const {
    const double r = x[1];
    if (!(std::abs(r - rs_) < rs_ * horizon_eps())) return false;
    // g_vv = −(1 − r_s/r), g_vr = 1.
    const double E = -(1.0 - rs_ / r) * k[0] + k[1];
    return r < rs_ ? (k[1] > 0.0 && E < 0.0) : (E > 0.0 && k[1] < 0.0);
  }

  /// Size of k for the integrator's constraint test (integrators.h, MetricSystem::constraint): v
  /// is a null coordinate, so there is no slicing observer; use the free-falling observer u of
  /// natural_tetrad(Freefall) below, defined for every r > 0. With w = sqrt(r_s/r),
  /// u_μ = (−1, 1/(1 + w), 0, 0), so its energy is E = −u·k = k^v − k^r/(1 + w), and
  /// h(k,k) = g(k,k) + 2E² is the Euclidean norm² of k in u's orthonormal frame.
  double constraint_norm(const Vec4& x, const Mat4& g, const Vec4& k) const {
    return scalar::edd_fink_in_constraint_norm(rs_, x, g, k);
  }

  /// Static observer (r > r_s), as Motion4D's m4dMetricEddFinkIn: with w = sqrt(1 − r_s/r),
  ///   e_(0) = ∂_v / w,  e_(1) = ∂_v / w + w ∂_r.
  /// Freefall observer falling radially from rest at infinity (any r > 0), w = sqrt(r_s/r):
  ///   e_(0) = ∂_v/(1 + w) − w ∂_r,  e_(1) = ∂_v/(1 + w) + ∂_r
  /// (u^r = −sqrt(r_s/r), u^t = 1/(1 − r_s/r) in Schwarzschild coordinates, and u^v = u^t + u^r/f).
  /// Default = static, as in Motion4D. e_(2) = ∂_θ/r, e_(3) = ∂_φ/(r sinθ) for both.
  /// Escape (escape.h): r is Schwarzschild's areal radius and k^r = dr/dλ in any chart, so the
  /// test is Schwarzschild's (photon sphere r = 1.5 r_s); r is |p|.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    return escapes_spherical(x[1], k[1], 1.5 * rs_, r_min, x[1], radius);
  }

  /// Capture (capture.h) of the rays that leaves_chart stops at the past horizon: outside the
  /// break band (r > r_s (1 + horizon_eps)), past-directed (E > 0, leaves_chart's sign) and moving
  /// inward (k^r < 0) below the photon sphere. The radial equation is Schwarzschild's: with
  /// E = g_{vμ}k^μ = −f k^v + k^r and L = r² k^φ (equatorial frame), g(k,k) = 0 gives
  /// (k^r)² = E² − f L²/r², f = 1 − r_s/r, so A B = 1 and h² = r³/(r − r_s) as in Schwarzschild:
  /// r falls monotonically into the band, where leaves_chart ends the ray with Invalid. The
  /// integration must run forward (c.direction > 0): leaves_chart reads the stored k as the
  /// direction of travel. Future-directed infalling rays (E < 0) cross the horizon to the
  /// singularity and are not captured.
  bool captures(const Vec4& x, const Vec4& k, const SolverConfig& c) const {
    const double r = x[1], r_band = rs_ * (1.0 + horizon_eps());
    if (!(c.direction > 0.0) || !(r > r_band)) return false;
    const double E = -(1.0 - rs_ / r) * k[0] + k[1];
    return E > 0.0 && captured_spherical(r, k[1], 1.5 * rs_, c.capture_radius) && capture_unobstructed(c, r_band);
  }
  /// captures on every lane of a packet, SIMD (bit l: lane l), the same comparisons and the same
  /// operations for E; the caller checks that the rays are light rays and c.capture_radius > 0.
  unsigned packet_captures_simd(const double* y, const SolverConfig& c) const;

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1];
    if (!(r > 0.0) || std::sin(x[2]) == 0.0)
      throw Error("EddFinkIn: no local tetrad at r = " + std::to_string(r) + " or on the polar axis");
    Tetrad e{};
    if (kind == TetradKind::Freefall) {
      const double w = std::sqrt(rs_ / r);
      e[0][0] = 1.0 / (1.0 + w);
      e[0][1] = -w;
      e[1][0] = 1.0 / (1.0 + w);
      e[1][1] = 1.0;
    } else {
      if (!(r > rs_))
        throw Error("EddFinkIn: no static observer at r = " + std::to_string(r) + " <= r_s = " + std::to_string(rs_) +
                    " (use localframe freefall inside the horizon)");
      const double w = std::sqrt(1.0 - rs_ / r);
      e[0][0] = 1.0 / w;
      e[1][0] = 1.0 / w;
      e[1][1] = w;
    }
    e[2][2] = 1.0 / r;
    e[3][3] = 1.0 / (r * std::sin(x[2]));
    return e;
  }

 protected:
  void on_params_changed() override {
    rs_ = 2.0 * p(0);
    r_min_ = rs_ > 0.0 ? 1e-6 * rs_ : 1e-300;
  }

 private:
  double rs_ = 2.0, r_min_ = 2e-6;
};

std::unique_ptr<Metric> make_metric_EddFinkIn() { return std::make_unique<EddFinkIn>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_EDD_FINK_IN_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/edd_fink_in_accel.h"

void edd_fink_in_packet_acceleration(double rs, const double* y, double* a) {
  packet_acceleration_simd(
      [rs](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k, Vec4T<SimdD>& acc) { edd_fink_in_accel(rs, x, k, acc); }, y,
      a, kPacketLanes);
}
void edd_fink_in_packet_jacobi_terms(double rs, const double* y, double* t) {
  packet_jacobi_terms_simd([&](const auto& x, const auto& k, auto& a) { edd_fink_in_accel(rs, x, k, a); }, y, t,
                           kPacketLanes);
}
void edd_fink_in_packet_constraint(double rs, const double* y, double target, double* value, double* scale) {
  packet_constraint_simd([rs](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { edd_fink_in_metric_tensor(rs, x, g); },
                         [rs](const Vec4T<SimdD>& x, const Mat4T<SimdD>& g, const Vec4T<SimdD>& k) {
                           return edd_fink_in_constraint_norm(rs, x, g, k);
                         },
                         y, target, value, scale, kPacketLanes);
}
/// EddFinkIn::is_valid on SIMD lanes: the same comparisons (x^2 != 0 as hn::Ne, which is false
/// for NaN where C++'s != is true, but a NaN x^2 already fails isfinite in both).
unsigned edd_fink_in_packet_is_valid(double r_min, const double* y) {
  return packet_position_mask_simd(
      [r_min](const Vec4T<SimdD>& x) {
        return x[1] > SimdD(r_min) && SimdMask{hn::IsFinite(x[0].v)} && SimdMask{hn::IsFinite(x[2].v)} &&
               SimdMask{hn::IsFinite(x[3].v)} && x[2] != SimdD(0.0);
      },
      y, kPacketLanes);
}
/// EddFinkIn::escapes (escapes_spherical(r, dr, 1.5 r_s, r_min, r, radius) with dr = sign·k^r)
/// on SIMD lanes: the same comparisons; radius = r on every lane (read only where escaped).
unsigned edd_fink_in_packet_escapes(double rs, const double* y, double sign, double r_min, double* radius) {
  constexpr size_t W = kPacketLanes;
  unsigned bits = 0;
  for (size_t l = 0; l < W; l += SimdD::lanes()) {
    const SimdD r = SimdD::load(y + 1 * W + l), dr = SimdD(sign) * SimdD::load(y + 5 * W + l);
    const SimdMask escaped = r > SimdD(1.5 * rs) && dr > SimdD(0.0) && r > SimdD(r_min);
    r.store(radius + l);
    bits |= mask_bits(escaped) << l;
  }
  return bits;
}
/// EddFinkIn::captures' conditions on the ray (all but the direction of integration and the
/// box, the same for every lane) on SIMD lanes: r > r_band, E > 0, r < 1.5 r_s, r < r_max,
/// k^r < 0 (captured_spherical), E computed by the same operations in the same order.
unsigned edd_fink_in_packet_captures(double rs, double r_band, double r_max, const double* y) {
  constexpr size_t W = kPacketLanes;
  unsigned bits = 0;
  for (size_t l = 0; l < W; l += SimdD::lanes()) {
    const SimdD r = SimdD::load(y + 1 * W + l), kv = SimdD::load(y + 4 * W + l), kr = SimdD::load(y + 5 * W + l);
    const SimdD E = -(SimdD(1.0) - SimdD(rs) / r) * kv + kr;
    const SimdMask captured = r > SimdD(r_band) && E > SimdD(0.0) && r < SimdD(1.5 * rs) && r < SimdD(r_max) &&
                              kr < SimdD(0.0);
    bits |= mask_bits(captured) << l;
  }
  return bits;
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(edd_fink_in_packet_acceleration);
void EddFinkIn::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(edd_fink_in_packet_acceleration)(rs_, y, a);
}
HWY_EXPORT(edd_fink_in_packet_jacobi_terms);
void EddFinkIn::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(edd_fink_in_packet_jacobi_terms)(rs_, y, t);
}
HWY_EXPORT(edd_fink_in_packet_is_valid);
unsigned EddFinkIn::packet_is_valid_simd(const double* y) const {
  return HWY_DYNAMIC_DISPATCH(edd_fink_in_packet_is_valid)(r_min_, y);
}
HWY_EXPORT(edd_fink_in_packet_escapes);
unsigned EddFinkIn::packet_escapes_simd(const double* y, double sign, double r_min, double* radius) const {
  return HWY_DYNAMIC_DISPATCH(edd_fink_in_packet_escapes)(rs_, y, sign, r_min, radius);
}
HWY_EXPORT(edd_fink_in_packet_captures);
unsigned EddFinkIn::packet_captures_simd(const double* y, const SolverConfig& c) const {
  const double r_band = rs_ * (1.0 + horizon_eps());
  if (!(c.direction > 0.0) || !capture_unobstructed(c, r_band)) return 0;
  return HWY_DYNAMIC_DISPATCH(edd_fink_in_packet_captures)(rs_, r_band, c.capture_radius, y);
}
HWY_EXPORT(edd_fink_in_packet_constraint);
void EddFinkIn::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(edd_fink_in_packet_constraint)(rs_, y, target, value, scale);
}
}  // namespace geovis
#endif
