// Morris-Thorne (Ellis) wormhole in proper radial length l, coordinates (t, l, θ, φ):
//   ds² = −dt² + dl² + (b0² + l²)(dθ² + sin²θ dφ²)
// (Morris & Thorne, Am. J. Phys. 56 (1988) 395, eq. (55) with the shape b(r) = b0²/r; Müller &
// Grave, Catalogue of Spacetimes, arXiv:0904.4184, section "Morris-Thorne"). The throat of radius
// b0 is at l = 0; l > 0 and l < 0 are the two asymptotically flat universes.
//
// Natural tetrad (default = static, Catalogue "Morris-Thorne"): e_(0) = ∂_t, e_(1) = ∂_l,
// e_(2) = ∂_θ/r, e_(3) = ∂_φ/(r sinθ) with r = √(b0² + l²).
// Pseudo-Cartesian coordinates (Motion4D MetricMorrisThorne::transToPseudoCart): the plain
// spherical-to-Cartesian map applied to the *signed* l, i.e. (l sinθ cosφ, l sinθ sinφ, l cosθ);
// chart 0 for l > 0 and chart 1 for l <= 0 (the second universe appears point-reflected, which
// GeoViS scenes compensate in their texture transforms, e.g. morristhorne.scm).
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// morris_thorne_packet_acceleration below).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/morris_thorne.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_MORRIS_THORNE_ONCE_
#define GEOVIS_METRICS_MORRIS_THORNE_ONCE_
#include <algorithm>
#include <cmath>

#include "spacetime/metric_crtp.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/morris_thorne_accel.h"
}  // namespace scalar

class MorrisThorne final : public MetricCRTP<MorrisThorne> {
 public:
  MorrisThorne()
      : MetricCRTP({"MorrisThorne",
                    {"t", "l", "theta", "phi"},
                    CoordType::Spherical,
                    {{"b0", 1.0, 0.0, 1e300, true, false, "throat radius b0 > 0 of the wormhole"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Morris-Thorne wormhole, proper radial length l (Morris & Thorne, Am. J. Phys. 56 (1988) 395; "
                    "Mueller & Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 5, M_PI / 2, 0}},
                    {}}) {
    on_params_changed();
  }

  /// The line element in the file comment (morris_thorne_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::morris_thorne_metric_tensor(b02_, x, g);
  }

  /// Catalogue of Spacetimes, "Morris-Thorne": Γ^l_θθ = −l, Γ^l_φφ = −l sin²θ,
  /// Γ^θ_lθ = Γ^φ_lφ = l/(b0² + l²), Γ^θ_φφ = −sinθ cosθ, Γ^φ_θφ = cotθ.
  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double l = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double lr2 = l / (b02_ + l * l);
    G.G[1][2][2] = -l;
    G.G[1][3][3] = -l * st * st;
    G.G[2][1][2] = G.G[2][2][1] = lr2;
    G.G[2][3][3] = -st * ct;
    G.G[3][1][3] = G.G[3][3][1] = lr2;
    G.G[3][2][3] = G.G[3][3][2] = ct / st;
  }

  /// −Γ^μ_{ab} k^a k^b with the symbols above written out (morris_thorne_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const { scalar::morris_thorne_accel(b02_, x, k, a); }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::morris_thorne_accel(b02_, xx, kk, a); }, x, k, Y, t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;
  /// is_valid on every lane of a packet, SIMD (bit l: lane l); the packet's validity test was
  /// lane by lane before (callgrind on morristhorne, issue 13).
  unsigned packet_is_valid_simd(const double* y) const;
  /// escapes(x, sign·k, r_min, radius) on every lane of a packet, SIMD (bit l: lane l).
  unsigned packet_escapes_simd(const double* y, double sign, double r_min, double* radius) const;

  /// The spacetime is regular everywhere; only the polar axis is a coordinate singularity.
  bool is_valid(const Vec4& x) const override {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]) &&
           x[2] != 0.0;  // sin θ == 0 iff θ == 0 (double θ)
  }

  /// Escape (escape.h) into either universe: h² = b0² + l² (A = 1) grows with |l| on both sides
  /// of the throat l = 0, the only photon sphere; so the test is on |l| = |p| and d|l|/dλ.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    const double s = x[1] > 0.0 ? 1.0 : -1.0;
    return escapes_spherical(s * x[1], s * k[1], 0.0, r_min, s * x[1], radius);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double st = std::sin(x[2]);
    if (st == 0.0) throw Error("MorrisThorne: the natural tetrad is singular on the polar axis (sin(theta) = 0)");
    const double r = std::sqrt(b02_ + x[1] * x[1]);
    Tetrad e{};
    e[0][0] = 1.0;
    e[1][1] = 1.0;
    e[2][2] = 1.0 / r;
    e[3][3] = 1.0 / (r * st);
    return e;
  }

  int to_pseudo_cartesian(const Vec4& x, Vec3& p) const override {
    const double l = x[1], st = std::sin(x[2]);
    p = {l * st * std::cos(x[3]), l * st * std::sin(x[3]), l * std::cos(x[2])};
    return l > 0.0 ? 0 : 1;
  }

  /// |p| = |l| (n(θ, φ) is a unit vector), the chart as to_pseudo_cartesian's.
  bool pseudo_cartesian_radius(const Vec4& x, double& radius, int& chart) const override {
    radius = std::fabs(x[1]);
    chart = x[1] > 0.0 ? 0 : 1;
    return true;
  }

  /// pseudo_cartesian_radius of all lanes of a packet in one call on SIMD lanes (the renderer asks
  /// once per round of steps): Metric's default made a virtual call per lane, ~3 % of
  /// morristhorne.scm's profile (perf, issue 13). Entries of lanes outside `lanes` are undefined
  /// (Metric's contract), so all lanes are computed.
  void pseudo_cartesian_radii(const double* x, unsigned lanes, double* radius, int* chart) const override;

  /// Inverse of to_pseudo_cartesian: chart 0 gives l = +|p|, chart 1 gives l = −|p| with the
  /// angles of −p (so that l·n(θ,φ) = p again).
  Vec4 from_pseudo_cartesian(double t, const Vec3& p, int chart) const override {
    const double s = chart == 0 ? 1.0 : -1.0;
    const double d = norm(p);
    const double th = d > 0 ? std::acos(std::clamp(s * p.z / d, -1.0, 1.0)) : 0.0;
    return {{t, s * d, th, std::atan2(s * p.y, s * p.x)}};
  }

 protected:
  void on_params_changed() override { b02_ = p(0) * p(0); }

 private:
  double b02_ = 1.0;
};

