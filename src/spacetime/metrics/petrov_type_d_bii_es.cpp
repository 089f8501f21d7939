// Ehlers–Kundt class BII of the static vacuum Petrov type D metrics (Motion4D
// "Petrov_Type_D_BII_ES"; Stephani et al., Exact Solutions of Einstein's Field Equations (2003)
// §18.6; Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Petrov type D – Levi-Civita
// spacetimes"), in (t, r, φ, z), 0 < z < b:
//   ds² = z² (−sinh²r dt² + dr²) + (b/z − 1) dφ² + dz²/(b/z − 1),
// class AII with the roles of t and φ exchanged (t → iφ, φ → it). Christoffel symbols: diagonal
// (diagonal_metric.h) with h = (−z² sinh²r, z², b/z − 1, 1/(b/z − 1)): ∂_r g_tt = −2z² sinh r cosh r,
// ∂_z h = (−2z sinh²r, 2z, −b/z², b/(b − z)²).
// Natural tetrad (Motion4D localToCoord): e_(0) = ∂_t/(z sinh r), e_(1) = ∂_r/z, e_(2) = ∂_φ/w,
// e_(3) = w ∂_z, w = √(b/z − 1). The ray stops at z <= 0, where b/z − 1 < horizon_eps (Motion4D:
// z² >= (1 − eps) b²) and before the Killing horizon r = 0, where ∂_t becomes null
// (g_tt = −z² sinh²r = 0): k^t ∝ 1/sinh²r diverges there as at a Schwarzschild horizon, and a ray
// running into it ended in step underflow (gallery: every ray, as "error"); it stops with the break
// margin of the horizon metrics (metric.h, Metric::horizon_eps) on the vanishing factor,
// sinh²r < horizon_eps. Motion4D has no break condition at r = 0.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PetrovTypeD_BII final : public MetricCRTP<PetrovTypeD_BII> {
 public:
  PetrovTypeD_BII()
      : MetricCRTP({"Petrov_Type_D_BII_ES",
                    {"t", "r", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"b", 1.0, 0.0, 1e300, true, false, "parameter b > 0 (0 < z < b)"}},
                    {TetradKind::Default},
                    "Ehlers-Kundt static type D vacuum BII (Stephani et al., Exact Solutions (2003) 18.6; Mueller & "
                    "Grave, arXiv:0904.4184)",
                    Vec4{{0, 6, 0, 0.9}},
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
    g[0][0] = -z * z * sh * sh;
    g[1][1] = z * z;
    g[2][2] = w2;
    g[3][3] = 1.0 / w2;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double z = x[3], w2 = b_ / z - 1.0;
    const double sh = std::sinh(x[1]), ch = std::cosh(x[1]);
    d.h[0] = -z * z * sh * sh;
    d.h[1] = z * z;
    d.h[2] = w2;
    d.h[3] = 1.0 / w2;
    d.dh[1][0] = -2.0 * z * z * sh * ch;
    d.dh[3][0] = -2.0 * z * sh * sh;
    d.dh[3][1] = 2.0 * z;
    d.dh[3][2] = -b_ / (z * z);
    d.dh[3][3] = b_ / ((b_ - z) * (b_ - z));
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
    const double sr = std::sinh(x[1]);
    return z > 0.0 && b_ / z - 1.0 > horizon_eps_ && sr * sr > horizon_eps_ && std::isfinite(x[0]) &&
           std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(z);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double z = x[3], r = x[1];
    if (!(z > 0.0 && z < b_) || r == 0.0)
      throw Error("Petrov_Type_D_BII_ES: no static observer at (r, z) = (" + std::to_string(r) + ", " +
                  std::to_string(z) + ") (needs 0 < z < b, r != 0)");
    const double w = std::sqrt(b_ / z - 1.0);
    Tetrad e{};
    e[0][0] = 1.0 / (z * std::fabs(std::sinh(r)));
    e[1][1] = 1.0 / z;
    e[2][2] = 1.0 / w;
    e[3][3] = w;
    return e;
  }

 protected:
  void on_params_changed() override { b_ = p(0); }

 private:
  double b_ = 1.0;
};

std::unique_ptr<Metric> make_metric_PetrovTypeD_BII() { return std::make_unique<PetrovTypeD_BII>(); }

}  // namespace geovis
