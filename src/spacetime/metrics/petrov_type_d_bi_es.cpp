// Ehlers–Kundt class BI of the static vacuum Petrov type D metrics (Motion4D "Petrov_Type_D_BI_ES";
// Stephani et al., Exact Solutions of Einstein's Field Equations (2003) §18.6; Müller & Grave,
// Catalogue of Spacetimes, arXiv:0904.4184, "Petrov type D – Levi-Civita spacetimes"), in (t, r, θ, φ):
//   ds² = r² (−sin²θ dt² + dθ²) + dr²/(1 − b/r) + (1 − b/r) dφ²,
// Schwarzschild (class AI) with the roles of t and φ exchanged by t → iφ, φ → it: the 2-surfaces
// r = const are de Sitter instead of spheres, and b = 0 is flat. Christoffel symbols: diagonal
// (diagonal_metric.h) with h = (−r² sin²θ, 1/(1 − b/r), r², 1 − b/r):
// ∂_r h = (−2r sin²θ, −b/(r − b)², 2r, b/r²), ∂_θ g_tt = −2r² sinθ cosθ.
// Natural tetrad (Motion4D localToCoord): e_(0) = ∂_t/(r sin θ), e_(1) = w ∂_r, e_(2) = ∂_θ/r,
// e_(3) = ∂_φ/w, w = √(1 − b/r). The ray stops at r > 0, for b > 0 at the break radius
// b (1 + horizon_eps) (Motion4D: r² <= (1 + 1e-6) b²), and before the Killing horizons sin θ = 0,
// where ∂_t becomes null (g_tt = −r² sin²θ = 0): there k^t ∝ 1/sin²θ diverges as k^t at a
// Schwarzschild horizon, so a ray approaching it creeps on in ever smaller steps until the step
// size underflows (gallery: 38% of the rays ended so, as "error"); it stops with the break margin
// of the horizon metrics (metric.h, Metric::horizon_eps) on the vanishing factor, sin²θ <
// horizon_eps. Motion4D has no break condition there.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PetrovTypeD_BI final : public MetricCRTP<PetrovTypeD_BI> {
 public:
  PetrovTypeD_BI()
      : MetricCRTP({"Petrov_Type_D_BI_ES",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"b", 1.0, -1e300, 1e300, false, false, "parameter b (b = 0: flat)"}},
                    {TetradKind::Default},
                    "Ehlers-Kundt static type D vacuum BI (Stephani et al., Exact Solutions (2003) 18.6; Mueller & "
                    "Grave, arXiv:0904.4184)",
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
    g[0][0] = -r * r * st * st;
    g[1][1] = 1.0 / f;
    g[2][2] = r * r;
    g[3][3] = f;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double r = x[1], f = 1.0 - b_ / r;
    double st, ct;
    fast_sincos(x[2], st, ct);
    d.h[0] = -r * r * st * st;
    d.h[1] = 1.0 / f;
    d.h[2] = r * r;
    d.h[3] = f;
    d.dh[1][0] = -2.0 * r * st * st;
    d.dh[2][0] = -2.0 * r * r * st * ct;
    d.dh[1][1] = -b_ / ((r - b_) * (r - b_));
    d.dh[1][2] = 2.0 * r;
    d.dh[1][3] = b_ / (r * r);
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
    const double st = std::sin(x[2]);
    return x[1] > r_break_ && st * st > horizon_eps_ && std::isfinite(x[0]) && std::isfinite(x[1]) &&
           std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1], st = std::sin(x[2]);
    if (!(r > 0.0 && r > b_) || st == 0.0)
      throw Error("Petrov_Type_D_BI_ES: no static observer at r = " + std::to_string(r) +
                  ", theta = " + std::to_string(x[2]) + " (needs r > max(0, b), sin(theta) != 0)");
    const double w = std::sqrt(1.0 - b_ / r);
    Tetrad e{};
    e[0][0] = 1.0 / (r * std::fabs(st));
    e[1][1] = w;
    e[2][2] = 1.0 / r;
    e[3][3] = 1.0 / w;
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

std::unique_ptr<Metric> make_metric_PetrovTypeD_BI() { return std::make_unique<PetrovTypeD_BI>(); }

}  // namespace geovis
