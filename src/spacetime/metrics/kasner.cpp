// Kasner spacetime in (t, x, y, z) (Motion4D "Kasner"; Kasner, Am. J. Math. 43 (1921) 217;
// Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Kasner"):
//   ds² = −dt² + t^(2p1) dx² + t^(2p2) dy² + t^(2p3) dz²,
// a homogeneous anisotropic vacuum cosmology with p1 + p2 + p3 = p1² + p2² + p3² = 1, the
// exponents from the Khalatnikov–Lifshitz parameter u (Motion4D MetricKasner::calc_parameters):
//   p1 = −u/(1 + u + u²),  p2 = (1 + u)/(1 + u + u²),  p3 = u (1 + u)/(1 + u + u²).
// u = 0 (p = (0, 1, 0)) and u = −1 (p = (1, 0, 0)) are flat (a Milne wedge times a plane).
// Christoffel symbols of the diagonal metric (diagonal_metric.h) with h_i = t^(2p_i),
// ∂_t h_i = 2 p_i t^(2p_i − 1): Γ^i_ti = p_i/t, Γ^t_ii = p_i t^(2p_i − 1).
// Natural tetrad (Motion4D localToCoord): e_(0) = ∂_t, e_(i) = t^(−p_i) ∂_i. Singular at t = 0
// (the big bang for p_i < 1): the chart is t > 0, as Motion4D's breakCondition.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class Kasner final : public MetricCRTP<Kasner> {
 public:
  Kasner()
      : MetricCRTP({"Kasner",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"u", 0.0, -1e300, 1e300, false, false,
                      "Khalatnikov-Lifshitz parameter u of the Kasner exponents (u = 0, -1: flat)"}},
                    {TetradKind::Default},
                    "Kasner anisotropic vacuum cosmology (Kasner, Am. J. Math. 43 (1921) 217; Mueller & Grave, "
                    "arXiv:0904.4184)",
                    Vec4{{1, 0, 0, 0}},
                    {{"u", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::pow;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    g[0][0] = T(-1.0);
    for (int i = 1; i < 4; ++i) g[i][i] = pow(x[0], 2.0 * p_[i]);
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double t = x[0];
    d.h[0] = -1.0;
    for (int i = 1; i < 4; ++i) {
      d.h[i] = std::pow(t, 2.0 * p_[i]);
      d.dh[0][i] = 2.0 * p_[i] * d.h[i] / t;
    }
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  GEOVIS_HOT_INLINE void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_accel(d, k, a);
  }

  /// After the initial singularity, t > 0 (Motion4D breakCondition t <= 0).
  bool is_valid(const Vec4& x) const override {
    return x[0] > 0.0 && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!(x[0] > 0.0)) throw Error("Kasner: no observer at t = " + std::to_string(x[0]) + " (the chart is t > 0)");
    Tetrad e{};
    e[0][0] = 1.0;
    for (int i = 1; i < 4; ++i) e[i][i] = std::pow(x[0], -p_[i]);
    return e;
  }

 protected:
  void on_params_changed() override {
    const double u = p(0), n = 1.0 / (1.0 + u + u * u);
    p_[1] = -u * n;
    p_[2] = (1.0 + u) * n;
    p_[3] = u * p_[2];
  }

 private:
  double p_[4] = {0.0, 0.0, 1.0, 0.0};
};

std::unique_ptr<Metric> make_metric_Kasner() { return std::make_unique<Kasner>(); }

}  // namespace geovis
