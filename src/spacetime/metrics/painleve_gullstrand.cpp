// Schwarzschild spacetime in Painlevé-Gullstrand coordinates (T, r, θ, φ), G = c = 1:
//   ds² = −(1 − r_s/r) dT² + 2 sqrt(r_s/r) dT dr + dr² + r² (dθ² + sin²θ dφ²)
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Schwarzschild spacetime /
// Painlevé-Gullstrand coordinates"; K. Martel, E. Poisson, Am. J. Phys. 69 (2001) 476.
// T is the proper time of observers falling radially from rest at infinity; the slices T = const
// are flat and the chart is regular across the horizon.
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"

namespace geovis {

class PainleveGullstrand final : public MetricCRTP<PainleveGullstrand> {
 public:
  PainleveGullstrand()
      : MetricCRTP({"PainleveGullstrand",
                    {"T", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0 of the black hole (r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static, TetradKind::Freefall},
                    "Schwarzschild black hole in Painleve-Gullstrand coordinates (Mueller & Grave, Catalogue of "
                    "Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::sin;
    using std::sqrt;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T st = sin_t(x[2]);
    g[0][0] = -(1.0 - rs_ / r);
    // M = 0 (Minkowski): no shift; sqrt has no derivative at 0 for automatic differentiation.
    g[0][1] = g[1][0] = rs_ > 0.0 ? sqrt(rs_ / r) : T(0.0);
    g[1][1] = T(1.0);
    g[2][2] = r * r;
    g[3][3] = r * r * st * st;
  }

  /// Non-zero symbols (Catalogue of Spacetimes, Painlevé-Gullstrand coordinates), w = sqrt(r_s/r):
  ///   Γ^T_TT = w r_s/(2r²), Γ^T_Tr = r_s/(2r²), Γ^T_rr = w/(2r), Γ^T_θθ = −w r, Γ^T_φφ = −w r sin²θ,
  ///   Γ^r_TT = r_s (r − r_s)/(2r³), Γ^r_Tr = −w r_s/(2r²), Γ^r_rr = −r_s/(2r²),
  ///   Γ^r_θθ = −(r − r_s), Γ^r_φφ = −(r − r_s) sin²θ,
  ///   Γ^θ_rθ = Γ^φ_rφ = 1/r, Γ^θ_φφ = −sinθ cosθ, Γ^φ_θφ = cotθ.
  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double r = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double w = std::sqrt(rs_ / r);
    const double rmrs = r - rs_;
    const double q = rs_ / (2.0 * r * r);
    G.G[0][0][0] = w * q;
    G.G[0][0][1] = G.G[0][1][0] = q;
    G.G[0][1][1] = w / (2.0 * r);
    G.G[0][2][2] = -w * r;
    G.G[0][3][3] = -w * r * st * st;
    G.G[1][0][0] = rs_ * rmrs / (2.0 * r * r * r);
    G.G[1][0][1] = G.G[1][1][0] = -w * q;
    G.G[1][1][1] = -q;
    G.G[1][2][2] = -rmrs;
    G.G[1][3][3] = -rmrs * st * st;
    G.G[2][1][2] = G.G[2][2][1] = 1.0 / r;
    G.G[2][3][3] = -st * ct;
    G.G[3][1][3] = G.G[3][3][1] = 1.0 / r;
    G.G[3][2][3] = G.G[3][3][2] = ct / st;
  }

  /// −Γ^μ_{ab} k^a k^b with the symbols above written out.
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    const double r = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double w = std::sqrt(rs_ / r);
    const double rmrs = r - rs_;
    const double q = rs_ / (2.0 * r * r);
    const double ang = k[2] * k[2] + st * st * k[3] * k[3];
    a[0] = -(w * q * k[0] * k[0] + 2.0 * q * k[0] * k[1] + w / (2.0 * r) * k[1] * k[1]) + w * r * ang;
    a[1] = -(rs_ * rmrs / (2.0 * r * r * r) * k[0] * k[0] - 2.0 * w * q * k[0] * k[1] - q * k[1] * k[1]) + rmrs * ang;
    a[2] = -2.0 / r * k[1] * k[2] + st * ct * k[3] * k[3];
    a[3] = -2.0 / r * k[1] * k[3] - 2.0 * ct / st * k[2] * k[3];
  }

  /// Regular across the horizon: valid for r > 0 (small margin) and off the polar axis.
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
    // g_tt = −(1 − r_s/r), g_tr = sqrt(r_s/r).
    const double E = -(1.0 - rs_ / r) * k[0] + std::sqrt(rs_ / r) * k[1];
    return r < rs_ ? (k[1] > 0.0 && E < 0.0) : (E > 0.0 && k[1] < 0.0);
  }

  /// Static observer (r > r_s), as Motion4D's m4dMetricPainleveGullstrand, w = sqrt(1 − r_s/r):
  ///   e_(0) = ∂_T / w,  e_(1) = sqrt(r_s/(r − r_s)) ∂_T + w ∂_r.
  /// Freefall observer from rest at infinity (any r > 0), w = sqrt(r_s/r):
  ///   e_(0) = ∂_T − w ∂_r,  e_(1) = ∂_r.
  /// Default = static, as in Motion4D. e_(2) = ∂_θ/r, e_(3) = ∂_φ/(r sinθ) for both.
  /// Escape (escape.h): r is Schwarzschild's areal radius and k^r = dr/dλ in any chart, so the
  /// test is Schwarzschild's (photon sphere r = 1.5 r_s); r is |p|.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    return escapes_spherical(x[1], k[1], 1.5 * rs_, r_min, x[1], radius);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1];
    if (!(r > 0.0) || std::sin(x[2]) == 0.0)
      throw Error("PainleveGullstrand: no local tetrad at r = " + std::to_string(r) + " or on the polar axis");
    Tetrad e{};
    if (kind == TetradKind::Freefall) {
      e[0][0] = 1.0;
      e[0][1] = -std::sqrt(rs_ / r);
      e[1][1] = 1.0;
    } else {
      if (!(r > rs_))
        throw Error("PainleveGullstrand: no static observer at r = " + std::to_string(r) +
                    " <= r_s = " + std::to_string(rs_) + " (use localframe freefall inside the horizon)");
      const double w = std::sqrt(1.0 - rs_ / r);
      e[0][0] = 1.0 / w;
      e[1][0] = std::sqrt(rs_ / (r - rs_));
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

std::unique_ptr<Metric> make_metric_PainleveGullstrand() { return std::make_unique<PainleveGullstrand>(); }

}  // namespace geovis
