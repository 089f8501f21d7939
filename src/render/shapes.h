// GeoViS primitives (catalogue §1, §4): solids (ellipsoid, box, closed elliptic cylinder, thick
// ring, background), planar surfaces (annulus, triangle, parallelogram). Each tests the straight
// segment p0 -> p1 of one ray step (paper §2.3) in its own frame: the object-to-parent transform
// M (scale/rotate/translate) is applied by mapping the segment with M⁻¹, which keeps the
// fraction s along the segment unchanged (affine map).
#pragma once

#include <array>
#include <memory>
#include <string>

#include "core/params.h"
#include "render/object.h"
#include "render/shader.h"

namespace geovis {

/// GeoViS gpObjTypeLocal / gpObjTypeInCoords.
enum class ObjType { Local = 0, InCoords = 1 };

/// Affine 3D map x -> A x + b (row-major 3x4), with helpers for points, directions, normals.
struct Affine3 {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  static Affine3 from(const Transform& t);
  Transform to_transform() const;
  Affine3 inverse() const;  ///< throws Error when singular
  bool is_identity() const;
  Vec3 point(const Vec3& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  Vec3 dir(const Vec3& d) const {
    return {m[0][0] * d.x + m[0][1] * d.y + m[0][2] * d.z, m[1][0] * d.x + m[1][1] * d.y + m[1][2] * d.z,
            m[2][0] * d.x + m[2][1] * d.y + m[2][2] * d.z};
  }
  /// Aᵀ n: with `this` = M⁻¹ this maps an object normal to the parent frame (M⁻ᵀ n).
  Vec3 transposed_dir(const Vec3& n) const {
    return {m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
            m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z};
  }
  Bounds3 bounds(const Bounds3& b) const;  ///< bounds of the 8 transformed corners
};

/// What every leaf primitive carries: shader, GeoViS objID, object type and its transform.
struct PrimitiveData {
  const Shader* shader = nullptr;
  ShaderPtr shader_owner;
  int object_id = 0;
  ObjType objtype = ObjType::InCoords;
  bool transformed = false;
  Affine3 to_parent, to_local;
  void set_transform(const Transform& t);
};

// ---- solids: span lists along the ray's line (CSG) ----------------------------------------------

class SolidPrimitive;

/// A surface crossing at line parameter t (point = a + t d).
struct Crossing {
  double t = 0;
  const SolidPrimitive* prim = nullptr;  ///< whose surface (computes normal and uv on demand)
  Vec3 p_local;                          ///< the point in the primitive's local frame
  Vec3 d_local;                          ///< the line's direction in the primitive's local frame
  int part = 0;                          ///< face index
  bool flip = false;  ///< normal reversed (boundary taken from the subtracted solid of a CSG difference)
};
/// Inside the solid between `in` and `out` (in.t <= out.t).
struct Span {
  Crossing in, out;
};
constexpr int kMaxSpans = 8;
/// Sorted, disjoint spans; fixed capacity (no heap on the hot path).
struct SpanList {
  int n = 0;
  Span s[kMaxSpans];
  void push(const Span& sp) {
    if (n < kMaxSpans) s[n++] = sp;
  }
};

/// A solid: knows where the infinite line a + t d is inside it.
class Solid : public SceneObject {
 public:
  /// Spans of the line a + t d (a, d in this object's parent frame), sorted by t.
  virtual void spans(const Vec3& a, const Vec3& d, SpanList& out) const = 0;
  /// Closest crossing of the segment with 0 <= t < min(1, hit.s): entry, or exit when the
  /// segment starts inside.
  bool intersect(const Segment& seg, Hit& hit) const override;
};

/// Fills `hit` from a crossing of segment p0 -> p1 (the frame in which spans() was asked).
void fill_hit_from_crossing(const Crossing& c, const Segment& seg, Hit& hit);

/// A convex (or ring) primitive solid with its own transform.
class SolidPrimitive : public Solid, public PrimitiveData {
 public:
  void spans(const Vec3& a, const Vec3& d, SpanList& out) const final;
  Bounds3 bounds() const final;
  /// Spans of the line o + t d in the local frame.
  virtual void local_spans(const Vec3& o, const Vec3& d, SpanList& out) const = 0;
  virtual Bounds3 local_bounds() const = 0;
  /// Outward unit normal (local frame) and texture coordinates at a crossing.
  virtual Vec3 local_normal(const Vec3& p, int part) const = 0;
  virtual void uv(const Vec3& p, int part, double& u, double& v) const = 0;
  /// Outward unit normal in the parent frame.
  Vec3 parent_normal(const Vec3& p_local, int part) const;
  /// Hit::shade_normal and Hit::shade_dir at local point p for local direction d: the outward
  /// normal and the unit direction in the normalised frame of the primitive (GeoViS GvsSol*:
  /// unit sphere, unit cube, unit cylinder).
  virtual void shading_frame(const Vec3& p, const Vec3& d, int part, Vec3& n, Vec3& dir) const = 0;
};

/// GvsSolEllipsoid: centre c, semi-axes a. uv (catalogue §4) from n = (p − c)/a on the unit
/// sphere: v = acos(−n_z)/π, u = acos(n_x/sin θ)/2π, u -> 1 − u for n_y < 0.
class Ellipsoid final : public SolidPrimitive {
 public:
  Ellipsoid(const Vec3& center, const Vec3& axlen) : center(center), axlen(axlen) {}
  void local_spans(const Vec3& o, const Vec3& d, SpanList& out) const override;
  Bounds3 local_bounds() const override;
  Vec3 local_normal(const Vec3& p, int part) const override;
  void uv(const Vec3& p, int part, double& u, double& v) const override;
  void shading_frame(const Vec3& p, const Vec3& d, int part, Vec3& n, Vec3& dir) const override;
  /// Untransformed: |c| + the largest semi-axis (a sphere's own radius, not its box's corner);
  /// transformed: the bounds'.
  double outer_radius() const override;
  Vec3 center, axlen;
};
/// The GeoViS uv of a point n on the unit sphere (catalogue §4).
void ellipsoid_uv(const Vec3& n, double& u, double& v);

/// GvsSolBox: axis-aligned box between the corners (any order). Faces 0..5 = −x,+x,−y,+y,−z,+z;
/// uv from the point q in the unit box (GeoViS GvsSolBox): (1−q_y, q_z), (q_y, q_z), (q_x, q_z),
/// (1−q_x, q_z), (q_x, q_y), (q_x, q_y).
class Box final : public SolidPrimitive {
 public:
  Box(const Vec3& c0, const Vec3& c1);
  void local_spans(const Vec3& o, const Vec3& d, SpanList& out) const override;
  Bounds3 local_bounds() const override { return {lo, hi}; }
  Vec3 local_normal(const Vec3& p, int part) const override;
  void uv(const Vec3& p, int part, double& u, double& v) const override;
  void shading_frame(const Vec3& p, const Vec3& d, int part, Vec3& n, Vec3& dir) const override;
  Vec3 lo, hi;
};

/// Frame of a cylinder (GeoViS GvsSolCylinder::setGeometry): the unit cylinder mapped by
/// T(base)·Rz(α)·Ry(β)·S(r1, r2, h) with a = top − base, α = atan2(a_y, a_x),
/// β = atan2(√(a_x² + a_y²), a_z), h = |a|; so ez = a/h, e1 = Rz(α)Ry(β) x̂ =
/// (cos α cos β, sin α cos β, −sin β), e2 = Rz(α) ŷ = (−sin α, cos α, 0).
struct CylinderFrame {
  Vec3 base, e1, e2, ez;
  double height = 0;
  CylinderFrame() = default;
  CylinderFrame(const Vec3& base, const Vec3& top);
  /// Coordinates (x along e1, y along e2, z along the axis from base).
  Vec3 to_frame(const Vec3& p) const {
    const Vec3 q = p - base;
    return {dot(q, e1), dot(q, e2), dot(q, ez)};
  }
  Vec3 dir_to_frame(const Vec3& d) const { return {dot(d, e1), dot(d, e2), dot(d, ez)}; }
  Vec3 from_frame_dir(const Vec3& d) const { return d.x * e1 + d.y * e2 + d.z * ez; }
};

/// GvsSolCylinder: closed elliptic cylinder, radii (r1 along e1, r2 along e2). Parts: 0 side,
/// 1 base cap, 2 top cap. uv (GvsSolCylinder::calcTexUVParam) from the point (x, y, z) of the unit
/// cylinder (x = q·e1/r1, y = q·e2/r2, z = q·ez/h): side u = acos(x)/2π (1 − that for y < 0),
/// v = z; caps u = (atan2(y, x) + π)/2π, v = √(x² + y²).
class Cylinder final : public SolidPrimitive {
 public:
  Cylinder(const Vec3& base, const Vec3& top, double r1, double r2);
  void local_spans(const Vec3& o, const Vec3& d, SpanList& out) const override;
  Bounds3 local_bounds() const override;
  Vec3 local_normal(const Vec3& p, int part) const override;
  void uv(const Vec3& p, int part, double& u, double& v) const override;
  void shading_frame(const Vec3& p, const Vec3& d, int part, Vec3& n, Vec3& dir) const override;
  CylinderFrame frame;
  double r1, r2;
};

/// GvsSolRing: the cylinder (radii) minus the coaxial inner cylinder (innerradii) — a thick ring.
/// Parts: 0 outer side, 1 base annulus, 2 top annulus, 3 inner side (normal towards the axis).
/// uv as the cylinder's (GvsSolRing::calcTexUVParam), in the unit frame of the outer cylinder,
/// except on the inner side: in the unit frame of the inner cylinder (radii innerradii).
class Ring final : public SolidPrimitive {
 public:
  Ring(const Vec3& base, const Vec3& top, double r1, double r2, double ri1, double ri2);
  void local_spans(const Vec3& o, const Vec3& d, SpanList& out) const override;
  Bounds3 local_bounds() const override;
  Vec3 local_normal(const Vec3& p, int part) const override;
  void uv(const Vec3& p, int part, double& u, double& v) const override;
  void shading_frame(const Vec3& p, const Vec3& d, int part, Vec3& n, Vec3& dir) const override;
  CylinderFrame frame;
  double r1, r2, ri1, ri2;
};

// ---- planar surfaces ----------------------------------------------------------------------------

/// A two-sided flat surface: the reported normal faces the incoming ray.
class PlanarPrimitive : public SceneObject, public PrimitiveData {
 public:
  bool intersect(const Segment& seg, Hit& hit) const final;
  Bounds3 bounds() const final;
  /// Local segment o -> o + d: fraction t in [0, tmax) of a hit, with local normal and uv.
  virtual bool local_intersect(const Vec3& o, const Vec3& d, double tmax, double& t, Vec3& n, double& u,
                               double& v) const = 0;
  virtual Bounds3 local_bounds() const = 0;
  /// Matter on circular Keplerian orbits (plane-ring `emitter "keplerian"`; Hit::keplerian).
  bool keplerian_disk = false;
};

/// GvsPlanarRing: annulus rin <= r <= rout around `center` in the plane ⟂ `normal` (the thin
/// accretion disk of paper §4.2). uv (GvsPlanarRing::calcTexUVParam) of the point p, r = p − c:
/// u = (|r| − rin)/(rout − rin) (radial), v = atan2(r·ŷ, r·x̂)/2π + 1/2 — the angle about the
/// frame's z axis for any normal (GeoViS's e1/e2 are always the x and y axes: the test that would
/// choose others reads e1 before setting it). GeoViS takes the angle of p itself, not of p − c;
/// the same for every ring centred at the origin (docs/geovis-differences.md). e1, e2 here only
/// span the plane for the bounds.
class PlaneRing final : public PlanarPrimitive {
 public:
  PlaneRing(const Vec3& center, const Vec3& normal, double rin, double rout);
  bool local_intersect(const Vec3& o, const Vec3& d, double tmax, double& t, Vec3& n, double& u,
                       double& v) const override;
  Bounds3 local_bounds() const override;
  /// Untransformed: |p|² = (c·n)² + |c⊥ + q|² with |q| ≥ rin in the plane, so |p| ≥
  /// √((c·n)² + max(0, rin − |c⊥|)²) (c⊥: the centre's part in the plane); transformed: the bounds'.
  double inner_radius() const override;
  Vec3 center, normal, e1, e2;
  double rin, rout;
};

/// GvsTriangle: p1, p2, p3; uv = barycentric coordinates (weights of p2, p3).
class Triangle final : public PlanarPrimitive {
 public:
  Triangle(const Vec3& p1, const Vec3& p2, const Vec3& p3) : p1(p1), p2(p2), p3(p3) {}
  bool local_intersect(const Vec3& o, const Vec3& d, double tmax, double& t, Vec3& n, double& u,
                       double& v) const override;
  Bounds3 local_bounds() const override;
  Vec3 p1, p2, p3;
};

/// Parallelogram with corner p1 and adjacent corners p2, p3 (fourth corner p2 + p3 − p1);
/// uv = the coordinates along the edges p2 − p1 and p3 − p1, both in [0, 1].
class Parallelogram final : public PlanarPrimitive {
 public:
  Parallelogram(const Vec3& p1, const Vec3& p2, const Vec3& p3) : p1(p1), p2(p2), p3(p3) {}
  bool local_intersect(const Vec3& o, const Vec3& d, double tmax, double& t, Vec3& n, double& u,
                       double& v) const override;
  Bounds3 local_bounds() const override;
  Vec3 p1, p2, p3;
};

/// Segment o -> o + d against triangle (a, b, c) (Möller & Trumbore, J. Graphics Tools 2 (1997)
/// 21): fraction t in [0, tmax), barycentric weights (b1, b2) of b and c. `parallelogram`: accept
/// b1, b2 in [0,1] independently (the parallelogram a, b, c, b + c − a).
bool segment_triangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c, double tmax, double& t,
                      double& b1, double& b2, bool parallelogram = false);

/// Slab test of the segment o + t d, t in [t0, t1], against a box; narrows [t0, t1].
inline bool segment_box(const Vec3& o, const Vec3& inv_d, const Bounds3& b, double& t0, double& t1) {
  for (int i = 0; i < 3; ++i) {
    double ta = (b.lo[i] - o[i]) * inv_d[i];
    double tb = (b.hi[i] - o[i]) * inv_d[i];
    if (ta > tb) std::swap(ta, tb);
    // NaN (0 * inf when the segment lies in a slab plane) must not reject: fmax/fmin ignore NaN.
    t0 = std::fmax(t0, ta);
    t1 = std::fmin(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace geovis
