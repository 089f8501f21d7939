#include "render/segment_cull.h"

#include <limits>

namespace geovis {

SegmentCull::SegmentCull(const SceneObject& scene) {
  for (double& r : radius_) r = std::numeric_limits<double>::infinity();
  scene.restrict_surface_free_radii(radius_, kCharts);
  for (double& r : radius_) r = r > 0 ? r * (1.0 - kMargin) : 0.0;  // also NaN -> 0: cull nothing
}

}  // namespace geovis
