// Ehlers–Kundt class AI of the static vacuum Petrov type D metrics (Motion4D
// "Petrov_Type_D_AI_ES"; Ehlers & Kundt in Gravitation: an Introduction to Current Research, ed.
// Witten (1962); Stephani et al., Exact Solutions of Einstein's Field Equations (2003) §18.6;
// Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Petrov type D – Levi-Civita
// spacetimes"), in (t, r, θ, φ):
//   ds² = −(1 − b/r) dt² + dr²/(1 − b/r) + r² (dθ² + sin²θ dφ²),
// i.e. Schwarzschild with b = 2M (b may be negative: a negative mass without horizon).
// Christoffel symbols: diagonal (diagonal_metric.h, spherical_diagonal with A = 1 − b/r,
// A' = b/r²). Natural tetrad (Motion4D localToCoord): static, e_(0) = ∂_t/w, e_(1) = w ∂_r,
// e_(2) = ∂_θ/r, e_(3) = ∂_φ/(r sin θ), w = √(1 − b/r). Stop at r > 0 and, for b > 0, at the
// horizon break radius b (1 + horizon_eps) (Motion4D: r <= (1 + 1e-6) b).
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PetrovTypeD_AI final : public MetricCRTP<PetrovTypeD_AI> {
 public:
  PetrovTypeD_AI()
      : MetricCRTP({"Petrov_Type_D_AI_ES",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"b", 1.0, -1e300, 1e300, false, false, "mass parameter b = 2M (any real; b < 0: no horizon)"}},
                    {TetradKind::Default},
                    "Ehlers-Kundt static type D vacuum AI (Schwarzschild) (Stephani et al., Exact Solutions (2003) "
                    "18.6; Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"b", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T f = 1.0 - b_ / r;
    const T st = sin_t(x[2]);
    g[0][0] = -f;
    g[1][1] = 1.0 / f;
    g[2][2] = r * r;
    g[3][3] = r * r * st * st;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    const double r = x[1], f = 1.0 - b_ / r, df = b_ / (r * r);
    spherical_diagonal(f, df, 1.0 / f, -df / (f * f), r * r, 2.0 * r, x[2], d);
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

  bool is_valid(const Vec4& x) const override {
    return x[1] > r_break_ && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) &&
           std::isfinite(x[3]) && x[2] != 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (x[1] > 0.0 && x[1] > b_) diagonal(x, d);
    if (!(x[1] > 0.0 && x[1] > b_) || !diagonal_static_tetrad(d.h, e))
      throw Error("Petrov_Type_D_AI_ES: no static observer at r = " + std::to_string(x[1]) +
                  " (needs r > max(0, b) and sin(theta) != 0)");
    return e;
  }

 protected:
  void on_params_changed() override {
    b_ = p(0);
    r_break_ = b_ > 0.0 ? b_ * (1.0 + horizon_eps_) : 0.0;
  }

 private:
  double b_ = 1.0, r_break_ = 1.0;
};

std::unique_ptr<Metric> make_metric_PetrovTypeD_AI() { return std::make_unique<PetrovTypeD_AI>(); }

}  // namespace geovis
