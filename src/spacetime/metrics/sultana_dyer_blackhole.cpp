// Sultana–Dyer black hole in a dust-dominated universe (Motion4D "SultanaDyerBlackhole"; Sultana &
// Dyer, Gen. Rel. Grav. 37 (2005) 1347), coordinates (t, r, θ, φ):
//   ds² = t⁴ [−(1 − h) dt² + 2h dt dr + (1 + h) dr² + r² (dθ² + sin²θ dφ²)],  h = 2m/r,
// the Schwarzschild metric ĝ in Kerr–Schild (ingoing Eddington–Finkelstein) time, conformally
// scaled by Ω² = a(t)², a = t² (a flat dust universe in conformal time t). Motion4D writes the same
// metric with signature (+,−,−,−).
// Christoffel symbols of g = Ω² ĝ (Wald (1984) eq. D.1): Γ^a_bc = Γ̂^a_bc + ω (δ^a_b δ^t_c + δ^a_c δ^t_b)
// − ω ĝ_bc ĝ^at, ω = ∂_t ln Ω = 2/t. With ĝ^tt = −(1 + h), ĝ^tr = h, ĝ^rr = 1 − h and h' = −h/r:
//   Γ^t_tt = −½ h h' + ω (1 + h²),  Γ^t_tr = (1 + h)(ωh − ½h'),  Γ^t_rr = −h'(1 + h/2) + ω (1 + h)²,
//   Γ^t_θθ = −h r + ω r² (1 + h),  Γ^t_φφ = Γ^t_θθ sin²θ,
//   Γ^r_tt = (1 − h)(ωh − ½h'),  Γ^r_tr = ½ h h' + ω (1 − h²),  Γ^r_rr = (1 + h)(½h' − ωh),
//   Γ^r_θθ = −(1 − h) r − ω r² h,  Γ^r_φφ = Γ^r_θθ sin²θ,
//   Γ^θ_tθ = Γ^φ_tφ = ω,  Γ^θ_rθ = Γ^φ_rφ = 1/r,  Γ^θ_φφ = −sinθ cosθ,  Γ^φ_θφ = cot θ.
// Natural tetrads (Motion4D localToCoord, all scaled by 1/a = 1/t²): static (= default),
// e_(0) = ∂_t/(t² w), e_(1) = (h/w ∂_t + w ∂_r)/t², w = √(1 − h); comoving (the observer normal to
// t = const), e_(0) = (W ∂_t − h/W ∂_r)/t², e_(1) = ∂_r/(t² W), W = √(1 + h); e_(2) = ∂_θ/(t² r),
// e_(3) = ∂_φ/(t² r sin θ).
// The ray stops at r² <= (1 + horizon_eps) (2m)² (Motion4D breakCondition), at the big bang t <= 0
// (a = 0) and on the polar axis. Cosmological: no escape criterion.
#include <cmath>

#include "spacetime/metric_crtp.h"

