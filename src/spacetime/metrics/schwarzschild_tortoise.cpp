// Schwarzschild spacetime in tortoise coordinates (t, ρ, θ, φ) (Motion4D "SchwarzschildTortoise";
// Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Schwarzschild: tortoise
// coordinates"; Misner, Thorne & Wheeler (1973) §25.5):
//   ρ = r + r_s ln(r/r_s − 1),   ds² = (1 − r_s/r) (−dt² + dρ²) + r² (dθ² + sin²θ dφ²),
// covering the exterior r > r_s with ρ ∈ ℝ (the horizon is ρ → −∞). Radial light rays are
// t ± ρ = const. The areal radius is r(ρ) = r_s (1 + w) with w = W(e^(ρ/r_s − 1)) (Lambert W,
// principal branch), found here by Newton's method on w + ln w = ρ/r_s − 1 (no overflow for large
// ρ); dw/dρ = w/(r_s (1 + w)), d²w/dρ² = w/(r_s² (1 + w)³), which carry r(ρ) through automatic
// differentiation (second-order Taylor step from the double value, exact for Dual and Dual²).
// Christoffel symbols: diagonal metric (diagonal_metric.h) with f = 1 − r_s/r = w/(1 + w),
// ∂_ρ f = r_s f/r², ∂_ρ r² = 2 r f. Natural tetrad: static, e_(0) = ∂_t/√f, e_(1) = ∂_ρ/√f,
// e_(2) = ∂_θ/r, e_(3) = ∂_φ/(r sin θ). The ray stops where f < horizon_eps (as Schwarzschild).
// Pseudo-Cartesian coordinates use the areal radius r(ρ).
#include <algorithm>
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class SchwarzschildTortoise final : public MetricCRTP<SchwarzschildTortoise> {
 public:
  SchwarzschildTortoise()
      : MetricCRTP({"SchwarzschildTortoise",
                    {"t", "rho", "theta", "phi"},
                    CoordType::Custom,
                    {{"mass", 1.0, 0.0, 1e300, true, false, "mass M > 0 of the black hole (r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Schwarzschild black hole in tortoise coordinates (Misner, Thorne & Wheeler (1973) 25.5; "
                    "Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 8, M_PI / 2, 0}},
                    {}}) {
    on_params_changed();
  }

  /// w = W(e^u), u = ρ/r_s − 1, from w + ln w = u (Newton; converges from the asymptotic guesses
  /// in a few steps for every u).
  double lambert_w_exp(double u) const {
    double w = u > 1.0 ? u - std::log(u) : std::exp(u);
    for (int i = 0; i < 40; ++i) {
      const double f = w + std::log(w) - u;
      const double step = f / (1.0 + 1.0 / w);
      double wn = w - step;
      if (!(wn > 0.0)) wn = 0.5 * w;  // keep w > 0 (only possible far from the root)
      if (std::fabs(wn - w) <= 1e-15 * wn) return wn;
      w = wn;
    }
    return w;
  }

  /// Areal radius r(ρ) (file comment).
  double areal_radius(double rho) const { return rs_ * (1.0 + lambert_w_exp(rho / rs_ - 1.0)); }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const double rho0 = value_of(x[1]);
    const double w0 = lambert_w_exp(rho0 / rs_ - 1.0);
    const T delta = x[1] - rho0;
    const double w1 = w0 / (rs_ * (1.0 + w0)), w2 = w0 / (rs_ * rs_ * std::pow(1.0 + w0, 3));
    const T w = w0 + w1 * delta + 0.5 * w2 * delta * delta;
    const T f = w / (1.0 + w);
    const T r = rs_ * (1.0 + w);
    const T st = sin_t(x[2]);
    g[0][0] = -f;
    g[1][1] = f;
    g[2][2] = r * r;
    g[3][3] = r * r * st * st;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    const double w = lambert_w_exp(x[1] / rs_ - 1.0);
    const double r = rs_ * (1.0 + w), f = w / (1.0 + w), df = rs_ * f / (r * r);
    spherical_diagonal(f, df, f, df, r * r, 2.0 * r * f, x[2], d);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_accel(d, k, a);
  }

  /// Outside the horizon break radius: ρ > ρ(r_s (1 + horizon_eps)), i.e. 1 − r_s/r > ~horizon_eps
  /// (Metric::horizon_eps); off the polar axis.
  bool is_valid(const Vec4& x) const override {
    return x[1] > rho_break_ && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) &&
           std::isfinite(x[3]) && x[2] != 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!std::isfinite(x[1]) || std::sin(x[2]) == 0.0)
      throw Error("SchwarzschildTortoise: no static observer at rho = " + std::to_string(x[1]) +
                  ", theta = " + std::to_string(x[2]));
    const double w = lambert_w_exp(x[1] / rs_ - 1.0);
    const double r = rs_ * (1.0 + w), sf = std::sqrt(w / (1.0 + w));
    Tetrad e{};
    e[0][0] = 1.0 / sf;
    e[1][1] = 1.0 / sf;
    e[2][2] = 1.0 / r;
    e[3][3] = 1.0 / (r * std::sin(x[2]));
    return e;
  }

  int to_pseudo_cartesian(const Vec4& x, Vec3& p) const override {
    const double r = areal_radius(x[1]);
    double st, ct, sp, cp;
    fast_sincos(x[2], st, ct);
    fast_sincos(x[3], sp, cp);
    p = {r * st * cp, r * st * sp, r * ct};
    return 0;
  }
  Vec4 from_pseudo_cartesian(double t, const Vec3& p, int) const override {
    const double r = norm(p);
    const double th = r > 0 ? std::acos(std::clamp(p.z / r, -1.0, 1.0)) : 0.0;
    const double rho = r > rs_ ? r + rs_ * std::log(r / rs_ - 1.0) : -INFINITY;
    return {{t, rho, th, std::atan2(p.y, p.x)}};
  }

 protected:
  void on_params_changed() override {
    rs_ = 2.0 * p(0);
    const double rb = rs_ * (1.0 + horizon_eps_);
    rho_break_ = rb + rs_ * std::log(rb / rs_ - 1.0);
  }

 private:
  double rs_ = 2.0, rho_break_ = 0.0;
};

std::unique_ptr<Metric> make_metric_SchwarzschildTortoise() { return std::make_unique<SchwarzschildTortoise>(); }

}  // namespace geovis
