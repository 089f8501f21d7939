// Ehlers–Kundt class AII of the static vacuum Petrov type D metrics (Motion4D
// "Petrov_Type_D_AII_ES"; Stephani et al., Exact Solutions of Einstein's Field Equations (2003)
// §18.6; Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Petrov type D – Levi-Civita
// spacetimes"), in (t, r, φ, z), 0 < z < b:
//   ds² = −(b/z − 1) dt² + dz²/(b/z − 1) + z² (dr² + sinh²r dφ²),
// the analogue of Schwarzschild with hyperbolic instead of spherical 2-surfaces z = const, t = const;
// z = b is a horizon. Christoffel symbols: diagonal (diagonal_metric.h) with ∂_z g_tt = −b/z²,
// ∂_z g_zz = (b/z²)/(b/z − 1)², ∂_z g_rr = 2z, ∂_z g_φφ = 2z sinh²r, ∂_r g_φφ = 2z² sinh r cosh r.
// Natural tetrad (Motion4D localToCoord): e_(0) = ∂_t/w, e_(1) = ∂_r/z, e_(2) = ∂_φ/(z sinh r),
// e_(3) = w ∂_z, w = √(b/z − 1). Chart: z > 0, off the axis r = 0, and before the horizon: the ray
// stops where b/z − 1 < horizon_eps (Motion4D: z² >= (1 − eps) b²).
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PetrovTypeD_AII final : public MetricCRTP<PetrovTypeD_AII> {
 public:
  PetrovTypeD_AII()
      : MetricCRTP({"Petrov_Type_D_AII_ES",
                    {"t", "r", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"b", 1.0, 0.0, 1e300, true, false, "mass parameter b > 0 (horizon at z = b)"}},
                    {TetradKind::Default},
                    "Ehlers-Kundt static type D vacuum AII (Stephani et al., Exact Solutions (2003) 18.6; Mueller & "
                    "Grave, arXiv:0904.4184)",
                    Vec4{{0, 1, 0, 0.6}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::sinh;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& z = x[3];
    const T w2 = b_ / z - 1.0;
    const T sh = sinh(x[1]);
    g[0][0] = -w2;
    g[1][1] = z * z;
    g[2][2] = z * z * sh * sh;
    g[3][3] = 1.0 / w2;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double z = x[3], w2 = b_ / z - 1.0, dw2 = -b_ / (z * z);
    const double sh = std::sinh(x[1]), ch = std::cosh(x[1]);
    d.h[0] = -w2;
    d.h[1] = z * z;
    d.h[2] = z * z * sh * sh;
    d.h[3] = 1.0 / w2;
    d.dh[3][0] = -dw2;
    d.dh[3][1] = 2.0 * z;
    d.dh[3][2] = 2.0 * z * sh * sh;
    d.dh[1][2] = 2.0 * z * z * sh * ch;
    d.dh[3][3] = -dw2 / (w2 * w2);
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
    const double z = x[3];
    return z > 0.0 && b_ / z - 1.0 > horizon_eps_ && x[1] != 0.0 && std::isfinite(x[0]) && std::isfinite(x[1]) &&
           std::isfinite(x[2]) && std::isfinite(z);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double z = x[3], r = x[1];
    if (!(z > 0.0 && z < b_) || r == 0.0)
      throw Error("Petrov_Type_D_AII_ES: no static observer at (r, z) = (" + std::to_string(r) + ", " +
                  std::to_string(z) + ") (needs 0 < z < b, r != 0)");
    const double w = std::sqrt(b_ / z - 1.0);
    Tetrad e{};
    e[0][0] = 1.0 / w;
    e[1][1] = 1.0 / z;
    e[2][2] = 1.0 / (z * std::fabs(std::sinh(r)));
    e[3][3] = w;
    return e;
  }

 protected:
  void on_params_changed() override { b_ = p(0); }

 private:
  double b_ = 1.0;
};

std::unique_ptr<Metric> make_metric_PetrovTypeD_AII() { return std::make_unique<PetrovTypeD_AII>(); }

}  // namespace geovis