namespace geovis {

class SultanaDyerBlackhole final : public MetricCRTP<SultanaDyerBlackhole> {
 public:
  SultanaDyerBlackhole()
      : MetricCRTP({"SultanaDyerBlackhole",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass m of the black hole"}},
                    {TetradKind::Default, TetradKind::Static, TetradKind::Comoving},
                    "Sultana-Dyer black hole in a dust universe (Sultana & Dyer, Gen. Rel. Grav. 37 (2005) 1347)",
                    Vec4{{1, 6, M_PI / 2, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T a2 = x[0] * x[0] * x[0] * x[0];
    const T h = 2.0 * m_ / r;
    const T st = sin_t(x[2]);
    g[0][0] = -a2 * (1.0 - h);
    g[0][1] = g[1][0] = a2 * h;
    g[1][1] = a2 * (1.0 + h);
    g[2][2] = a2 * r * r;
    g[3][3] = a2 * r * r * st * st;
  }

  /// The independent symbols of the file comment.
  struct Symbols {
    double ttt, ttr, trr, tqq, rtt, rtr, rrr, rqq, w, ir, sc, cot, s2;
  };
  void symbols(const Vec4& x, Symbols& c) const {
    const double t = x[0], r = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double h = 2.0 * m_ / r, dh = -h / r, w = 2.0 / t;
    c.ttt = -0.5 * h * dh + w * (1.0 + h * h);
    c.ttr = (1.0 + h) * (w * h - 0.5 * dh);
    c.trr = -dh * (1.0 + 0.5 * h) + w * (1.0 + h) * (1.0 + h);
    c.tqq = -h * r + w * r * r * (1.0 + h);
    c.rtt = (1.0 - h) * (w * h - 0.5 * dh);
    c.rtr = 0.5 * h * dh + w * (1.0 - h * h);
    c.rrr = (1.0 + h) * (0.5 * dh - w * h);
    c.rqq = -(1.0 - h) * r - w * r * r * h;
    c.w = w;
    c.ir = 1.0 / r;
    c.sc = st * ct;
    c.cot = ct / st;
    c.s2 = st * st;
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    Symbols c;
    symbols(x, c);
    auto set = [&G](int mu, int a, int b, double v) { G.G[mu][a][b] = G.G[mu][b][a] = v; };
    set(0, 0, 0, c.ttt);
    set(0, 0, 1, c.ttr);
    set(0, 1, 1, c.trr);
    set(0, 2, 2, c.tqq);
    set(0, 3, 3, c.tqq * c.s2);
    set(1, 0, 0, c.rtt);
    set(1, 0, 1, c.rtr);
    set(1, 1, 1, c.rrr);
    set(1, 2, 2, c.rqq);
    set(1, 3, 3, c.rqq * c.s2);
    set(2, 0, 2, c.w);
    set(2, 1, 2, c.ir);
    set(2, 3, 3, -c.sc);
    set(3, 0, 3, c.w);
    set(3, 1, 3, c.ir);
    set(3, 2, 3, c.cot);
  }

  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    Symbols c;
    symbols(x, c);
    const double ang = k[2] * k[2] + c.s2 * k[3] * k[3];
    a[0] = -(c.ttt * k[0] * k[0] + 2.0 * c.ttr * k[0] * k[1] + c.trr * k[1] * k[1] + c.tqq * ang);
    a[1] = -(c.rtt * k[0] * k[0] + 2.0 * c.rtr * k[0] * k[1] + c.rrr * k[1] * k[1] + c.rqq * ang);
    a[2] = -2.0 * (c.w * k[0] + c.ir * k[1]) * k[2] + c.sc * k[3] * k[3];
    a[3] = -2.0 * (c.w * k[0] + c.ir * k[1] + c.cot * k[2]) * k[3];
  }

  /// After the big bang t > 0, outside the horizon break radius (file comment), off the axis.
  bool is_valid(const Vec4& x) const override {
    return x[0] > 0.0 && x[1] > 0.0 && x[1] * x[1] > r2_break_ && std::isfinite(x[0]) && std::isfinite(x[1]) &&
           std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double t = x[0], r = x[1], st = std::sin(x[2]);
    const double h = 2.0 * m_ / r;
    const bool comoving = kind == TetradKind::Comoving;
    if (!(t > 0.0 && r > 0.0) || st == 0.0 || (!comoving && !(h < 1.0)))
      throw Error("SultanaDyerBlackhole: no " + std::string(tetrad_kind_name(kind)) +
                  " observer at t = " + std::to_string(t) + ", r = " + std::to_string(r) +
                  " (needs t > 0, sin(theta) != 0 and, for the static frame, r > 2m)");
    const double ia = 1.0 / (t * t);
    Tetrad e{};
    if (comoving) {
      const double W = std::sqrt(1.0 + h);
      e[0][0] = W * ia;
      e[0][1] = -h / W * ia;
      e[1][1] = ia / W;
    } else {
      const double w = std::sqrt(1.0 - h);
      e[0][0] = ia / w;
      e[1][0] = h / w * ia;
      e[1][1] = w * ia;
    }
    e[2][2] = ia / r;
    e[3][3] = ia / (r * st);
    return e;
  }

 protected:
  void on_params_changed() override {
    m_ = p(0);
    r2_break_ = (1.0 + horizon_eps_) * 4.0 * m_ * m_;
  }

 private:
  double m_ = 1.0, r2_break_ = 4.0;
};

std::unique_ptr<Metric> make_metric_SultanaDyerBlackhole() { return std::make_unique<SultanaDyerBlackhole>(); }

}  // namespace geovis
