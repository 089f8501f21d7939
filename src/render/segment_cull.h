// Steps that cannot touch the scene are not tested against it (issue #13). Most accepted steps of
// a ray run far from every surface: between the camera and a background sphere around it, every
// chord lies inside the sphere. The scene gives, once per Tracer, the radius of the ball around
// the origin of each chart that holds none of its surface (SceneObject::
// restrict_surface_free_radii: a ball or ellipsoid's inscribed ball, the distance of an object's
// bounds, combined over CSG, compounds and their transforms). A chord whose two ends lie in that
// ball of their common chart lies in it whole (the ball is convex) and crosses no surface, so the
// object tests could only return "no hit": the step is skipped, and the picture is the same to
// the bit. Chords that change chart, and charts beyond kCharts, are always tested.
#pragma once

#include "render/object.h"

namespace geovis {

class SegmentCull {
 public:
  /// Charts with an empty ball (Morris–Thorne and the Teo wormholes have two).
  static constexpr int kCharts = 4;
  /// The ball's radius is shrunk by this fraction. Rounding: the chord's ends carry the error of
  /// the coordinate transformation (|p| from |r| differs from the norm of the computed p by a few
  /// ulps, Metric::pseudo_cartesian_radius), and a primitive's test of a chord that stays inside
  /// by a gap δ·R cannot report a crossing in [0, 1) unless its own rounding (a few ulps of the
  /// scene's lengths, ~1e-15 relative) exceeds the gap. 1e-6 leaves nine orders of magnitude for
  /// both and costs nothing: only chords ending within 1e-6·R of the ball's rim are tested that
  /// could have been skipped.
  static constexpr double kMargin = 1e-6;

  /// Skips nothing.
  SegmentCull() = default;
  /// The empty balls of `scene`.
  explicit SegmentCull(const SceneObject& scene);

  /// The chord from radius r0 in chart0 to radius r1 in chart1 (|p| of its pseudo-Cartesian ends)
  /// can hit nothing.
  bool excludes(int chart0, double r0, int chart1, double r1) const {
    return chart0 == chart1 && chart0 >= 0 && chart0 < kCharts && r0 < radius_[chart0] && r1 < radius_[chart0];
  }
  /// The (shrunk) radius of the empty ball of `chart` (0: none; +∞: no object in that chart).
  double radius(int chart) const { return chart >= 0 && chart < kCharts ? radius_[chart] : 0.0; }

 private:
  double radius_[kCharts] = {0, 0, 0, 0};
};

}  // namespace geovis
