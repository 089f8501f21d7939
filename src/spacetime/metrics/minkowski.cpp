// Minkowski spacetime in Cartesian coordinates (t, x, y, z): ds² = −dt² + dx² + dy² + dz².
#include "spacetime/metric_crtp.h"

namespace geovis {

class Minkowski final : public MetricCRTP<Minkowski> {
 public:
  Minkowski()
      : MetricCRTP(
            {"Minkowski",
             {"t", "x", "y", "z"},
             CoordType::Cartesian,
             {},
             {TetradKind::Default},
             "flat spacetime in Cartesian coordinates (Mueller & Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
             Vec4{{0, 0, 0, 0}},
             {},
             /*inertial_cartesian=*/true}) {}

  template <class T>
  void g_tmpl(const Vec4T<T>&, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(i == j ? (i == 0 ? -1.0 : 1.0) : 0.0);
  }
  void christoffel_closed(const Vec4&, Christoffel& G) const { G = Christoffel{}; }
  void accel_closed(const Vec4&, const Vec4&, Vec4& a) const { a = Vec4{{0, 0, 0, 0}}; }

  /// Escape (escape.h): a straight ray with x·k > 0 moves away from the origin for good
  /// (|x + λk|² = |x|² + 2λ x·k + λ²|k|²); no photon sphere.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    const double r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    return escapes_spherical(r, x[1] * k[1] + x[2] * k[2] + x[3] * k[3], 0.0, r_min, r, radius);
  }

  Tetrad natural_tetrad(const Vec4&, TetradKind kind) const override {
    require_tetrad_kind(kind);
    Tetrad e;
    for (int a = 0; a < 4; ++a)
      for (int mu = 0; mu < 4; ++mu) e[a][mu] = a == mu ? 1.0 : 0.0;
    return e;
  }
};

std::unique_ptr<Metric> make_metric_Minkowski() { return std::make_unique<Minkowski>(); }

}  // namespace geovis
