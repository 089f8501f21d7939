// Scene objects: the contract between ray traversal (render/tracer) and the object
// implementations (render/shapes, csg, mesh, bvh, local objects).
//
// Ray traversal integrates the null geodesic backwards; every accepted step becomes a Segment in
// pseudo-Cartesian coordinates (paper §2.3). Objects test the straight segment and report the
// closest hit as the fraction `s` along it; the tracer refines the hit to integration precision.
// A segment may be arbitrarily long in space and time (in Minkowski the whole ray is one segment,
// spacetime/straight_ray.h): an object whose test needs short pieces (a moving or turning local
// object, render/local_object.h) cuts the segment itself.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "spacetime/geodesic.h"
#include "spacetime/vec.h"

namespace geovis {

class Shader;
class Metric;

struct Bounds3 {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
  void expand(const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  void expand(const Bounds3& b) {
    expand(b.lo);
    expand(b.hi);
  }
  bool empty() const { return lo.x > hi.x; }
  /// Distance of the box's closest point from the origin (0 when the box contains it; +∞ when
  /// empty: no point at all).
  double distance_from_origin() const {
    if (empty()) return std::numeric_limits<double>::infinity();
    double d2 = 0;
    for (int i = 0; i < 3; ++i) {
      const double d = std::max({lo[i], 0.0, -hi[i]});
      d2 += d * d;
    }
    return std::sqrt(d2);
  }
  /// Distance of the box's farthest point (a corner) from the origin (0 when empty).
  double farthest_distance_from_origin() const {
    if (empty()) return 0;
    const Vec3 far{std::max(-lo.x, hi.x), std::max(-lo.y, hi.y), std::max(-lo.z, hi.z)};
    return std::sqrt(dot(far, far));
  }
  /// The segment from p to q lies beyond one face of the box (both ends beyond the same face; the
  /// half-space is convex), so it misses the box. A NaN coordinate puts it beyond no face of its
  /// axis.
  bool segment_beyond_a_face(const Vec3& p, const Vec3& q) const {
    bool out = false;
    for (int i = 0; i < 3; ++i) out |= (p[i] < lo[i] && q[i] < lo[i]) | (p[i] > hi[i] && q[i] > hi[i]);
    return out;
  }
  static Bounds3 infinite() {
    const double inf = std::numeric_limits<double>::infinity();
    return {Vec3{-inf, -inf, -inf}, Vec3{inf, inf, inf}};
  }
};

struct Hit;
class SceneObject;

/// One step of the ray, as a straight 4D segment. `x0`/`x1` are the metric coordinates of the
/// ends, `p0`/`p1` the pseudo-Cartesian positions (chart0/chart1 the charts), the coordinate time
/// is x[0]. Ray direction: from p0 (closer to the observer in the backward trace) towards p1.
struct Segment {
  Vec4 x0, x1;
  Vec3 p0, p1;
  int chart0 = 0, chart1 = 0;
  const StepView* step = nullptr;  ///< the integration step (for refinement); may be null
  const Metric* metric = nullptr;
  /// A sub-chord of refine_hit (render/tracer.cpp): the hit on the chord whose piece of the curve
  /// this one approximates more closely (an object may start its search where it found that hit:
  /// Hit::frame_object); null otherwise.
  const Hit* refines = nullptr;
};

/// The closest intersection found so far. An object updates it only when it finds a hit with
/// 0 <= s < hit.s.
struct Hit {
  double s = std::numeric_limits<double>::infinity();  ///< fraction along the segment
  Vec3 point;    ///< hit point, pseudo-Cartesian (or object-local for local objects)
  Vec3 normal;   ///< unit outward surface normal, same frame as `point`
  Vec3 ray_dir;  ///< unit ray direction (p1 - p0) in the same frame as `normal`
  /// Normal (unit, outward) and unit ray direction in the primitive's normalised local frame
  /// (GeoViS's "standard object system": unit sphere, unit cube [0,1]³, unit cylinder; the plane of
  /// a planar surface; a mesh's own frame), in which the diffuse term is computed (GeoViS
  /// GvsSurfaceShader::reflArtifColor). Not changed by the transforms of enclosing compounds.
  Vec3 shade_normal;
  Vec3 shade_dir;
  double u = 0, v = 0;  ///< surface texture coordinates in [0,1]
  const Shader* shader = nullptr;
  int object_id = 0;  ///< GeoViS objID: primitive counter, 1 = first primitive created; 0 = none
  double time = 0;    ///< coordinate time of the hit (x^0)
  /// Four-velocity of the emitting surface (coordinates), zero when the object is at rest in the
  /// natural static frame; used for the frequency shift.
  Vec4 emitter_u{{0, 0, 0, 0}};
  /// The surface is a thin disk of matter on circular Keplerian orbits (plane-ring `emitter
  /// "keplerian"`): the tracer takes the emitter velocity from spacetime/circular_orbit.h at the
  /// refined hit event (emitter_u zero).
  bool keplerian = false;
  /// Part of a multi-part primitive (box face 0..5: -x,+x,-y,+y,-z,+z as GeoViS GvsSolBox;
  /// cylinder/ring 0 outer side, 1 base, 2 top, 3 ring inner side); 0 otherwise. Used by DieT2D.
  int part = 0;
  /// A local object on a sampled motion (render/local_object.h) that found this hit, and the proper
  /// time τ of the frame it found it in (the converged frozen frame); null and 0 otherwise. Its
  /// tests of the sub-chords that refine the hit (Segment::refines) start in that frame.
  const SceneObject* frame_object = nullptr;
  double frame_tau = 0;
  bool valid() const { return s < std::numeric_limits<double>::infinity(); }
};

class SceneObject {
 public:
  virtual ~SceneObject() = default;
  /// Tests the segment; on a closer hit (0 <= s < hit.s) fills `hit` and returns true, else
  /// leaves `hit` as it is and returns false (the tracer reuses one Hit for the chords that miss).
  virtual bool intersect(const Segment& seg, Hit& hit) const = 0;
  /// Bounds in pseudo-Cartesian coordinates (infinite when unknown/unbounded): a segment that
  /// hits the object touches them (a compound's BVH and the tracer's SegmentCull skip the others).
  virtual Bounds3 bounds() const = 0;
  /// No point of the object lies closer to the origin than this (pseudo-Cartesian |p|; the
  /// renderer's capture radius, geodesic.h SolverConfig::capture_radius). Default: the distance
  /// of its bounds, 0 when they contain the origin.
  virtual double inner_radius() const { return bounds().distance_from_origin(); }
  /// Every point of the object lies within this distance of the origin (|p|; a local object's
  /// bounding sphere in its frame, render/local_object.h). Default: the farthest corner of its
  /// bounds.
  virtual double outer_radius() const { return bounds().farthest_distance_from_origin(); }
  /// Radius of the ball around the origin of the object's chart that holds none of its surface:
  /// a segment inside it cannot hit the object (every hit is a crossing of the surface; a solid
  /// seen from inside is hit where the segment leaves it). Exact in real arithmetic up to a
  /// margin where it is a difference of large lengths; the tracer adds the margin for the rounding
  /// of the chord's ends and of the tests (render/segment_cull.h). Default: inner_radius() (no
  /// point of the object at all is closer).
  virtual double surface_free_radius() const { return inner_radius(); }
  /// Lowers free[c] to the surface-free radius of every part of the object in chart c < n (the
  /// scene's per-chart empty ball, Tracer): a leaf tests only segments of its own chart, so it
  /// restricts free[chart] alone; groups (render/compound.h) combine their children.
  virtual void restrict_surface_free_radii(double* free, int n) const {
    if (chart >= 0 && chart < n) free[chart] = std::min(free[chart], surface_free_radius());
  }
  /// Chart in which the object lives (paper §2.3; e.g. Morris-Thorne 0: l>0, 1: l<=0).
  int chart = 0;
  std::string id;
};

using SceneObjectPtr = std::shared_ptr<SceneObject>;

}  // namespace geovis
