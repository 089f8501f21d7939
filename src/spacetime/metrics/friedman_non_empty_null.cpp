// Friedmann–Lemaître–Robertson–Walker dust universe without cosmological constant in conformal
// time χ and isotropic radius r (Motion4D "FriedmanNonEmptyNull": non-empty, Λ = 0; Friedmann,
// Z. Phys. 10 (1922) 377; Misner, Thorne & Wheeler (1973) §27.10, Box 27.1), coordinates (χ, r, θ, φ):
//   ds² = R(χ)² [−dχ² + (dr² + r² (dθ² + sin²θ dφ²))/B²],  B = 1 + k r²/4,
// with the dust scale factors of Motion4D (calc_R), C = 4M/(3π):
//   k = 0: R = (9/4) C χ²,   k = 1: R = (C/2)(1 − cos χ),   k = −1: R = (C/2)(cosh χ − 1).
// The parameter k is snapped as in Motion4D: k >= 1 → 1, k <= −1 → −1, otherwise 0. Each R solves
// the dust (zero pressure) equation 2 R R'' − R'² + k R² = 0 (the pressure-free Friedmann equation,
// MTW §27.10, in conformal time).
// Christoffel symbols: diagonal metric (diagonal_metric.h) with h = R² (−1, 1/B², r²/B², r² sin²θ/B²),
// ∂_χ h = (2R'/R) h, ∂_r(1/B²) = −k r/B³.
// Natural tetrad (Motion4D localToCoord, the same for default and static): the comoving dust
// observer, e_(0) = ∂_χ/R, e_(1) = |B| ∂_r/R, e_(2) = |B| ∂_θ/(R r), e_(3) = |B| ∂_φ/(R r sin θ).
// The ray stops at the big bang / big crunch R(χ) = 0 (χ <= 0, and χ >= 2π for k = 1), at
// B = 0 for k = −1 (|B| < 1e-12, Motion4D breakCondition; the conformal boundary of the Poincaré
// ball r = 2), at r <= 0 and on the polar axis. Cosmological: no escape criterion.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class FriedmanNonEmptyNull final : public MetricCRTP<FriedmanNonEmptyNull> {
 public:
  FriedmanNonEmptyNull()
      : MetricCRTP(
            {"FriedmanNonEmptyNull",
             {"chi", "r", "theta", "phi"},
             CoordType::Spherical,
             {{"k", 0.0, -1e300, 1e300, false, false, "spatial curvature k (snapped: >= 1 -> 1, <= -1 -> -1, else 0)"},
              {"mass", 1.0, 0.0, 1e300, true, false, "mass M of the dust (C = 4M/(3 pi))"}},
             {TetradKind::Default, TetradKind::Static},
             "Friedmann dust universe in conformal time (Friedmann, Z. Phys. 10 (1922) 377; Misner, Thorne & "
             "Wheeler (1973) 27.10)",
             Vec4{{1, 10, M_PI / 2, 0}},
             {}}) {
    on_params_changed();
  }

  /// R(χ) (file comment); templated for automatic differentiation.
  template <class T>
  T scale(const T& chi) const {
    using std::cos;
    using std::cosh;
    if (k_ == 0) return 2.25 * c_ * chi * chi;
    if (k_ == 1) return 0.5 * c_ * (1.0 - cos(chi));
    return 0.5 * c_ * (cosh(chi) - 1.0);
  }
  double scale_rate(double chi) const {
    if (k_ == 0) return 4.5 * c_ * chi;
    if (k_ == 1) return 0.5 * c_ * std::sin(chi);
    return 0.5 * c_ * std::sinh(chi);
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T R = scale(x[0]);
    const T& r = x[1];
    const T B = 1.0 + 0.25 * double(k_) * r * r;
    const T a = R * R / (B * B);
    const T st = sin_t(x[2]);
    g[0][0] = -R * R;
    g[1][1] = a;
    g[2][2] = a * r * r;
    g[3][3] = a * r * r * st * st;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double R = scale(x[0]), dlnR2 = 2.0 * scale_rate(x[0]) / R;
    const double r = x[1], k = double(k_);
    const double B = 1.0 + 0.25 * k * r * r;
    const double R2 = R * R, a = R2 / (B * B), da = -R2 * k * r / (B * B * B);  // ∂_r (R²/B²)
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double s2 = st * st;
    d.h[0] = -R2;
    d.h[1] = a;
    d.h[2] = a * r * r;
    d.h[3] = a * r * r * s2;
    for (int i = 0; i < 4; ++i) d.dh[0][i] = dlnR2 * d.h[i];
    d.dh[1][1] = da;
    d.dh[1][2] = da * r * r + 2.0 * a * r;
    d.dh[1][3] = d.dh[1][2] * s2;
    d.dh[2][3] = 2.0 * a * r * r * st * ct;
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

  /// Between big bang and big crunch, off the conformal boundary, r > 0, off the axis (file comment).
  bool is_valid(const Vec4& x) const override {
    const double chi = x[0], r = x[1];
    if (!(std::isfinite(chi) && std::isfinite(r) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0))
      return false;
    if (!(chi > 0.0 && r > 0.0) || (k_ == 1 && !(chi < 2.0 * M_PI))) return false;
    return k_ != -1 || std::fabs(1.0 - 0.25 * r * r) >= 1e-12;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x))
      throw Error("FriedmanNonEmptyNull: no comoving observer at chi = " + std::to_string(x[0]) +
                  ", r = " + std::to_string(x[1]) + " (outside the chart)");
    const double R = scale(x[0]), r = x[1];
    const double B = std::fabs(1.0 + 0.25 * double(k_) * r * r);
    Tetrad e{};
    e[0][0] = 1.0 / R;
    e[1][1] = B / R;
    e[2][2] = B / (R * r);
    e[3][3] = B / (R * r * std::sin(x[2]));
    return e;
  }

 protected:
  void on_params_changed() override {
    k_ = p(0) >= 1.0 ? 1 : (p(0) <= -1.0 ? -1 : 0);
    c_ = 4.0 * p(1) / (3.0 * M_PI);
  }

 private:
  int k_ = 0;
  double c_ = 4.0 / (3.0 * M_PI);
};

std::unique_ptr<Metric> make_metric_FriedmanNonEmptyNull() { return std::make_unique<FriedmanNonEmptyNull>(); }

}  // namespace geovis
