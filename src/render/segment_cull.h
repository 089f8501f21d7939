// Steps that cannot touch the scene are not tested against it (issue #13). Most accepted steps of
// a ray run far from every surface: between the camera and a background sphere around it, every
// chord lies inside the sphere; around a thin disk, every chord that does not cross its plane
// lies beside it. Two regions hold none of the scene's surface, both found once per Tracer:
//  - the ball around the origin of each chart (SceneObject::restrict_surface_free_radii: a ball
//    or ellipsoid's inscribed ball, the distance of an object's bounds, combined over CSG,
//    compounds and their transforms). A chord whose two ends lie in that ball of their common
//    chart lies in it whole (the ball is convex). Chords that change chart, and charts beyond
//    kCharts, are always tested;
//  - the outside of the scene's bounding box (SceneObject::bounds, which holds every object of
//    every chart). A chord whose two ends lie beyond the same face of the box lies beyond it whole
//    (the half-space is convex).
// Such a chord crosses no surface, so the object tests could only return "no hit": the step is
// skipped, and the picture is the same to the bit.
#pragma once

#include "render/object.h"

namespace geovis {

class SegmentCull {
 public:
  /// Charts with an empty ball (Morris–Thorne and the Teo wormholes have two).
  static constexpr int kCharts = 4;
  /// The ball's radius is shrunk, the box widened by this fraction of its farthest corner's
  /// distance. Rounding: the chord's ends carry the error of the coordinate transformation (|p|
  /// from |r| differs from the norm of the computed p by a few ulps, Metric::
  /// pseudo_cartesian_radius), and a primitive's test of a chord that stays clear of its surface
  /// by a gap δ·R cannot report a crossing in [0, 1) unless its own rounding (a few ulps of the
  /// scene's lengths, ~1e-15 relative) exceeds the gap. 1e-6 leaves nine orders of magnitude for
  /// both and costs nothing: only chords ending within 1e-6·R of the ball's rim or the box's
  /// faces are tested that could have been skipped.
  static constexpr double kMargin = 1e-6;

  /// Skips nothing.
  SegmentCull() = default;
  /// The empty regions of `scene`.
  explicit SegmentCull(const SceneObject& scene);

  /// The chord from squared radius r0² in chart0 to r1² in chart1 (|p|² of its pseudo-Cartesian
  /// ends) lies in the empty ball of its chart. Squares: the ends' |p|² needs no square root.
  bool inside_empty_ball(int chart0, double r0_squared, int chart1, double r1_squared) const {
    return chart0 == chart1 && chart0 >= 0 && chart0 < kCharts && r0_squared < radius2_[chart0] &&
           r1_squared < radius2_[chart0];
  }
  /// The chord from p0 to p1 (pseudo-Cartesian) lies beyond one face of the scene's (widened)
  /// bounding box (a NaN coordinate puts it beyond no face of its axis).
  bool outside_bounds(const Vec3& p0, const Vec3& p1) const { return box_.segment_beyond_a_face(p0, p1); }
  /// For the chords of the lanes in `lanes` of a packet (kPacketLanes lanes) from p0 to p1 in
  /// chart 0 (SoA: rows x, y, z of kPacketLanes doubles each), whose ends p0 have |p0|²
  /// r0_squared: bit l of `lanes` where chord l lies in the empty ball or beyond a face of the box
  /// (inside_empty_ball || outside_bounds, their comparisons), all chords at once on SIMD lanes.
  /// Writes the next chords' starts: next_p = p1 and next_r0_squared = |p1|² (dot(p1, p1), its
  /// operations) on the lanes in `lanes`, p0 and r0_squared on the others. Why: the cull lane by
  /// lane, with a branch per test, was 50–85 instructions per step of the packet in Mino time
  /// (~8 % of kerrAccretionDisk.scm's tracing, callgrind, issue 13).
  unsigned chart0_chords_skipped(unsigned lanes, const double* p0, const double* r0_squared, const double* p1,
                                 double* next_p, double* next_r0_squared) const;
  /// The (shrunk) radius of the empty ball of `chart` (0: none; +∞: no object in that chart).
  double radius(int chart) const { return chart >= 0 && chart < kCharts ? radius_[chart] : 0.0; }
  /// The (widened) bounding box outside which nothing is hit (infinite: none; empty: no object).
  const Bounds3& bounds() const { return box_; }

 private:
  double radius_[kCharts] = {0, 0, 0, 0};
  double radius2_[kCharts] = {0, 0, 0, 0};  ///< radius_ squared
  Bounds3 box_ = Bounds3::infinite();
};

}  // namespace geovis
