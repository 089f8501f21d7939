// Teo's rotating traversable wormhole in Teo's general form (Motion4D "TeoWHl": the functions N(l),
// K(l), r(l), ω(l) of Teo, Phys. Rev. D 58 (1998) 024014, eq. (1), with Motion4D's choices N = K = 1,
// r = √(l² + b0²), ω = b0²/(2 r³)) — the same spacetime as TeoSimpleWH; geometry, Christoffel
// symbols, tetrads and charts in teo_wormhole.h. Differences from TeoSimpleWH, as Motion4D: the
// initial position l = 10 and the default tetrad, which is the static one (Motion4D localToCoord
// uses the lnrf frame only when asked for it).
#include "spacetime/metrics/teo_wormhole.h"

namespace geovis {

class TeoWHl final : public TeoWormhole<TeoWHl> {
 public:
  TeoWHl()
      : TeoWormhole({"TeoWHl",
                     {"t", "l", "theta", "phi"},
                     CoordType::Spherical,
                     {{"b0", 1.0, 0.0, 1e300, true, false, "throat radius b0 > 0 of the rotating wormhole"}},
                     {TetradKind::Default, TetradKind::Static, TetradKind::LNRF},
                     "Teo's rotating wormhole, general form with N = K = 1 (Teo, PRD 58 (1998) 024014)",
                     Vec4{{0, 10, M_PI / 2, 0}},
                     {}}) {
    on_params_changed();
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    return teo_tetrad(x, kind != TetradKind::LNRF);
  }
};

std::unique_ptr<Metric> make_metric_TeoWHl() { return std::make_unique<TeoWHl>(); }

}  // namespace geovis
