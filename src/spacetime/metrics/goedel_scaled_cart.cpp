// Gödel universe in scaled Cartesian coordinates (T, X, Y, Z) = (t, x, y, z)/r_G (Motion4D
// "GoedelScaledCart"): r_G² times the Cartesian Gödel metric with a = 1/2
// (spacetime/metrics/goedel.h; the constant factor leaves the Christoffel symbols unchanged and
// divides the tetrad vectors by r_G). Gödel radius X² + Y² = 1.
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/goedel.h"

namespace geovis {

class GoedelScaledCart final : public MetricCRTP<GoedelScaledCart> {
 public:
  GoedelScaledCart()
      : MetricCRTP({"GoedelScaledCart",
                    {"T", "X", "Y", "Z"},
                    CoordType::Cartesian,
                    {{"rg", 1.0, 0.0, 1e300, true, false, "Goedel radius r_G > 0 (the unit of T, X, Y and Z)"},
                     {"zeta", 0.0, -1e300, 1e300, false, false,
                      "angular velocity dphi/dT of the tetrad's observer (0: comoving with the dust)"}},
                    {TetradKind::Default},
                    "Goedel universe, Cartesian coordinates scaled by the Goedel radius (Goedel, RMP 21 (1949) "
                    "447; Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 0.25, 0, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    goedel::cart_metric(0.5, x[1], x[2], g);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = rg2_ * g[i][j];
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    goedel::cart_derivs(0.5, x[1], x[2], d);
    christoffel_from_derivs(d, G);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    Tetrad e;
    if (!goedel::cart_tetrad(0.5, zeta_, x[1], x[2], e)) {
      std::ostringstream os;
      os << "GoedelScaledCart: no observer rotating with zeta = " << zeta_ << " at (X, Y) = (" << x[1] << ", " << x[2]
         << ") (its worldline is not timelike there)";
      throw Error(os.str());
    }
    for (int a = 0; a < 4; ++a)
      for (int mu = 0; mu < 4; ++mu) e[a][mu] /= rg_;
    return e;
  }

 protected:
  void on_params_changed() override {
    rg_ = p(0);
    rg2_ = rg_ * rg_;
    zeta_ = p(1);
  }

 private:
  double rg_ = 1.0, rg2_ = 1.0, zeta_ = 0.0;
};

std::unique_ptr<Metric> make_metric_GoedelScaledCart() { return std::make_unique<GoedelScaledCart>(); }

}  // namespace geovis
