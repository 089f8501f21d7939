// Alcubierre warp drive with a piecewise-polynomial shape function (Motion4D
// "AlcubierreWarpSimple"), coordinates (t, x, y, z):
//   ds² = −dt² + (dx − v_s f(r_s) dt)² + dy² + dz²,  r_s = √((x − v_s t)² + y² + z²)
// (Alcubierre, Class. Quantum Grav. 11 (1994) L73, eq. (8); Müller & Grave, Catalogue of
// Spacetimes, section "Alcubierre warp drive"), i.e. g_tt = −1 + v_s² f², g_tx = −v_s f.
// Shape function (Motion4D m4dMetricAlcubierreSimple::calcF): with R1 = R − ΔR/2, R2 = R + ΔR/2,
//   f = 1 for r_s <= R1,  f = (1 − w²)² with w = (r_s − R1)/ΔR for R1 < r_s < R2,  f = 0 beyond;
// f is C¹ (f' vanishes at R1 and R2), so the Christoffel symbols are continuous.
//
// Christoffel symbols (derived from the line element; j ∈ {y, z}, f_μ = ∂_μ f, f_t = −v_s f_x):
//   Γ^t_tt = v³f²f_x,  Γ^t_tx = −v²f f_x,  Γ^t_tj = −½v²f f_j,  Γ^t_xx = v f_x,  Γ^t_xj = ½v f_j,
//   Γ^x_tt = −v f_t − v²f f_x + v⁴f³f_x,  Γ^x_tx = −v³f²f_x,  Γ^x_tj = −½v f_j (1 + v²f²),
//   Γ^x_xx = v²f f_x,  Γ^x_xj = ½v²f f_j,  Γ^j_tt = −v²f f_j,  Γ^j_tx = ½v f_j
// (v = v_s; these agree with the Catalogue and with Motion4D's calculateChristoffels).
// Natural tetrads (Motion4D localToCoord):
//   comoving (Eulerian observer): e_(0) = ∂_t + v_s f ∂_x, e_(1) = ∂_x, e_(2) = ∂_y, e_(3) = ∂_z;
//   default = static: e_(0) = ∂_t/w, e_(1) = −(v_s f/w) ∂_t + w ∂_x, w = √(1 − v_s² f²)
//   (only where v_s |f| < 1).
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"

