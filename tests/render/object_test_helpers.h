// Helpers shared by the object/texture tests: straight segments in Minkowski-like coordinates.
#pragma once

#include "render/object.h"

namespace geovis::testing {

/// Segment p0 -> p1 with coordinate times t0, t1 (Cartesian coordinates = pseudo-Cartesian).
inline Segment make_segment(const Vec3& p0, const Vec3& p1, double t0 = 0.0, double t1 = 0.0) {
  Segment s;
  s.p0 = p0;
  s.p1 = p1;
  s.x0 = Vec4{{t0, p0.x, p0.y, p0.z}};
  s.x1 = Vec4{{t1, p1.x, p1.y, p1.z}};
  return s;
}

/// A backward light ray segment in Minkowski: from event (t, p) along unit direction n for a
/// length L, the coordinate time decreasing by L.
inline Segment light_segment(double t, const Vec3& p, const Vec3& n, double L) {
  return make_segment(p, p + L * n, t, t - L);
}

}  // namespace geovis::testing
