// The central surface of a black-hole or wormhole spacetime, for drawing it next to a light ray
// (`geovis view`): the event horizon of the Schwarzschild family, Kerr and Reissner–Nordström, the
// throat of the Morris–Thorne wormhole. The radius is the one in the metric's pseudo-Cartesian
// coordinates (Metric::to_pseudo_cartesian, paper §2.3), i.e. where a ray that ends there is drawn.
#pragma once

#include <optional>
#include <string>

#include "spacetime/metric.h"

namespace geovis {

struct CentralSurface {
  std::string kind;   ///< "horizon" or "throat"
  double radius = 0;  ///< pseudo-Cartesian radius |p|
  /// The coordinate statement, e.g. "r+ = M + sqrt(M^2 - a^2)".
  std::string formula;
};

/// The surface for the metrics listed above; nothing for every other metric, for a naked
/// singularity (|a| > M, |Q| > M) and for mass 0.
std::optional<CentralSurface> central_surface(const Metric& m);

}  // namespace geovis
