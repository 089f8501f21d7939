// Vaidya spacetime of a radiating star in ingoing Eddington–Finkelstein form (Motion4D
// "VaidyaIncRad"; Vaidya, Proc. Indian Acad. Sci. A 33 (1951) 264; Griffiths & Podolský, Exact
// Space-Times (2009) §9.5), coordinates (v, r, θ, φ):
//   ds² = −(1 − 2m(v)/r) dv² + 2 dv dr + r² (dθ² + sin²θ dφ²),
// a null dust with R_ab = (2 m'(v)/r²) ∂_a v ∂_b v (Poisson, A Relativist's Toolkit (2004) §4.3.5).
// Mass function as Motion4D (m4dMetricVaidyaIncRad calcMassFunc), s = v_l − v:
//   m(v) = k s^(1/3) tanh²(σ s) for v < v_l,  m(v) = 0 for v >= v_l (Minkowski),
//   m'(v) = −k [s^(−2/3) tanh²(σ s)/3 + 2σ s^(1/3) tanh(σ s)/cosh²(σ s)].
// Christoffel symbols (from the line element; f = 1 − 2m/r, inverse metric g^vr = 1, g^rr = f,
// g^vv = 0):
//   Γ^v_vv = m/r²,  Γ^v_θθ = −r,  Γ^v_φφ = −r sin²θ,
//   Γ^r_vv = m'/r + f m/r²,  Γ^r_vr = −m/r²,  Γ^r_θθ = −f r,  Γ^r_φφ = −f r sin²θ,
//   Γ^θ_rθ = Γ^φ_rφ = 1/r,  Γ^θ_φφ = −sinθ cosθ,  Γ^φ_θφ = cot θ.
// Natural tetrad (Motion4D localToCoord, the same for default and static): the static observer,
// e_(0) = ∂_v/w, e_(1) = ∂_v/w + w ∂_r, e_(2) = ∂_θ/r, e_(3) = ∂_φ/(r sin θ), w = √f.
// The ray stops at r <= 2m(v) (1 + horizon_eps) (Motion4D: r² <= (1 + eps) 4m²), at r <= 0 and on
// the polar axis. Time dependent: no escape criterion.
#include <cmath>

#include "spacetime/metric_crtp.h"

namespace geovis {

class VaidyaIncRad final : public MetricCRTP<VaidyaIncRad> {
 public:
  VaidyaIncRad()
      : MetricCRTP({"VaidyaIncRad",
                    {"v", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"k", 1.0, -1e300, 1e300, false, false,
                      "amplitude k of the mass function m(v) = k s^(1/3) tanh^2(sigma s)"},
                     {"sigma", 0.5, -1e300, 1e300, false, false, "rate sigma of the mass function, s = vl - v"},
                     {"vl", 0.0, -1e300, 1e300, false, false, "advanced time vl after which m = 0 (Minkowski)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Vaidya radiating star, ingoing Eddington-Finkelstein form (Vaidya, Proc. Indian Acad. Sci. A 33 "
                    "(1951) 264; Motion4D VaidyaIncRad mass function)",
                    Vec4{{0, 10, M_PI / 2, 0}},
                    {{"k", 0.0}}}) {
    on_params_changed();
  }

  /// m(v) (file comment); templated so that automatic differentiation sees m'(v) and m''(v).
  template <class T>
  T mass(const T& v) const {
    using std::pow;
    using std::tanh;
    if (!(value_of(v) < vl_)) return T(0.0);
    const T s = vl_ - v;
    const T th = tanh(sigma_ * s);
    return k_ * pow(s, 1.0 / 3.0) * th * th;
  }

  /// m(v) and m'(v) (file comment).
  void mass_and_rate(double v, double& m, double& dm) const {
    if (!(v < vl_)) {
      m = dm = 0.0;
      return;
    }
    const double s = vl_ - v, th = std::tanh(sigma_ * s), ch = std::cosh(sigma_ * s);
    const double c = std::cbrt(s);
    m = k_ * c * th * th;
    dm = -k_ * (th * th / (3.0 * c * c) + 2.0 * sigma_ * c * th / (ch * ch));
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T st = sin_t(x[2]);
    g[0][0] = -(1.0 - 2.0 * mass(x[0]) / r);
    g[0][1] = g[1][0] = T(1.0);
    g[2][2] = r * r;
    g[3][3] = r * r * st * st;
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double r = x[1];
    double m, dm, st, ct;
    mass_and_rate(x[0], m, dm);
    fast_sincos(x[2], st, ct);
    const double f = 1.0 - 2.0 * m / r, mr2 = m / (r * r), s2 = st * st;
    auto set = [&G](int mu, int a, int b, double v) { G.G[mu][a][b] = G.G[mu][b][a] = v; };
    set(0, 0, 0, mr2);
    set(0, 2, 2, -r);
    set(0, 3, 3, -r * s2);
    set(1, 0, 0, dm / r + f * mr2);
    set(1, 0, 1, -mr2);
    set(1, 2, 2, -f * r);
    set(1, 3, 3, -f * r * s2);
    set(2, 1, 2, 1.0 / r);
    set(2, 3, 3, -st * ct);
    set(3, 1, 3, 1.0 / r);
    set(3, 2, 3, ct / st);
  }

  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    const double r = x[1];
    double m, dm, st, ct;
    mass_and_rate(x[0], m, dm);
    fast_sincos(x[2], st, ct);
    const double f = 1.0 - 2.0 * m / r, mr2 = m / (r * r), s2 = st * st;
    const double ang = k[2] * k[2] + s2 * k[3] * k[3];
    a[0] = -mr2 * k[0] * k[0] + r * ang;
    a[1] = -(dm / r + f * mr2) * k[0] * k[0] + 2.0 * mr2 * k[0] * k[1] + f * r * ang;
    a[2] = -2.0 / r * k[1] * k[2] + st * ct * k[3] * k[3];
    a[3] = -2.0 / r * k[1] * k[3] - 2.0 * ct / st * k[2] * k[3];
  }

  /// Outside the apparent horizon r = 2m(v) (file comment) and off the polar axis.
  bool is_valid(const Vec4& x) const override {
    if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0))
      return false;
    double m, dm;
    mass_and_rate(x[0], m, dm);
    return x[1] > 0.0 && x[1] > 2.0 * m * (1.0 + horizon_eps_);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    double m, dm;
    mass_and_rate(x[0], m, dm);
    const double r = x[1], st = std::sin(x[2]);
    if (!(r > 0.0 && r > 2.0 * m) || st == 0.0)
      throw Error("VaidyaIncRad: no static observer at v = " + std::to_string(x[0]) + ", r = " + std::to_string(r) +
                  " (needs r > 2m(v) = " + std::to_string(2.0 * m) + ", sin(theta) != 0)");
    const double w = std::sqrt(1.0 - 2.0 * m / r);
    Tetrad e{};
    e[0][0] = 1.0 / w;
    e[1][0] = 1.0 / w;
    e[1][1] = w;
    e[2][2] = 1.0 / r;
    e[3][3] = 1.0 / (r * st);
    return e;
  }

 protected:
  void on_params_changed() override {
    k_ = p(0);
    sigma_ = p(1);
    vl_ = p(2);
  }

 private:
  double k_ = 1.0, sigma_ = 0.5, vl_ = 0.0;
};

std::unique_ptr<Metric> make_metric_VaidyaIncRad() { return std::make_unique<VaidyaIncRad>(); }

}  // namespace geovis
