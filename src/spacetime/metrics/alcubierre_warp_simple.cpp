// Alcubierre warp drive with a piecewise-polynomial shape function (Motion4D
// "AlcubierreWarpSimple"), coordinates (t, x, y, z):
//   ds² = −dt² + (dx − v_s f(r_s) dt)² + dy² + dz²,  r_s = √((x − v_s t)² + y² + z²)
// (Alcubierre, Class. Quantum Grav. 11 (1994) L73, eq. (8); Müller & Grave, Catalogue of
// Spacetimes, section "Alcubierre warp drive"), i.e. g_tt = −1 + v_s² f², g_tx = −v_s f.
// Shape function (Motion4D m4dMetricAlcubierreSimple::calcF): with R1 = R − ΔR/2, R2 = R + ΔR/2,
//   f = 1 for r_s <= R1,  f = (1 − w²)² with w = (r_s − R1)/ΔR for R1 < r_s < R2,  f = 0 beyond;
// f is C¹ (f' vanishes at R1 and R2), so the Christoffel symbols are continuous.
// Line element, Christoffel symbols, tetrads and Motion4D's k^t rescaling:
// spacetime/metrics/alcubierre.h.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/alcubierre.h"

namespace geovis {

class AlcubierreWarpSimple final : public MetricCRTP<AlcubierreWarpSimple> {
 public:
  AlcubierreWarpSimple()
      : MetricCRTP(
            {"AlcubierreWarpSimple",
             {"t", "x", "y", "z"},
             CoordType::Cartesian,
             {{"dr", 0.1, 0.0, 1e300, true, false,
               "thickness dR > 0 of the bubble wall (f falls from 1 to 0 over R +- dR/2)"},
              {"r", 1.0, 0.0, 1e300, true, false, "radius R > 0 of the warp bubble"},
              {"vs", 1.0, -1e300, 1e300, false, false, "velocity v_s of the warp bubble along x (may exceed 1)"}},
             {TetradKind::Default, TetradKind::Comoving, TetradKind::Static},
             "Alcubierre warp drive with polynomial wall (Alcubierre, CQG 11 (1994) L73)",
             Vec4{{0, -3, 0, 0}},
             {{"vs", 0.0}}}) {
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
    const T X = x[1] - vs_ * x[0];
    alcubierre::metric(vs_ * shape<T>(X * X + x[2] * x[2] + x[3] * x[3]), g);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    const double X = x[1] - vs_ * x[0];
    const double rs2 = X * X + x[2] * x[2] + x[3] * x[3];
    const double rs = std::sqrt(rs2);
    // df/dr_s (non-zero only inside the wall), then f_μ = f' ∂_μ r_s.
    double dfdr = 0.0;
    if (rs > R1_ && rs < R2_) {
      const double w = (rs - R1_) / dR_;
      dfdr = -4.0 * (1.0 - w * w) * w / dR_;
    }
    if (dfdr == 0.0) {
      G = Christoffel{};  // f constant here: flat (possibly moving) frame, all Γ vanish
      return;
    }
    alcubierre::christoffel(vs_, shape<double>(rs2), dfdr * X / rs, dfdr * x[2] / rs, dfdr * x[3] / rs, G);
  }

  /// Motion4D's resize after every accepted step of a lightlike geodesic (alcubierre.h; called by
  /// integrators.h MetricSystem::rescale).
  void rescale_null_direction(double* k) const { alcubierre::rescale_direction(k); }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double X = x[1] - vs_ * x[0];
    const double vf = vs_ * shape<double>(X * X + x[2] * x[2] + x[3] * x[3]);
    Tetrad e;
    if (!alcubierre::tetrad(vf, kind == TetradKind::Comoving, e)) {
      std::ostringstream os;
      os << "AlcubierreWarpSimple: no static observer at (" << x[0] << ", " << x[1] << ", " << x[2] << ", " << x[3]
         << "): v_s f = " << vf << " (|v_s f| >= 1, d/dt is not timelike here); use the comoving frame";
      throw Error(os.str());
    }
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
