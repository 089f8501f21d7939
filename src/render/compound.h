// GeoViS comp-object / comp-octree-object: a group of objects, closest hit wins. Children with
// finite bounds sit in a BVH (render/bvh.h), unbounded ones are tested always. An optional
// transform maps the whole group (object -> parent).
#pragma once

#include <vector>

#include "render/bvh.h"
#include "render/shapes.h"

namespace geovis {

class CompoundObject final : public SceneObject {
 public:
  CompoundObject() = default;
  explicit CompoundObject(std::vector<SceneObjectPtr> children);
  /// Appends a child (add-object) and rebuilds the hierarchy.
  void add(SceneObjectPtr child);
  void add(const std::vector<SceneObjectPtr>& more);
  void set_transform(const Transform& t);
  bool intersect(const Segment& seg, Hit& hit) const override;
  Bounds3 bounds() const override;
  /// The smallest of the children's (untransformed; else the bounds').
  double inner_radius() const override;
  /// The largest of the children's (untransformed; else the bounds').
  double outer_radius() const override;
  const std::vector<SceneObjectPtr>& children() const { return children_; }

 private:
  void rebuild();
  bool intersect_children(const Segment& seg, Hit& hit) const;
  std::vector<SceneObjectPtr> children_;
  std::vector<SceneObjectPtr> merged_;       ///< children moving with one motion, grouped (owned here)
  std::vector<const SceneObject*> bounded_;  ///< indexed by BVH item
  std::vector<const SceneObject*> unbounded_;
  Bvh bvh_;
  Bounds3 bounds_;
  bool transformed_ = false;
  Affine3 to_parent_, to_local_;
};

}  // namespace geovis
