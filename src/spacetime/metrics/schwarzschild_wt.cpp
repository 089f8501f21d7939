// "Schwarzschild without time" (Motion4D "SchwarzschildWT") in (t, r, θ, φ):
//   ds² = −dt² + dr²/(1 − r_s/r) + r² (dθ² + sin²θ dφ²),  r_s = 2M,
// the spatial Schwarzschild geometry (Flamm's paraboloid) times a flat time: light rays follow the
// geodesics of the spatial slice t = const of Schwarzschild, without the gravitational redshift
// and time delay (Flamm, Phys. Z. 17 (1916) 448; Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184). Its curvature is that of the spatial slice: sectional curvatures −M/r³ for the
// radial and 2M/r³ for the tangential planes. Christoffel symbols: diagonal (diagonal_metric.h,
// spherical_diagonal with A = 1, B = 1/(1 − r_s/r)). Natural tetrad (Motion4D localToCoord):
// e_(0) = ∂_t, e_(1) = √(1 − r_s/r) ∂_r, e_(2) = ∂_θ/r, e_(3) = ∂_φ/(r sin θ). The chart ends at
// the throat r = r_s (g_rr diverges): stop at r_s (1 + horizon_eps) (Motion4D: r² <= (1 + 1e-6) r_s²).
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class SchwarzschildWT final : public MetricCRTP<SchwarzschildWT> {
 public:
  SchwarzschildWT()
      : MetricCRTP({"SchwarzschildWT",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0 (throat of the spatial slice at r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "spatial Schwarzschild geometry times flat time (Flamm, Phys. Z. 17 (1916) 448; Mueller & "
                    "Grave, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T st = sin_t(x[2]);
    g[0][0] = T(-1.0);
    g[1][1] = 1.0 / (1.0 - rs_ / r);
    g[2][2] = r * r;
    g[3][3] = r * r * st * st;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    const double r = x[1], f = 1.0 - rs_ / r, df = rs_ / (r * r);
    spherical_diagonal(1.0, 0.0, 1.0 / f, -df / (f * f), r * r, 2.0 * r, x[2], d);
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
    return x[1] > r_break_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (x[1] > rs_ && x[1] > 0.0) diagonal(x, d);
    if (!(x[1] > rs_ && x[1] > 0.0) || !diagonal_static_tetrad(d.h, e))
      throw Error("SchwarzschildWT: no static observer at r = " + std::to_string(x[1]) +
                  " (needs r > r_s and sin(theta) != 0)");
    return e;
  }

 protected:
  void on_params_changed() override {
    rs_ = 2.0 * p(0);
    r_break_ = rs_ > 0.0 ? rs_ * (1.0 + horizon_eps_) : 1e-300;
  }

 private:
  double rs_ = 2.0, r_break_ = 2.0;
};

std::unique_ptr<Metric> make_metric_SchwarzschildWT() { return std::make_unique<SchwarzschildWT>(); }

}  // namespace geovis