namespace geovis {

class AlcubierreWarpSimple final : public MetricCRTP<AlcubierreWarpSimple> {
 public:
  AlcubierreWarpSimple()
      : MetricCRTP({"AlcubierreWarpSimple",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"dr", 0.1, 0.0, 1e300, true, false, "thickness dR > 0 of the bubble wall (f falls from 1 to 0 over R +- dR/2)"},
                     {"r", 1.0, 0.0, 1e300, true, false, "radius R > 0 of the warp bubble"},
                     {"vs", 1.0, -1e300, 1e300, false, false, "velocity v_s of the warp bubble along x (may exceed 1)"}},
                    {TetradKind::Default, TetradKind::Comoving, TetradKind::Static},
                    "Alcubierre warp drive with polynomial wall (Alcubierre, CQG 11 (1994) L73)"}) {
    on_params_changed();
  }

  /// f(r_s) from r_s²; generic in the scalar (compares values only).
  template <class T>
  T shape(const T& rs2) const {
    using std::sqrt;
    if (rs2 <= R1_ * R1_ && R1_ > 0.0) return T(1.0);
    const T rs = sqrt(rs2);
    if (rs <= R1_) return T(1.0);
    if (rs < R2_) {
      const T w = (rs - R1_) / dR_;
      const T y = 1.0 - w * w;
      return y * y;
    }
    return T(0.0);
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T X = x[1] - vs_ * x[0];
    const T f = shape<T>(X * X + x[2] * x[2] + x[3] * x[3]);
    const T vf = vs_ * f;
    g[0][0] = -1.0 + vf * vf;
    g[0][1] = g[1][0] = -vf;
    g[1][1] = T(1.0);
    g[2][2] = T(1.0);
    g[3][3] = T(1.0);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double X = x[1] - vs_ * x[0];
    const double rs2 = X * X + x[2] * x[2] + x[3] * x[3];
    const double rs = std::sqrt(rs2);
    const double f = shape<double>(rs2);
    // df/dr_s (non-zero only inside the wall), then f_μ = f' ∂_μ r_s.
    double dfdr = 0.0;
    if (rs > R1_ && rs < R2_) {
      const double w = (rs - R1_) / dR_;
      dfdr = -4.0 * (1.0 - w * w) * w / dR_;
    }
    if (dfdr == 0.0) return;  // f constant here: flat (possibly moving) frame, all Γ vanish
    const double fx = dfdr * X / rs, fy = dfdr * x[2] / rs, fz = dfdr * x[3] / rs;
    const double ft = -vs_ * fx;
    const double v = vs_, v2 = v * v, f2 = f * f;
    auto set = [&G](int mu, int a, int b, double val) { G.G[mu][a][b] = G.G[mu][b][a] = val; };
    set(0, 0, 0, v2 * v * f2 * fx);
    set(0, 0, 1, -v2 * f * fx);
    set(0, 0, 2, -0.5 * v2 * f * fy);
    set(0, 0, 3, -0.5 * v2 * f * fz);
    set(0, 1, 1, v * fx);
    set(0, 1, 2, 0.5 * v * fy);
    set(0, 1, 3, 0.5 * v * fz);
    set(1, 0, 0, -v * ft - v2 * f * fx + v2 * v2 * f2 * f * fx);
    set(1, 0, 1, -v2 * v * f2 * fx);
    set(1, 0, 2, -0.5 * v * fy * (1.0 + v2 * f2));
    set(1, 0, 3, -0.5 * v * fz * (1.0 + v2 * f2));
    set(1, 1, 1, v2 * f * fx);
    set(1, 1, 2, 0.5 * v2 * f * fy);
    set(1, 1, 3, 0.5 * v2 * f * fz);
    set(2, 0, 0, -v2 * f * fy);
    set(2, 0, 1, 0.5 * v * fy);
    set(3, 0, 0, -v2 * f * fz);
    set(3, 0, 1, 0.5 * v * fz);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double X = x[1] - vs_ * x[0];
    const double vf = vs_ * shape<double>(X * X + x[2] * x[2] + x[3] * x[3]);
    Tetrad e{};
    e[2][2] = 1.0;
    e[3][3] = 1.0;
    if (kind == TetradKind::Comoving) {
      e[0][0] = 1.0;
      e[0][1] = vf;
      e[1][1] = 1.0;
      return e;
    }
    // Default and static.
    const double w2 = 1.0 - vf * vf;
    if (!(w2 > 0.0)) {
      std::ostringstream os;
      os << "AlcubierreWarpSimple: no static observer at (" << x[0] << ", " << x[1] << ", " << x[2] << ", "
         << x[3] << "): v_s f = " << vf << " (|v_s f| >= 1, d/dt is not timelike here); use the comoving frame";
      throw Error(os.str());
    }
    const double w = std::sqrt(w2);
    e[0][0] = 1.0 / w;
    e[1][0] = -vf / w;
    e[1][1] = w;
    return e;
  }

 protected:
  void on_params_changed() override {
    dR_ = p(0);
    vs_ = p(2);
    R1_ = p(1) - 0.5 * dR_;
    R2_ = p(1) + 0.5 * dR_;
  }

 private:
  double dR_ = 0.1, vs_ = 1.0, R1_ = 0.95, R2_ = 1.05;
};

std::unique_ptr<Metric> make_metric_AlcubierreWarpSimple() { return std::make_unique<AlcubierreWarpSimple>(); }

}  // namespace geovis
