// De Sitter universe in conformally flat coordinates (T, x, y, z) (Motion4D
// "DeSitterUnivConformal"; Hawking & Ellis, The Large Scale Structure of Space-Time (1973) §5.2;
// Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "de Sitter: conformally flat"):
//   ds² = (−dT² + dx² + dy² + dz²) / (H² T²),   T < 0,
// the flat slicing of DeSitterUniv with conformal time T = −e^(−H t)/H. Motion4D's parameter p
// switches the conformal factor off for p < 0 (then the metric is Minkowski, a device to compare
// the two: light rays are the same straight lines, only the affine parameter differs).
// Christoffel symbols (diagonal_metric.h) with c = 1/(H² T²), ∂_T c = −2c/T:
//   Γ^T_TT = Γ^T_ii = Γ^i_Ti = −1/T (all zero for p < 0).
// Natural tetrad (Motion4D localToCoord): e_(a) = −H T ∂_a (= ∂_a for p < 0). The chart ends at
// T = 0 (future infinity); Motion4D's break condition T + 1e-12 >= 0.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class DeSitterUnivConformal final : public MetricCRTP<DeSitterUnivConformal> {
 public:
  DeSitterUnivConformal()
      : MetricCRTP({"DeSitterUnivConformal",
                    {"T", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"hubble", 0.1, 0.0, 1e300, true, false, "Hubble constant H > 0"},
                     {"p", 1.0, -1e300, 1e300, false, false,
                      "p < 0 switches the conformal factor off (Minkowski, for comparison)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "de Sitter universe in conformally flat coordinates (Hawking & Ellis (1973) 5.2; Mueller & "
                    "Grave, arXiv:0904.4184)",
                    Vec4{{-1, 0, 0, 0}},
                    {{"p", -1.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T c = conformal_ ? 1.0 / (H_ * H_ * x[0] * x[0]) : T(1.0);
    g[0][0] = -c;
    g[1][1] = g[2][2] = g[3][3] = c;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double T = x[0];
    const double c = conformal_ ? 1.0 / (H_ * H_ * T * T) : 1.0, dc = conformal_ ? -2.0 * c / T : 0.0;
    d.h[0] = -c;
    d.dh[0][0] = -dc;
    for (int i = 1; i < 4; ++i) {
      d.h[i] = c;
      d.dh[0][i] = dc;
    }
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

  /// Before future infinity: T < −1e-12 (Motion4D); any T for p < 0.
  bool is_valid(const Vec4& x) const override {
    return (!conformal_ || x[0] + 1e-12 < 0.0) && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) &&
           std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x))
      throw Error("DeSitterUnivConformal: no observer at T = " + std::to_string(x[0]) + " (needs T < 0)");
    const double f = conformal_ ? -H_ * x[0] : 1.0;
    Tetrad e{};
    for (int a = 0; a < 4; ++a) e[a][a] = f;
    return e;
  }

 protected:
  void on_params_changed() override {
    H_ = p(0);
    conformal_ = !(p(1) < 0.0);
  }

 private:
  double H_ = 0.1;
  bool conformal_ = true;
};

std::unique_ptr<Metric> make_metric_DeSitterUnivConformal() { return std::make_unique<DeSitterUnivConformal>(); }

}  // namespace geovis
