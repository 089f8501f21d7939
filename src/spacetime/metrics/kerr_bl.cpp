// Kerr black hole in Boyer-Lindquist coordinates (t, r, θ, φ), G = c = 1, r_s = 2M:
//   ds² = −(1 − r_s r/Σ) dt² − (2 r_s a r sin²θ/Σ) dt dφ + (Σ/Δ) dr² + Σ dθ² + (A/Σ) sin²θ dφ²,
//   Σ = r² + a² cos²θ,  Δ = r² − r_s r + a²,  A = (r² + a²) Σ + r_s a² r sin²θ
//   (Boyer & Lindquist, J. Math. Phys. 8 (1967) 265; Müller & Grave, Catalogue of Spacetimes,
//   arXiv:0904.4184, section "Kerr"). A·sin²θ/Σ is the usual g_φφ = (r² + a² + r_s a² r sin²θ/Σ) sin²θ.
//
// Natural tetrads (Motion4D m4dMetricKerrBL::localToCoord; Catalogue "Kerr", local tetrads):
//   default = lnrf: locally non-rotating frame (Bardeen, Press & Teukolsky, ApJ 178 (1972) 347),
//     e_(0) = √(A/(ΣΔ)) (∂_t + ω ∂_φ), ω = r_s a r / A,  e_(1) = √(Δ/Σ) ∂_r,  e_(2) = ∂_θ/√Σ,
//     e_(3) = √(Σ/A) ∂_φ / sinθ.
//   static: e_(0) = ∂_t/w, w = √(1 − r_s r/Σ) (only outside the ergosphere),
//     e_(3) = r_s a r sinθ/(w √Δ Σ) ∂_t − w/(√Δ sinθ) ∂_φ. NOTE: Motion4D's static e_(3) points
//     along −∂_φ (its e33 = −w/(√Δ sinθ)); we keep that convention so that GeoViS scenes with
//     `localframe 1` see the same picture.
// Pseudo-Cartesian coordinates: plain spherical-to-Cartesian of (r, θ, φ) (Motion4D's KerrBL does
// not override transToPseudoCart), i.e. the default for CoordType::Spherical.
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// kerr_bl_packet_acceleration below).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/kerr_bl.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_KERR_BL_ONCE_
#define GEOVIS_METRICS_KERR_BL_ONCE_
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/kerr_bl_accel.h"
}  // namespace scalar

namespace {

/// The twenty independent non-zero Christoffel symbols of Kerr in BL coordinates, named
/// <upper>_<lower><lower> (e.g. r_tt = Γ^r_{tt}). Formulas: Catalogue of Spacetimes, "Kerr"
/// (the same expressions as Motion4D's hand-written MetricKerrBL::calcDerivs). T is double, or a
/// dual number when the Jacobi equation needs the symbols' derivatives (spacetime/jacobi.h).
template <class T>
struct KerrGamma {
  T t_tr, t_tth, t_rph, t_thph;                      // Γ^t
  T r_tt, r_tph, r_rr, r_rth, r_thth, r_phph;        // Γ^r
  T th_tt, th_tph, th_rr, th_rth, th_thth, th_phph;  // Γ^θ
  T ph_tr, ph_tth, ph_rph, ph_thph;                  // Γ^φ
};

template <class T>
inline KerrGamma<T> kerr_gamma(double rs, double a, const T& r, const T& theta) {
  T st, ct;
  sincos_t(theta, st, ct);
  const T st2 = st * st, ct2 = ct * ct, stct = st * ct;
  const T r2 = r * r;
  const double a2 = a * a;
  const T sigma = r2 + a2 * ct2;     // Σ
  const T delta = r2 - rs * r + a2;  // Δ
  const T r2a2 = r2 + a2;
  const T A = r2a2 * sigma + rs * r * a2 * st2;
  const T w = r2 - a2 * ct2;  // r² − a² cos²θ, a recurring factor
  const T is = 1.0 / sigma, is2 = is * is, is3 = is2 * is;
  const T id = 1.0 / delta;
  const T cot = ct / st;
  KerrGamma<T> g;
  g.r_tt = 0.5 * rs * delta * w * is3;
  g.t_tr = 0.5 * rs * r2a2 * w * is2 * id;
  g.t_tth = -rs * r * a2 * stct * is2;
  g.r_tph = -0.5 * delta * rs * a * st2 * w * is3;
  g.r_rr = 0.5 * (2.0 * r * a2 * st2 - rs * w) * is * id;
  g.r_rth = -a2 * stct * is;
  g.t_rph = 0.5 * rs * a * st2 * (a2 * ct2 * (a2 - r2) - r2 * (a2 + 3.0 * r2)) * is2 * id;
  g.ph_rph = 0.5 * (2.0 * r * sigma * sigma + rs * (a2 * a2 * st2 * ct2 - r2 * (sigma + r2a2))) * is2 * id;
  g.ph_thph = cot * (1.0 + rs * a2 * r * st2 * is2);
  g.r_phph = 0.5 * delta * st2 * (-2.0 * r * sigma * sigma + rs * a2 * st2 * w) * is3;
  g.th_phph = -stct * (A * sigma + r2a2 * rs * a2 * r * st2) * is3;
  g.th_tt = -rs * r * a2 * stct * is3;
  g.ph_tr = 0.5 * rs * a * w * is2 * id;
  g.ph_tth = -rs * r * a * cot * is2;
  g.th_tph = rs * r * a * r2a2 * stct * is3;
  g.th_rr = a2 * stct * is * id;
  g.th_rth = r * is;
  g.r_thth = -r * delta * is;
  g.th_thth = -a2 * stct * is;
  g.t_thph = rs * r * a2 * a * st2 * stct * is2;
  return g;
}

}  // namespace

