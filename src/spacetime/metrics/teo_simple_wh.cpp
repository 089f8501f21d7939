// Teo's rotating traversable wormhole, simplest member (Motion4D "TeoSimpleWH"); geometry,
// Christoffel symbols, tetrads and charts in teo_wormhole.h. Default tetrad = lnrf (Motion4D
// localToCoord); static: the standard static observer (Motion4D leaves it empty).
#include "spacetime/metrics/teo_wormhole.h"

namespace geovis {

class TeoSimpleWH final : public TeoWormhole<TeoSimpleWH> {
 public:
  TeoSimpleWH()
      : TeoWormhole({"TeoSimpleWH",
                     {"t", "l", "theta", "phi"},
                     CoordType::Spherical,
                     {{"b0", 1.0, 0.0, 1e300, true, false, "throat radius b0 > 0 of the rotating wormhole"}},
                     {TetradKind::Default, TetradKind::Static, TetradKind::LNRF},
                     "Teo's rotating wormhole with N = 1 and omega = b0^2/(2 r^3) (Teo, PRD 58 (1998) 024014)",
                     Vec4{{0, 5, M_PI / 2, 0}},
                     {}}) {
    on_params_changed();
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    return teo_tetrad(x, kind == TetradKind::Static);
  }
};

std::unique_ptr<Metric> make_metric_TeoSimpleWH() { return std::make_unique<TeoSimpleWH>(); }

}  // namespace geovis
