// Teo's rotating traversable wormhole with N = 1, K = 1, the Ellis shape b(r) = b0²/r and frame
// dragging ω = b0²/(2r³), shared by Motion4D's "TeoSimpleWH" and "TeoWHl" (the latter is Teo's
// general form with N(l) = K(l) = 1 written out, i.e. the same spacetime). Coordinates (t, l, θ, φ)
// with proper radial length l:
//   ds² = −dt² + dl² + r² dθ² + r² sin²θ (dφ − ω dt)²,  r² = b0² + l²,  ω = b0²/(2 r³)
// (Teo, Phys. Rev. D 58 (1998) 024014, eq. (1) with redshift N = 1, K = 1, frame dragging
// ω = 2J/r³ with J = b0²/4 as chosen in Motion4D). Expanded: g_tt = −1 + r² sin²θ ω²,
// g_tφ = −r² sin²θ ω, g_φφ = r² sin²θ. (Motion4D's TeoSimpleWH calculateMetric writes sin⁴θ in
// g[0][3] but sin²θ in g[3][0]; its commented-out version, its Christoffel symbols and TeoWHl use
// sin²θ, which is what the line element above gives.)
//
// Christoffel symbols: derived from the line element (F = r² sin²θ, ω' = dω/dl = −3ωl/r²):
//   Γ^t_tl = −½Fωω',  Γ^t_lφ = ½Fω',
//   Γ^l_tt = −l sin²θ ω² − Fωω',  Γ^l_tφ = l sin²θ ω + ½Fω',  Γ^l_θθ = −l,  Γ^l_φφ = −l sin²θ,
//   Γ^θ_tt = −sinθcosθ ω²,  Γ^θ_tφ = sinθcosθ ω,  Γ^θ_lθ = l/r²,  Γ^θ_φφ = −sinθcosθ,
//   Γ^φ_tl = −½ω'(1 + Fω²) − ωl/r²,  Γ^φ_tθ = −ω cotθ,  Γ^φ_lφ = ½Fωω' + l/r²,  Γ^φ_θφ = cotθ.
// Natural tetrads (Motion4D localToCoord): lnrf e_(0) = ∂_t + ω ∂_φ, e_(1) = ∂_l, e_(2) = ∂_θ/r,
// e_(3) = ∂_φ/(r sinθ); static e_(0) = ∂_t/w, w = √(1 − r² sin²θ ω²),
// e_(3) = (−r sinθ ω/w) ∂_t + (w/(r sinθ)) ∂_φ. Which of them is "default" is the metric's choice.
// Pseudo-Cartesian charts as Morris-Thorne (Motion4D transToPseudoCart): signed l, chart 0 for
// l > 0, chart 1 for l <= 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "spacetime/metric_crtp.h"

namespace geovis {

template <class M>
class TeoWormhole : public MetricCRTP<M> {
 public:
  using MetricCRTP<M>::MetricCRTP;

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::sin;
    using std::sqrt;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T r2 = b02_ + x[1] * x[1];
    const T r = sqrt(r2);
    const T omega = 0.5 * b02_ / (r2 * r);
    const T st = sin_t(x[2]);
    const T F = r2 * st * st;
    g[0][0] = -1.0 + F * omega * omega;
    g[0][3] = g[3][0] = -F * omega;
    g[1][1] = T(1.0);
    g[2][2] = r2;
    g[3][3] = F;
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double l = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double r2 = b02_ + l * l, r = std::sqrt(r2);
    const double om = 0.5 * b02_ / (r2 * r);
    const double dom = -3.0 * om * l / r2;  // ω' = dω/dl
    const double s2 = st * st, sc = st * ct, cot = ct / st;
    const double F = r2 * s2;
    const double lr2 = l / r2;
    auto set = [&G](int mu, int a, int b, double v) { G.G[mu][a][b] = G.G[mu][b][a] = v; };
    set(0, 0, 1, -0.5 * F * om * dom);
    set(0, 1, 3, 0.5 * F * dom);
    set(1, 0, 0, -l * s2 * om * om - F * om * dom);
    set(1, 0, 3, l * s2 * om + 0.5 * F * dom);
    set(1, 2, 2, -l);
    set(1, 3, 3, -l * s2);
    set(2, 0, 0, -sc * om * om);
    set(2, 0, 3, sc * om);
    set(2, 1, 2, lr2);
    set(2, 3, 3, -sc);
    set(3, 0, 1, -0.5 * dom * (1.0 + F * om * om) - om * lr2);
    set(3, 0, 2, -om * cot);
    set(3, 1, 3, 0.5 * F * om * dom + lr2);
    set(3, 2, 3, cot);
  }

  /// Regular everywhere (Motion4D has no break condition); only the polar axis is singular.
  bool is_valid(const Vec4& x) const override {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]) &&
           x[2] != 0.0;  // sin θ == 0 iff θ == 0 (double θ)
  }

  int to_pseudo_cartesian(const Vec4& x, Vec3& p) const override {
    const double l = x[1], st = std::sin(x[2]);
    p = {l * st * std::cos(x[3]), l * st * std::sin(x[3]), l * std::cos(x[2])};
    return l > 0.0 ? 0 : 1;
  }

  Vec4 from_pseudo_cartesian(double t, const Vec3& p, int chart) const override {
    const double s = chart == 0 ? 1.0 : -1.0;
    const double d = norm(p);
    const double th = d > 0 ? std::acos(std::clamp(s * p.z / d, -1.0, 1.0)) : 0.0;
    return {{t, s * d, th, std::atan2(s * p.y, s * p.x)}};
  }

 protected:
  /// The static (static_frame) or the lnrf tetrad of the file comment.
  Tetrad teo_tetrad(const Vec4& x, bool static_frame) const {
    const std::string& name = this->info().name;
    const double st = std::sin(x[2]);
    if (st == 0.0) throw Error(name + ": natural tetrads are singular on the polar axis (sin(theta) = 0)");
    const double r2 = b02_ + x[1] * x[1], r = std::sqrt(r2);
    const double om = 0.5 * b02_ / (r2 * r);
    Tetrad e{};
    e[1][1] = 1.0;
    e[2][2] = 1.0 / r;
    if (static_frame) {
      const double w2 = 1.0 - r2 * st * st * om * om;  // −g_tt
      if (!(w2 > 0.0)) {
        std::ostringstream os;
        os << name << ": no static observer at l = " << x[1] << ", theta = " << x[2]
           << " (g_tt >= 0); use the lnrf frame";
        throw Error(os.str());
      }
      const double w = std::sqrt(w2);
      e[0][0] = 1.0 / w;
      e[3][0] = -r * st * om / w;
      e[3][3] = w / (r * st);
      return e;
    }
    e[0][0] = 1.0;
    e[0][3] = om;
    e[3][3] = 1.0 / (r * st);
    return e;
  }

  void on_params_changed() override { b02_ = this->p(0) * this->p(0); }

  double b02_ = 1.0;
};

}  // namespace geovis
