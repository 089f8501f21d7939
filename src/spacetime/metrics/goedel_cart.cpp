// Gödel universe in Cartesian coordinates (t, x, y, z), x = r cos φ, y = r sin φ (Motion4D
// "GoedelCart"); line element, its derivatives and the tetrad in spacetime/metrics/goedel.h
// (Gödel, Rev. Mod. Phys. 21 (1949) 447; Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184). Closed-form Christoffel symbols from the hand-written ∂g (metric_derivs.h).
// Regular everywhere, including the axis.
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/goedel.h"

namespace geovis {

class GoedelCart final : public MetricCRTP<GoedelCart> {
 public:
  GoedelCart()
      : MetricCRTP({"GoedelCart",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"a", 1.0, 0.0, 1e300, true, false, "scale a > 0 of the universe (Goedel radius r_G = 2a)"},
                     {"zeta", 0.0, -1e300, 1e300, false, false,
                      "angular velocity dphi/dt of the tetrad's observer (0: comoving with the dust)"}},
                    {TetradKind::Default},
                    "Goedel's rotating dust universe, Cartesian coordinates (Goedel, RMP 21 (1949) 447; Mueller & "
                    "Grave, arXiv:0904.4184)",
                    Vec4{{0, 0.5, 0, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    goedel::cart_metric(a_, x[1], x[2], g);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    goedel::cart_derivs(a_, x[1], x[2], d);
    christoffel_from_derivs(d, G);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    Tetrad e;
    if (!goedel::cart_tetrad(a_, zeta_, x[1], x[2], e)) {
      std::ostringstream os;
      os << "GoedelCart: no observer rotating with zeta = " << zeta_ << " at (x, y) = (" << x[1] << ", " << x[2]
         << ") (its worldline is not timelike there)";
      throw Error(os.str());
    }
    return e;
  }

 protected:
  void on_params_changed() override {
    a_ = p(0);
    zeta_ = p(1);
  }

 private:
  double a_ = 1.0, zeta_ = 0.0;
};

std::unique_ptr<Metric> make_metric_GoedelCart() { return std::make_unique<GoedelCart>(); }

}  // namespace geovis
