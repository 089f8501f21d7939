// "Rotating dihole" of Motion4D (m4dMetricRotDihole), coordinates (t, x, y, z):
//   ds² = −dt²/U² + U² (dx² + dy² + dz²),  U = 1 + M1/r1 + M2/r2,
//   r1 = √(x² + (y + sin ωt)² + (z − cos ωt)²),  r2 = √(x² + (y − sin ωt)² + (z + cos ωt)²).
// For ω = 0 this is the Majumdar-Papapetrou extreme Reissner-Nordström dihole with the holes at
// z = ±1 (Majumdar, Phys. Rev. 72 (1947) 390; Papapetrou, Proc. R. Irish Acad. A51 (1947) 191;
// Catalogue of Spacetimes, "Extreme Reissner-Nordström dihole"). For ω != 0 Motion4D lets the two
// holes revolve on the unit circle in the y-z plane; that is a kinematic toy model, not a solution
// of the Einstein-Maxwell equations.
//
// Christoffel symbols (derived from the line element; i, j spatial, i != j, U_μ = ∂_μ U):
//   Γ^t_tt = −U_t/U,  Γ^t_ti = −U_i/U,  Γ^t_ii = U³ U_t,  Γ^i_tt = −U_i/U⁵,  Γ^i_ti = U_t/U,
//   Γ^i_ii = U_i/U,  Γ^i_ij = U_j/U,  Γ^i_jj = −U_i/U   (= Motion4D calculateChristoffels).
// Natural tetrad (default only): e_(0) = U ∂_t, e_(i) = ∂_i/U.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"

namespace geovis {

class RotDihole final : public MetricCRTP<RotDihole> {
 public:
  RotDihole()
      : MetricCRTP(
            {"RotDihole",
             {"t", "x", "y", "z"},
             CoordType::Cartesian,
             {{"mass1", 1.0, 0.0, 1e300, false, false, "mass (= charge) M1 >= 0 of hole 1, at (0, -sin wt, cos wt)"},
              {"mass2", 1.0, 0.0, 1e300, false, false, "mass (= charge) M2 >= 0 of hole 2, at (0, sin wt, -cos wt)"},
              {"omega", 0.0, -1e300, 1e300, false, false,
               "angular frequency w of the holes' revolution about the x axis"}},
             {TetradKind::Default},
             "extreme Reissner-Nordstrom dihole, optionally revolving (Motion4D RotDihole; Majumdar-Papapetrou, "
             "Mueller & Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
             Vec4{{0, 3, 0, 0}},
             {{"mass1", 0.0}, {"mass2", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::cos;
    using std::sin;
    using std::sqrt;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T s = sin(omega_ * x[0]), c = cos(omega_ * x[0]);
    const T y1 = x[2] + s, z1 = x[3] - c, y2 = x[2] - s, z2 = x[3] + c;
    const T r1 = sqrt(x[1] * x[1] + y1 * y1 + z1 * z1);
    const T r2 = sqrt(x[1] * x[1] + y2 * y2 + z2 * z2);
    const T U = 1.0 + m1_ / r1 + m2_ / r2;
    const T U2 = U * U;
    g[0][0] = -1.0 / U2;
    g[1][1] = U2;
    g[2][2] = U2;
    g[3][3] = U2;
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double s = std::sin(omega_ * x[0]), c = std::cos(omega_ * x[0]);
    const double y1 = x[2] + s, z1 = x[3] - c, y2 = x[2] - s, z2 = x[3] + c;
    const double r1 = std::sqrt(x[1] * x[1] + y1 * y1 + z1 * z1);
    const double r2 = std::sqrt(x[1] * x[1] + y2 * y2 + z2 * z2);
    const double q1 = m1_ / (r1 * r1 * r1), q2 = m2_ / (r2 * r2 * r2);
    const double U = 1.0 + m1_ / r1 + m2_ / r2;
    // ∂_μ U = −Σ M_k (∂_μ r_k²)/(2 r_k³); ∂_t r1² = 2ω(y1 c + z1 s), ∂_t r2² = −2ω(y2 c + z2 s).
    const double dU[4] = {-q1 * omega_ * (y1 * c + z1 * s) + q2 * omega_ * (y2 * c + z2 * s), -(q1 + q2) * x[1],
                          -(q1 * y1 + q2 * y2), -(q1 * z1 + q2 * z2)};
    const double iU = 1.0 / U, U2 = U * U;
    G.G[0][0][0] = -dU[0] * iU;
    for (int i = 1; i < 4; ++i) {
      G.G[0][0][i] = G.G[0][i][0] = -dU[i] * iU;
      G.G[0][i][i] = U2 * U * dU[0];
      G.G[i][0][0] = -dU[i] * iU / (U2 * U2);
      G.G[i][0][i] = G.G[i][i][0] = dU[0] * iU;
      for (int j = 1; j < 4; ++j) {
        if (j == i) {
          G.G[i][i][i] = dU[i] * iU;
        } else {
          G.G[i][i][j] = G.G[i][j][i] = dU[j] * iU;
          G.G[i][j][j] = -dU[i] * iU;
        }
      }
    }
  }

  /// Stops at the holes (r_k → 0, the degenerate horizons in these coordinates) with a relative
  /// margin 1e-6 M_k.
  bool is_valid(const Vec4& x) const override {
    for (int i = 0; i < 4; ++i)
      if (!std::isfinite(x[i])) return false;
    const double s = std::sin(omega_ * x[0]), c = std::cos(omega_ * x[0]);
    const double y1 = x[2] + s, z1 = x[3] - c, y2 = x[2] - s, z2 = x[3] + c;
    const double x2 = x[1] * x[1];
    if (m1_ > 0 && !(x2 + y1 * y1 + z1 * z1 > r_break1_ * r_break1_)) return false;
    if (m2_ > 0 && !(x2 + y2 * y2 + z2 * z2 > r_break2_ * r_break2_)) return false;
    return true;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x)) {
      std::ostringstream os;
      os << "RotDihole: no observer at (" << x[0] << ", " << x[1] << ", " << x[2] << ", " << x[3]
         << "): on a black hole (r1 or r2 = 0)";
      throw Error(os.str());
    }
    const double s = std::sin(omega_ * x[0]), c = std::cos(omega_ * x[0]);
    const double y1 = x[2] + s, z1 = x[3] - c, y2 = x[2] - s, z2 = x[3] + c;
    const double U =
        1.0 + m1_ / std::sqrt(x[1] * x[1] + y1 * y1 + z1 * z1) + m2_ / std::sqrt(x[1] * x[1] + y2 * y2 + z2 * z2);
    Tetrad e{};
    e[0][0] = U;
    for (int i = 1; i < 4; ++i) e[i][i] = 1.0 / U;
    return e;
  }

 protected:
  void on_params_changed() override {
    m1_ = p(0);
    m2_ = p(1);
    omega_ = p(2);
    r_break1_ = 1e-6 * m1_;
    r_break2_ = 1e-6 * m2_;
  }

 private:
  double m1_ = 1, m2_ = 1, omega_ = 0, r_break1_ = 0, r_break2_ = 0;
};

std::unique_ptr<Metric> make_metric_RotDihole() { return std::make_unique<RotDihole>(); }

}  // namespace geovis
