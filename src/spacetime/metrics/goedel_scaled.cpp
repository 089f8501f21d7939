// Gödel universe in scaled cylindrical coordinates (T, R, φ, Z) = (t, r, φ, z)/r_G (Motion4D
// "GoedelScaled"): ds² = r_G² [−dT² − 2√2 R² dT dφ + dR²/(1 + R²) + R² (1 − R²) dφ² + dZ²], i.e.
// r_G² times the Gödel metric with a = 1/2 (spacetime/metrics/goedel.h, which derives the
// Christoffel symbols — unchanged by the constant factor — and the tetrad, divided by r_G here).
// The Gödel radius is R = 1 for every r_G, so the shape of the geodesics does not depend on r_G.
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/goedel.h"

namespace geovis {

class GoedelScaled final : public MetricCRTP<GoedelScaled> {
 public:
  GoedelScaled()
      : MetricCRTP({"GoedelScaled",
                    {"T", "R", "phi", "Z"},
                    CoordType::Cylindrical,
                    {{"rg", 1.0, 0.0, 1e300, true, false, "Goedel radius r_G > 0 (the unit of T, R and Z)"},
                     {"zeta", 0.0, -1e300, 1e300, false, false,
                      "angular velocity dphi/dT of the tetrad's observer (0: comoving with the dust)"}},
                    {TetradKind::Default},
                    "Goedel universe in coordinates scaled by the Goedel radius (Goedel, RMP 21 (1949) 447; "
                    "Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 0.25, 0, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    goedel::cylinder_metric(0.5, x[1], g);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = rg2_ * g[i][j];
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const { goedel::cylinder_christoffel(0.5, x[1], G); }

  /// Off the axis (R > 0); the spacetime itself is regular everywhere.
  bool is_valid(const Vec4& x) const override {
    return x[1] > 0.0 && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    Tetrad e;
    if (!goedel::cylinder_tetrad(0.5, zeta_, x[1], e)) {
      std::ostringstream os;
      os << "GoedelScaled: no observer rotating with zeta = " << zeta_ << " at R = " << x[1]
         << " (needs R > 0 and a timelike worldline)";
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

std::unique_ptr<Metric> make_metric_GoedelScaled() { return std::make_unique<GoedelScaled>(); }

}  // namespace geovis