std::unique_ptr<Metric> make_metric_MorrisThorne() { return std::make_unique<MorrisThorne>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_MORRIS_THORNE_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/morris_thorne_accel.h"

void morris_thorne_packet_acceleration(double b02, const double* y, double* a) {
  packet_acceleration_simd(
      [b02](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k, Vec4T<SimdD>& acc) { morris_thorne_accel(b02, x, k, acc); },
      y, a, kPacketLanes);
}
void morris_thorne_packet_jacobi_terms(double b02, const double* y, double* t) {
  packet_jacobi_terms_simd([&](const auto& x, const auto& k, auto& a) { morris_thorne_accel(b02, x, k, a); }, y, t,
                           kPacketLanes);
}
void morris_thorne_packet_constraint(double b02, const double* y, double target, double* value, double* scale) {
  packet_diagonal_constraint_simd(
      [b02](const Vec4T<SimdD>& x, SimdD(&g)[4]) { morris_thorne_metric_diagonal(b02, x, g); }, y, target, value, scale,
      kPacketLanes);
}
/// MorrisThorne::is_valid on SIMD lanes: the same tests (x^2 != 0 as hn::Ne, which is false for
/// NaN where C++'s != is true, but a NaN x^2 already fails isfinite in both).
unsigned morris_thorne_packet_is_valid(const double* y) {
  return packet_position_mask_simd(
      [](const Vec4T<SimdD>& x) {
        return SimdMask{hn::IsFinite(x[0].v)} && SimdMask{hn::IsFinite(x[1].v)} && SimdMask{hn::IsFinite(x[2].v)} &&
               SimdMask{hn::IsFinite(x[3].v)} && x[2] != SimdD(0.0);
      },
      y, kPacketLanes);
}
/// MorrisThorne::escapes on SIMD lanes: with s = ±1 the side of the throat (x^1 > 0 ? 1 : −1),
/// escapes_spherical(s·l, s·dl, 0, r_min, s·l, radius) with dl = sign·k^l: the same comparisons
/// (the products by ±1 are exact in any order); radius = s·l on every lane (read only where
/// escaped).
unsigned morris_thorne_packet_escapes(const double* y, double sign, double r_min, double* radius) {
  constexpr size_t W = kPacketLanes;
  unsigned bits = 0;
  for (size_t l = 0; l < W; l += SimdD::lanes()) {
    const SimdD x1 = SimdD::load(y + 1 * W + l);
    const SimdD s = select(x1 > SimdD(0.0), SimdD(1.0), SimdD(-1.0));
    const SimdD r = s * x1, dr = s * (SimdD(sign) * SimdD::load(y + 5 * W + l));
    const SimdMask escaped = r > SimdD(0.0) && dr > SimdD(0.0) && r > SimdD(r_min);
    r.store(radius + l);
    bits |= mask_bits(escaped) << l;
  }
  return bits;
}
/// MorrisThorne::pseudo_cartesian_radius on SIMD lanes: radius |l| (bit l of the result: l > 0,
/// chart 0).
unsigned morris_thorne_packet_radii(const double* y, double* radius) {
  constexpr size_t W = kPacketLanes;
  unsigned bits = 0;
  for (size_t l = 0; l < W; l += SimdD::lanes()) {
    const SimdD x1 = SimdD::load(y + 1 * W + l);
    abs(x1).store(radius + l);
    bits |= mask_bits(x1 > SimdD(0.0)) << l;
  }
  return bits;
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(morris_thorne_packet_acceleration);
void MorrisThorne::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(morris_thorne_packet_acceleration)(b02_, y, a);
}
HWY_EXPORT(morris_thorne_packet_jacobi_terms);
void MorrisThorne::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(morris_thorne_packet_jacobi_terms)(b02_, y, t);
}
HWY_EXPORT(morris_thorne_packet_is_valid);
unsigned MorrisThorne::packet_is_valid_simd(const double* y) const {
  return HWY_DYNAMIC_DISPATCH(morris_thorne_packet_is_valid)(y);
}
HWY_EXPORT(morris_thorne_packet_escapes);
unsigned MorrisThorne::packet_escapes_simd(const double* y, double sign, double r_min, double* radius) const {
  return HWY_DYNAMIC_DISPATCH(morris_thorne_packet_escapes)(y, sign, r_min, radius);
}
HWY_EXPORT(morris_thorne_packet_radii);
void MorrisThorne::pseudo_cartesian_radii(const double* x, unsigned /*lanes*/, double* radius, int* chart) const {
  const unsigned positive = HWY_DYNAMIC_DISPATCH(morris_thorne_packet_radii)(x, radius);
  for (int l = 0; l < kPacketLanes; ++l) chart[l] = positive >> l & 1u ? 0 : 1;
}
HWY_EXPORT(morris_thorne_packet_constraint);
void MorrisThorne::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(morris_thorne_packet_constraint)(b02_, y, target, value, scale);
}
}  // namespace geovis
#endif
