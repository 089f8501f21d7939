// Ehlers–Kundt class AIII of the static vacuum Petrov type D metrics (Motion4D
// "Petrov_Type_D_AIII_ES"; Ehlers & Kundt in Gravitation: an Introduction to Current Research, ed.
// Witten (1962); Stephani et al., Exact Solutions of Einstein's Field Equations (2003) §18.6;
// Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Petrov type D – Levi-Civita
// spacetimes"), in (t, r, φ, z), z > 0:
//   ds² = −dt²/z + z dz² + z² (dr² + r² dφ²),
// the member of the class A family ds² = −(b/z − ε) dt² + dz²/(b/z − ε) + z² dΣ_ε² with flat
// 2-surfaces (ε = 0, b = 1). Christoffel symbols: diagonal (diagonal_metric.h) with
// h = (−1/z, z², z² r², z): ∂_z h = (1/z², 2z, 2z r², 1), ∂_r g_φφ = 2z² r.
// Natural tetrad (Motion4D localToCoord): e_(0) = √z ∂_t, e_(1) = ∂_r/z, e_(2) = ∂_φ/(z r),
// e_(3) = ∂_z/√z. The ray stops near the singularity, z² <= 1e-6 (Motion4D breakCondition), and
// on the axis r = 0.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PetrovTypeD_AIII final : public MetricCRTP<PetrovTypeD_AIII> {
 public:
  PetrovTypeD_AIII()
      : MetricCRTP({"Petrov_Type_D_AIII_ES",
                    {"t", "r", "phi", "z"},
                    CoordType::Cylindrical,
                    {},
                    {TetradKind::Default},
                    "Ehlers-Kundt static type D vacuum AIII (Stephani et al., Exact Solutions (2003) 18.6; Mueller & "
                    "Grave, arXiv:0904.4184)",
                    Vec4{{0, 1, 0, 1}},
                    {}}) {}

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T& z = x[3];
    g[0][0] = -1.0 / z;
    g[1][1] = z * z;
    g[2][2] = z * z * r * r;
    g[3][3] = z;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double r = x[1], z = x[3];
    d.h[0] = -1.0 / z;
    d.h[1] = z * z;
    d.h[2] = z * z * r * r;
    d.h[3] = z;
    d.dh[3][0] = 1.0 / (z * z);
    d.dh[3][1] = 2.0 * z;
    d.dh[3][2] = 2.0 * z * r * r;
    d.dh[3][3] = 1.0;
    d.dh[1][2] = 2.0 * z * z * r;
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
    return x[3] > 0.0 && x[3] * x[3] > 1e-6 && x[1] != 0.0 && std::isfinite(x[0]) && std::isfinite(x[1]) &&
           std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1], z = x[3];
    if (!(z > 0.0) || r == 0.0)
      throw Error("Petrov_Type_D_AIII_ES: no static observer at (r, z) = (" + std::to_string(r) + ", " +
                  std::to_string(z) + ") (needs z > 0, r != 0)");
    const double sz = std::sqrt(z);
    Tetrad e{};
    e[0][0] = sz;
    e[1][1] = 1.0 / z;
    e[2][2] = 1.0 / (z * std::fabs(r));
    e[3][3] = 1.0 / sz;
    return e;
  }
};

std::unique_ptr<Metric> make_metric_PetrovTypeD_AIII() { return std::make_unique<PetrovTypeD_AIII>(); }

}  // namespace geovis
