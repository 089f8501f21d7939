// Ehlers–Kundt class BIII of the static vacuum Petrov type D metrics (Motion4D
// "Petrov_Type_D_BIII_ES", whose getMetricName() adds a trailing underscore; Stephani et al., Exact
// Solutions of Einstein's Field Equations (2003) §18.6; Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184, "Petrov type D – Levi-Civita spacetimes"), in (t, r, φ, z), z > 0:
//   ds² = z² (−r² dt² + dr²) + dφ²/z + z dz²,
// class AIII with the roles of t and φ exchanged (the 2-surfaces z = const are Rindler wedges).
// Christoffel symbols: diagonal (diagonal_metric.h) with h = (−z² r², z², 1/z, z):
// ∂_r g_tt = −2z² r, ∂_z h = (−2z r², 2z, −1/z², 1).
// Natural tetrad (Motion4D localToCoord): e_(0) = ∂_t/(z r), e_(1) = ∂_r/z, e_(2) = √z ∂_φ,
// e_(3) = ∂_z/√z. The ray stops near the singularity, z² <= 1e-6 (Motion4D breakCondition), and
// before the Rindler horizon r = 0, where ∂_t becomes null (g_tt = −z² r² = 0): k^t ∝ 1/r²
// diverges there as at a Schwarzschild horizon, and a ray running into it ended in step underflow
// (gallery: 93% of the rays, as "error"); it stops with the break margin of the horizon metrics
// (metric.h, Metric::horizon_eps) on the vanishing factor, r² < horizon_eps (Motion4D: no break
// condition at r = 0).
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PetrovTypeD_BIII final : public MetricCRTP<PetrovTypeD_BIII> {
 public:
  PetrovTypeD_BIII()
      : MetricCRTP({"Petrov_Type_D_BIII_ES",
                    {"t", "r", "phi", "z"},
                    CoordType::Cylindrical,
                    {},
                    {TetradKind::Default},
                    "Ehlers-Kundt static type D vacuum BIII (Stephani et al., Exact Solutions (2003) 18.6; Mueller & "
                    "Grave, arXiv:0904.4184)",
                    Vec4{{0, 6, 0, 0.9}},
                    {}}) {}

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T& z = x[3];
    g[0][0] = -z * z * r * r;
    g[1][1] = z * z;
    g[2][2] = 1.0 / z;
    g[3][3] = z;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double r = x[1], z = x[3];
    d.h[0] = -z * z * r * r;
    d.h[1] = z * z;
    d.h[2] = 1.0 / z;
    d.h[3] = z;
    d.dh[1][0] = -2.0 * z * z * r;
    d.dh[3][0] = -2.0 * z * r * r;
    d.dh[3][1] = 2.0 * z;
    d.dh[3][2] = -1.0 / (z * z);
    d.dh[3][3] = 1.0;
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
    return x[3] > 0.0 && x[3] * x[3] > 1e-6 && x[1] * x[1] > horizon_eps_ && std::isfinite(x[0]) &&
           std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1], z = x[3];
    if (!(z > 0.0) || r == 0.0)
      throw Error("Petrov_Type_D_BIII_ES: no static observer at (r, z) = (" + std::to_string(r) + ", " +
                  std::to_string(z) + ") (needs z > 0, r != 0)");
    const double sz = std::sqrt(z);
    Tetrad e{};
    e[0][0] = 1.0 / (z * std::fabs(r));
    e[1][1] = 1.0 / z;
    e[2][2] = sz;
    e[3][3] = 1.0 / sz;
    return e;
  }
};

std::unique_ptr<Metric> make_metric_PetrovTypeD_BIII() { return std::make_unique<PetrovTypeD_BIII>(); }

}  // namespace geovis
