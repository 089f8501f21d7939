// GeoViS csg-object (GvsSolidDifferObj / GvsSolidUnifiedObj / GvsSolidIntersecObj): Boolean
// combinations of two solids by interval arithmetic on their spans along the ray's line
// (Roth, "Ray casting for modeling solids", Comput. Graph. Image Process. 18 (1982) 109).
#pragma once

#include <memory>

#include "render/shapes.h"

namespace geovis {

/// GeoViS csgType: 1 difference (obj1 − obj2), 2 union, 3 intersection.
enum class CsgOp { Difference = 1, Union = 2, Intersection = 3 };

/// Span-list operations (inputs sorted and disjoint; output sorted and disjoint). Boundaries
/// taken from the subtracted solid get their normal flipped (they bound the result from inside
/// the removed volume).
void csg_union(const SpanList& a, const SpanList& b, SpanList& out);
void csg_intersection(const SpanList& a, const SpanList& b, SpanList& out);
void csg_difference(const SpanList& a, const SpanList& b, SpanList& out);

class CsgObject final : public Solid {
 public:
  CsgObject(CsgOp op, std::shared_ptr<const Solid> a, std::shared_ptr<const Solid> b);
  void spans(const Vec3& a, const Vec3& d, SpanList& out) const override;
  Bounds3 bounds() const override;
  /// The boundary of A ∪ B, A ∩ B and A − B lies in ∂A ∪ ∂B (every crossing of the span lists is
  /// one of a primitive's): the smaller of the two solids' radii, or inner_radius() if larger.
  double surface_free_radius() const override;
  CsgOp op;
  std::shared_ptr<const Solid> first, second;
};

}  // namespace geovis
