// Gödel universe in cylindrical coordinates (t, r, φ, z) (Motion4D "Goedel"); the line element,
// Christoffel symbols and the rotating-observer tetrad are in spacetime/metrics/goedel.h (Gödel,
// Rev. Mod. Phys. 21 (1949) 447; Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184).
// No horizon and no singularity: the chart is valid off the axis r = 0 (where the polar
// coordinates degenerate).
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/goedel.h"

namespace geovis {

class Goedel final : public MetricCRTP<Goedel> {
 public:
  Goedel()
      : MetricCRTP({"Goedel",
                    {"t", "r", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"a", 1.0, 0.0, 1e300, true, false, "scale a > 0 of the universe (Goedel radius r_G = 2a)"},
                     {"zeta", 0.0, -1e300, 1e300, false, false,
                      "angular velocity dphi/dt of the tetrad's observer (0: comoving with the dust)"}},
                    {TetradKind::Default},
                    "Goedel's rotating dust universe (Goedel, RMP 21 (1949) 447; Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 0.5, 0, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    goedel::cylinder_metric(a_, x[1], g);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const { goedel::cylinder_christoffel(a_, x[1], G); }

  /// Off the axis (r > 0); the spacetime itself is regular everywhere.
  bool is_valid(const Vec4& x) const override {
    return x[1] > 0.0 && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    Tetrad e;
    if (!goedel::cylinder_tetrad(a_, zeta_, x[1], e)) {
      std::ostringstream os;
      os << "Goedel: no observer rotating with zeta = " << zeta_ << " at r = " << x[1]
         << " (needs r > 0 and a timelike worldline; beyond the Goedel radius 2a = " << 2 * a_
         << " choose a smaller |zeta|)";
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

std::unique_ptr<Metric> make_metric_Goedel() { return std::make_unique<Goedel>(); }

}  // namespace geovis
