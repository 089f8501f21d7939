// The light ray behind one pixel, step by step (`geovis view`: click a pixel, see its ray): the
// tracer's own integration (render/tracer.h, same solver settings, stop logic and hit test) with
// every accepted step recorded, in metric and pseudo-Cartesian coordinates (paper §2.3).
#pragma once

#include <vector>

#include "render/tracer.h"

namespace geovis {

struct RayPoint {
  double lambda = 0;
  Vec4 x{{0, 0, 0, 0}};  ///< metric coordinates
  Vec4 k{{0, 0, 0, 0}};  ///< past-directed tangent (the tracer's backward ray, paper eq. 7)
  Vec3 p{0, 0, 0};       ///< pseudo-Cartesian position (Metric::to_pseudo_cartesian)
  int chart = 0;
};

struct RayPath {
  bool traced = false;      ///< false: the camera has no ray through this image position
  Vec3 local_dir{0, 0, 0};  ///< unit viewing direction in the observer's frame (camera)
  /// The same light ray started in the metric's natural (default) tetrad at the observer, as
  /// `geovis geodesic --dir` takes it: k = scale·(−E_(0) + natural_dir) with natural_dir a unit
  /// vector; scale = 1 for an observer at rest in the natural frame (otherwise aberration and
  /// Doppler factor: the affine parameter of `geovis geodesic` is scale times this one).
  Vec3 natural_dir{0, 0, 0};
  double natural_scale = 1;
  /// Start point, every accepted step; after a hit the last point is the refined hit event.
  std::vector<RayPoint> points;
  TraceResult result;
  double escape_radius = 0;  ///< of the tracer (Tracer::escape_radius)
};

/// Traces the ray through continuous image position (px, py) of `job` (pixel centre of (i, j):
/// (i + .5, j + .5)). The geodesic system is always the plain one (8 components): a Jacobi filter
/// changes nothing about the ray but would change the step sizes, and the path must be the one
/// `geovis geodesic` integrates.
RayPath trace_ray_path(const RenderJob& job, double px, double py);

}  // namespace geovis