class KerrBL final : public MetricCRTP<KerrBL> {
 public:
  KerrBL()
      : MetricCRTP({"KerrBL",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"angmom", 0.5, -1e300, 1e300, false, false,
                      "specific angular momentum a = J/M of the black hole, |a| <= mass"},
                     {"mass", 1.0, 0.0, 1e300, false, false, "mass M of the black hole (r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static, TetradKind::LNRF},
                    "Kerr black hole in Boyer-Lindquist coordinates (Mueller & Grave, Catalogue of Spacetimes, "
                    "arXiv:0904.4184)",
                    Vec4{{0, 10, M_PI / 2, 0}},
                    {{"angmom", 0.0}, {"mass", 0.0}}}) {
    on_params_changed();
  }

  /// The line element (kerr_bl_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::kerr_bl_metric_tensor(rs_, a_, a2_, x, g);
  }

  /// Γ^μ_{ab} in closed form, on doubles or on dual numbers (MetricCRTP::christoffel_inline,
  /// jacobi.h).
  template <class T>
  void christoffel_tmpl(const Vec4T<T>& x, ChristoffelT<T>& G) const {
    for (auto& g1 : G.G)
      for (auto& g2 : g1)
        for (T& v : g2) v = T(0.0);
    const KerrGamma<T> k = kerr_gamma(rs_, a_, x[1], x[2]);
    auto set = [&G](int mu, int a, int b, const T& v) { G.G[mu][a][b] = G.G[mu][b][a] = v; };
    set(0, 0, 1, k.t_tr);
    set(0, 0, 2, k.t_tth);
    set(0, 1, 3, k.t_rph);
    set(0, 2, 3, k.t_thph);
    set(1, 0, 0, k.r_tt);
    set(1, 0, 3, k.r_tph);
    set(1, 1, 1, k.r_rr);
    set(1, 1, 2, k.r_rth);
    set(1, 2, 2, k.r_thth);
    set(1, 3, 3, k.r_phph);
    set(2, 0, 0, k.th_tt);
    set(2, 0, 3, k.th_tph);
    set(2, 1, 1, k.th_rr);
    set(2, 1, 2, k.th_rth);
    set(2, 2, 2, k.th_thth);
    set(2, 3, 3, k.th_phph);
    set(3, 0, 1, k.ph_tr);
    set(3, 0, 2, k.ph_tth);
    set(3, 1, 3, k.ph_rph);
    set(3, 2, 3, k.ph_thph);
  }

  /// The Jacobi system's terms (JacobiTerms, metric_kernel.h): Gk[μ][b] = Γ^μ_{bc} k^c from the
  /// twenty symbols, contracted with k symbol by symbol instead of over all 64 entries, and
  /// dGkk[f][μ] = Y_f^ν ∂_ν Γ^μ_{ab} k^a k^b = −Y_f^ν ∂_ν a^μ from the covariant form of the
  /// acceleration a = −Γ(k, k) (accel_tmpl: ten metric derivatives instead of twenty symbols) on
  /// duals seeded along the two fields (only their r and θ components enter: g depends on r, θ).
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    const KerrGamma<double> g = kerr_gamma(rs_, a_, x[1], x[2]);
    const double kt = k[0], kr = k[1], kh = k[2], kp = k[3];
    // Γ^t and Γ^φ have the same non-zero pattern (tr, tθ, rφ, θφ), as have Γ^r and Γ^θ
    // (tt, tφ, rr, rθ, θθ, φφ).
    auto odd = [&](double* Gk, double tr, double tth, double rph, double thph) {
      Gk[0] = tr * kr + tth * kh;
      Gk[1] = tr * kt + rph * kp;
      Gk[2] = tth * kt + thph * kp;
      Gk[3] = rph * kr + thph * kh;
    };
    auto even = [&](double* Gk, double tt, double tph, double rr, double rth, double thth, double phph) {
      Gk[0] = tt * kt + tph * kp;
      Gk[1] = rr * kr + rth * kh;
      Gk[2] = rth * kr + thth * kh;
      Gk[3] = tph * kt + phph * kp;
    };
    odd(t.Gk[0], g.t_tr, g.t_tth, g.t_rph, g.t_thph);
    even(t.Gk[1], g.r_tt, g.r_tph, g.r_rr, g.r_rth, g.r_thth, g.r_phph);
    even(t.Gk[2], g.th_tt, g.th_tph, g.th_rr, g.th_rth, g.th_thth, g.th_phph);
    odd(t.Gk[3], g.ph_tr, g.ph_tth, g.ph_rph, g.ph_thph);
    using D = Dual<double, 2>;
    D r(x[1]), th(x[2]);
    for (int f = 0; f < 2; ++f) {
      r.d[f] = Y[f][1];
      th.d[f] = Y[f][2];
    }
    D acc[4];
    accel_tmpl(r, th, k, acc);
    for (int f = 0; f < 2; ++f)
      for (int mu = 0; mu < 4; ++mu) t.dGkk[f][mu] = -acc[mu].d[f];
  }

  /// a^μ = −Γ^μ_{ab} k^a k^b (hot path of every Kerr ray), evaluated in the covariant form
  ///   a^μ = g^{μν} F_ν,  F_ν = ½ ∂_ν g_ab k^a k^b − k^c ∂_c g_νb k^b,
  /// which is −Γ^μ_{ab} k^a k^b with Γ = ½ g^{μν}(∂_a g_νb + ∂_b g_νa − ∂_ν g_ab) contracted. g
  /// depends on r and θ only, so only ∂_r g and ∂_θ g of the five non-zero components enter (ten
  /// numbers instead of twenty Christoffel symbols), and g^{μν} is block-diagonal with the
  /// (t, φ) block det = g_tt g_φφ − g_tφ² = −Δ sin²θ. Two divisions: 1/Σ and 1/(Δ sin²θ).
  /// With u = r_s r/Σ:  g_tt = u − 1,  g_tφ = −a sin²θ u,  g_rr = Σ/Δ,  g_θθ = Σ,
  /// g_φφ = (r² + a² + a² sin²θ u) sin²θ;  ∂_r u = r_s (a² cos²θ − r²)/Σ²,
  /// ∂_θ u = 2 r_s r a² sinθ cosθ/Σ².
  GEOVIS_HOT_INLINE void accel_closed(const Vec4& x, const Vec4& k, Vec4& acc) const {
    scalar::kerr_bl_accel(rs_, a_, a2_, x[1], x[2], k[0], k[1], k[2], k[3], acc);
  }
  /// The same with dual numbers (or any number type) for r and θ: the derivatives of the
  /// acceleration along the Jacobi fields (jacobi_terms_closed).
  template <class T>
  GEOVIS_HOT_INLINE void accel_tmpl(const T& r, const T& theta, const Vec4& k, T (&acc)[4]) const {
    scalar::kerr_bl_accel(rs_, a_, a2_, r, theta, k[0], k[1], k[2], k[3], acc);
  }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// Outside the outer horizon r_+ = M + √(M² − a²) with the break margin r_+ (1 + horizon_eps)
  /// (Metric::horizon_eps) and off the polar axis, where BL coordinates are singular (sin θ == 0
  /// exactly iff θ == 0 for a finite double θ).
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_break_ && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) &&
           std::isfinite(x[3]) && x[2] != 0.0;
  }

  /// Geodesics through Carter's separated equations (MetricCRTP::integrate, kerr_mino.h).
  KerrMinoParams kerr_mino_params() const { return {mass_, a_, r_break_}; }

  /// Escape (escape.h) in the coordinate form: the test on the radial potential of the ray's
  /// constants (KerrMinoConstants::no_radial_turning_point_beyond); r is |p|.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    if (!(x[1] > r_min && k[1] > 0.0)) return false;
    if (!kerr_mino_constants(mass_, a_, x, k, 0.0).no_radial_turning_point_beyond(x[1])) return false;
    radius = x[1];
    return true;
  }

  /// Capture (capture.h) in the coordinate form: inward, with the radial potential of the ray's
  /// constants positive down to the break radius (KerrMinoConstants::radial_potential_positive_on).
  bool captures(const Vec4& x, const Vec4& k, const SolverConfig& c) const {
    if (!(x[1] < c.capture_radius && k[1] < 0.0) || !capture_unobstructed(c, r_break_)) return false;
    return kerr_mino_constants(mass_, a_, x, k, 0.0).radial_potential_positive_on(r_break_, x[1]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double sigma = r * r + a2_ * ct * ct;
    const double delta = r * r - rs_ * r + a2_;
    if (!(r > r_plus_) || !(delta > 0.0)) {
      std::ostringstream os;
      os << "KerrBL: no " << tetrad_kind_name(kind) << " observer at r = " << r
         << " (inside the outer horizon r+ = " << r_plus_ << ")";
      throw Error(os.str());
    }
    if (st == 0.0) throw Error("KerrBL: natural tetrads are singular on the polar axis (sin(theta) = 0)");
    Tetrad e{};
    e[1][1] = std::sqrt(delta / sigma);
    e[2][2] = 1.0 / std::sqrt(sigma);
    if (kind == TetradKind::Static) {
      const double w2 = 1.0 - rs_ * r / sigma;  // −g_tt
      if (!(w2 > 0.0)) {
        std::ostringstream os;
        os << "KerrBL: no static observer at r = " << r << ", theta = " << x[2]
           << ": inside the ergosphere (r_ergo = " << mass_ + std::sqrt(mass_ * mass_ - a2_ * ct * ct)
           << "); use the lnrf (default) frame";
        throw Error(os.str());
      }
      const double w = std::sqrt(w2), sd = std::sqrt(delta);
      e[0][0] = 1.0 / w;
      e[3][0] = rs_ * a_ * r * st / (w * sd * sigma);
      e[3][3] = -w / (sd * st);  // Motion4D convention: e_(3) along −∂_φ (see file comment)
      return e;
    }
    // Default and LNRF.
    const double A = (r * r + a2_) * sigma + rs_ * a2_ * r * st * st;
    const double omega = rs_ * a_ * r / A;
    const double gamma = std::sqrt(A / (sigma * delta));
    e[0][0] = gamma;
    e[0][3] = gamma * omega;
    e[3][3] = std::sqrt(sigma / A) / st;
    return e;
  }

 protected:
  void on_params_changed() override {
    a_ = p(0);
    mass_ = p(1);
    if (std::fabs(a_) > mass_) {
      std::ostringstream os;
      os << "metric KerrBL: |angmom| = " << std::fabs(a_) << " must not exceed mass = " << mass_
         << " (|a| <= M, otherwise there is no horizon: naked singularity)";
      throw Error(os.str());
    }
    rs_ = 2.0 * mass_;
    a2_ = a_ * a_;
    r_plus_ = mass_ + std::sqrt(mass_ * mass_ - a2_);
    r_break_ = (1.0 + horizon_eps_) * r_plus_;
  }

 private:
  double a_ = 0.5, mass_ = 1.0, rs_ = 2.0, a2_ = 0.25, r_plus_ = 0, r_break_ = 0;
};

std::unique_ptr<Metric> make_metric_KerrBL() { return std::make_unique<KerrBL>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_KERR_BL_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/kerr_bl_accel.h"

void kerr_bl_packet_acceleration(double rs, double a, double a2, const double* y, double* acc) {
  packet_acceleration_simd([rs, a, a2](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k,
                                       Vec4T<SimdD>& out) { kerr_bl_accel(rs, a, a2, x[1], x[2], k[0], k[1], k[2], k[3], out); },
                           y, acc, kPacketLanes);
}
void kerr_bl_packet_constraint(double rs, double a, double a2, const double* y, double target, double* value,
                               double* scale) {
  packet_constraint_simd(
      [rs, a, a2](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { kerr_bl_metric_tensor(rs, a, a2, x, g); }, y, target, value,
      scale, kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(kerr_bl_packet_acceleration);
void KerrBL::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(kerr_bl_packet_acceleration)(rs_, a_, a2_, y, a);
}
HWY_EXPORT(kerr_bl_packet_constraint);
void KerrBL::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(kerr_bl_packet_constraint)(rs_, a_, a2_, y, target, value, scale);
}
}  // namespace geovis
#endif
