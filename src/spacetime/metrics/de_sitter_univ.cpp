// De Sitter universe in flat slicing (comoving Cartesian coordinates (t, x, y, z)):
//   ds² = −dt² + e^{2Ht} (dx² + dy² + dz²)
// (Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, section "de Sitter spacetime";
// Motion4D m4dMetricDeSitterUniv). Non-zero Christoffel symbols: Γ^t_ii = H e^{2Ht}, Γ^i_ti = H.
// A radial light ray has comoving distance χ(t) = χ0 ± (e^{−H t0} − e^{−H t})/H.
// Natural tetrad (default = static, Motion4D localToCoord): e_(0) = ∂_t, e_(i) = e^{−Ht} ∂_i
// (the comoving observers).
#include <cmath>

#include "spacetime/metric_crtp.h"

namespace geovis {

class DeSitterUniv final : public MetricCRTP<DeSitterUniv> {
 public:
  DeSitterUniv()
      : MetricCRTP({"DeSitterUniv",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"hubble", 0.1, -1e300, 1e300, false, false,
                      "Hubble constant H (scale factor exp(H t); H < 0 is the contracting patch)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "de Sitter universe, flat slicing (Mueller & Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 0, 0, 0}},
                    {{"hubble", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::exp;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T a2 = exp(2.0 * H_ * x[0]);
    g[0][0] = T(-1.0);
    g[1][1] = a2;
    g[2][2] = a2;
    g[3][3] = a2;
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double t_ii = H_ * std::exp(2.0 * H_ * x[0]);
    for (int i = 1; i < 4; ++i) {
      G.G[0][i][i] = t_ii;
      G.G[i][0][i] = G.G[i][i][0] = H_;
    }
  }

  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    const double a2 = std::exp(2.0 * H_ * x[0]);
    a[0] = -H_ * a2 * (k[1] * k[1] + k[2] * k[2] + k[3] * k[3]);
    for (int i = 1; i < 4; ++i) a[i] = -2.0 * H_ * k[0] * k[i];
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double ia = std::exp(-H_ * x[0]);
    Tetrad e{};
    e[0][0] = 1.0;
    for (int i = 1; i < 4; ++i) e[i][i] = ia;
    return e;
  }

 protected:
  void on_params_changed() override { H_ = p(0); }

 private:
  double H_ = 0.1;
};

std::unique_ptr<Metric> make_metric_DeSitterUniv() { return std::make_unique<DeSitterUniv>(); }

}  // namespace geovis
