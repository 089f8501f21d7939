// Two extreme Reissner–Nordström black holes in equilibrium (Majumdar–Papapetrou), isotropic
// Cartesian coordinates (t, x, y, z) (Motion4D "ExtremeReissnerNordstromDihole"; Majumdar, Phys.
// Rev. 72 (1947) 390; Papapetrou, Proc. R. Irish Acad. A 51 (1947) 191; Chandrasekhar, Proc. R.
// Soc. A 421 (1989) 227; Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184,
// "Extreme Reissner-Nordström dihole"):
//   ds² = −dt²/U² + U² (dx² + dy² + dz²),   U = 1 + m1/r1 + m2/r2,
//   r1 = |x − (0, 0, 1)|,  r2 = |x − (0, 0, −1)|   (the holes sit at z = ±1, Motion4D calc_r).
// Christoffel symbols: diagonal metric (diagonal_metric.h) with ∂_c g_tt = 2 U_c/U³,
// ∂_c g_ii = 2 U U_c, U_c = −m1 (x_c − a1_c)/r1³ − m2 (x_c − a2_c)/r2³. Natural tetrad: static,
// e_(0) = U ∂_t, e_(i) = ∂_i/U. The horizons are the points r_i = 0 (infinitely far down a throat);
// the ray stops where the static observer's squared redshift factor −g_tt = 1/U² falls below
// horizon_eps (as for the other black holes, Metric::horizon_eps).
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class ExtremeReissnerNordstromDihole final : public MetricCRTP<ExtremeReissnerNordstromDihole> {
 public:
  ExtremeReissnerNordstromDihole()
      : MetricCRTP({"ExtremeReissnerNordstromDihole",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"m1", 1.0, 0.0, 1e300, false, false, "mass (= charge) m1 >= 0 of the hole at z = +1"},
                     {"m2", 1.0, 0.0, 1e300, false, false, "mass (= charge) m2 >= 0 of the hole at z = -1"}},
                    {TetradKind::Default, TetradKind::Static},
                    "two extreme Reissner-Nordstrom black holes, Majumdar-Papapetrou (Majumdar, Phys. Rev. 72 "
                    "(1947) 390; Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 10, 0, 0}},
                    {{"m1", 0.0}, {"m2", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::sqrt;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T rho2 = x[1] * x[1] + x[2] * x[2];
    const T U = 1.0 + m1_ / sqrt(rho2 + (x[3] - 1.0) * (x[3] - 1.0)) + m2_ / sqrt(rho2 + (x[3] + 1.0) * (x[3] + 1.0));
    g[0][0] = -1.0 / (U * U);
    g[1][1] = g[2][2] = g[3][3] = U * U;
  }

  /// U and its gradient U_c (c = 1, 2, 3).
  double potential(const Vec4& x, double dU[4]) const {
    const double rho2 = x[1] * x[1] + x[2] * x[2];
    const double z1 = x[3] - 1.0, z2 = x[3] + 1.0;
    const double r1 = std::sqrt(rho2 + z1 * z1), r2 = std::sqrt(rho2 + z2 * z2);
    const double a1 = m1_ / (r1 * r1 * r1), a2 = m2_ / (r2 * r2 * r2);
    dU[0] = 0.0;
    dU[1] = -(a1 + a2) * x[1];
    dU[2] = -(a1 + a2) * x[2];
    dU[3] = -a1 * z1 - a2 * z2;
    return 1.0 + m1_ / r1 + m2_ / r2;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    double dU[4];
    const double U = potential(x, dU);
    d.h[0] = -1.0 / (U * U);
    for (int i = 1; i < 4; ++i) d.h[i] = U * U;
    for (int c = 1; c < 4; ++c) {
      d.dh[c][0] = 2.0 * dU[c] / (U * U * U);
      for (int i = 1; i < 4; ++i) d.dh[c][i] = 2.0 * U * dU[c];
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

  /// Outside both horizons: 1/U² > horizon_eps (and away from the points r_i = 0 themselves).
  bool is_valid(const Vec4& x) const override {
    if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]))) return false;
    double dU[4];
    const double U = potential(x, dU);
    return std::isfinite(U) && 1.0 / (U * U) > horizon_eps_;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    double dU[4];
    const double U = potential(x, dU);
    if (!std::isfinite(U)) {
      std::ostringstream os;
      os << "ExtremeReissnerNordstromDihole: no static observer at a horizon point (" << x[1] << ", " << x[2] << ", "
         << x[3] << ")";
      throw Error(os.str());
    }
    Tetrad e{};
    e[0][0] = U;
    for (int i = 1; i < 4; ++i) e[i][i] = 1.0 / U;
    return e;
  }

 protected:
  void on_params_changed() override {
    m1_ = p(0);
    m2_ = p(1);
  }

 private:
  double m1_ = 1.0, m2_ = 1.0;
};

std::unique_ptr<Metric> make_metric_ExtremeReissnerNordstromDihole() {
  return std::make_unique<ExtremeReissnerNordstromDihole>();
}

}  // namespace geovis
