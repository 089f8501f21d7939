#include "render/segment_cull.h"

#include <limits>

namespace geovis {

SegmentCull::SegmentCull(const SceneObject& scene) {
  for (double& r : radius_) r = std::numeric_limits<double>::infinity();
  scene.restrict_surface_free_radii(radius_, kCharts);
  for (int c = 0; c < kCharts; ++c) {
    double& r = radius_[c];
    r = r > 0 ? r * (1.0 - kMargin) : 0.0;  // also NaN -> 0: cull nothing
    radius2_[c] = r * r;
  }
  // Empty bounds (an object that can never be hit, e.g. disjoint solids intersected; compound.h
  // skips such children) become the box from +∞ to −∞, beyond which every chord lies; infinite
  // ones stay infinite (nothing is beyond them).
  box_ = scene.bounds();
  if (box_.empty()) {
    box_ = Bounds3{};
  } else {
    const double widen = kMargin * box_.farthest_distance_from_origin();
    box_.lo = box_.lo - Vec3{widen, widen, widen};
    box_.hi = box_.hi + Vec3{widen, widen, widen};
  }
}

}  // namespace geovis
