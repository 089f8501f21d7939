#include "render/compound.h"

#include <cmath>
#include <map>

#include "render/local_object.h"
#include "render/object_type.h"

namespace geovis {

namespace {
bool finite_bounds(const Bounds3& b) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(b.lo[i]) || !std::isfinite(b.hi[i])) return false;
  return true;
}
}  // namespace

CompoundObject::CompoundObject(std::vector<SceneObjectPtr> children) : children_(std::move(children)) { rebuild(); }

void CompoundObject::add(SceneObjectPtr child) {
  children_.push_back(std::move(child));
  rebuild();
}

void CompoundObject::add(const std::vector<SceneObjectPtr>& more) {
  children_.insert(children_.end(), more.begin(), more.end());
  rebuild();
}

void CompoundObject::set_transform(const Transform& t) {
  to_parent_ = Affine3::from(t);
  to_local_ = to_parent_.inverse();
  transformed_ = !to_parent_.is_identity();
  rebuild();
}

void CompoundObject::rebuild() {
  bounded_.clear();
  unbounded_.clear();
  merged_.clear();
  // Objects moving with the same motion share one local frame: test them as one local object
  // (one frame transformation per segment instead of one per object; minkWheel.scm's wheel
  // consists of 11 primitives on one ConstVelocity motion).
  std::vector<SceneObjectPtr> flat;
  std::map<std::pair<const Motion*, int>, std::vector<std::shared_ptr<LocalObject>>> groups;
  for (const auto& c : children_) {
    auto lo = std::dynamic_pointer_cast<LocalObject>(c);
    if (lo && lo->frame().moving())
      groups[{lo->frame().motion(), lo->chart}].push_back(lo);
    else
      flat.push_back(c);
  }
  for (const auto& [key, members] : groups) {
    if (members.size() == 1) {
      flat.push_back(members[0]);
      continue;
    }
    std::vector<SceneObjectPtr> inner;
    for (const auto& m : members) inner.push_back(m->child());
    auto group = std::make_shared<CompoundObject>(std::move(inner));
    group->chart = key.second;
    auto merged = std::make_shared<LocalObject>(group, members[0]->frame());
    merged->chart = members[0]->chart;
    merged_.push_back(merged);
    flat.push_back(merged);
  }
  std::vector<Bounds3> boxes;
  Bounds3 all;
  bool infinite = false;
  for (const auto& c : flat) {
    const Bounds3 b = c->bounds();
    if (b.empty()) continue;  // can never be hit (e.g. intersection of disjoint solids)
    if (finite_bounds(b)) {
      bounded_.push_back(c.get());
      boxes.push_back(b);
      all.expand(b);
    } else {
      unbounded_.push_back(c.get());
      infinite = true;
    }
  }
  bvh_.build(boxes);
  bounds_ = infinite ? Bounds3::infinite() : (transformed_ ? to_parent_.bounds(all) : all);
}

bool CompoundObject::intersect_children(const Segment& seg, Hit& hit) const {
  bool found = false;
  for (const SceneObject* o : unbounded_) found |= o->intersect(seg, hit);
  const Vec3 d = seg.p1 - seg.p0;
  bvh_.traverse(seg.p0, d, std::min(1.0, hit.s), [&](int32_t i) {
    found |= bounded_[i]->intersect(seg, hit);
    return hit.s;
  });
  return found;
}

bool CompoundObject::intersect(const Segment& seg, Hit& hit) const {
  if (!transformed_) return intersect_children(seg, hit);
  Segment local = seg;
  local.p0 = to_local_.point(seg.p0);
  local.p1 = to_local_.point(seg.p1);
  if (!intersect_children(local, hit)) return false;
  // Back to the parent frame (s is unchanged by the affine map).
  hit.point = to_parent_.point(hit.point);
  hit.normal = normalize(to_local_.transposed_dir(hit.normal));
  hit.ray_dir = normalize(to_parent_.dir(hit.ray_dir));
  return true;
}

Bounds3 CompoundObject::bounds() const { return bounds_; }

double CompoundObject::inner_radius() const {
  if (transformed_) return bounds_.distance_from_origin();
  double r = std::numeric_limits<double>::infinity();
  for (const auto& c : children_) r = std::min(r, c->inner_radius());
  return r;
}

double CompoundObject::outer_radius() const {
  if (transformed_) return bounds_.farthest_distance_from_origin();
  double r = 0;
  for (const auto& c : children_) r = std::max(r, c->outer_radius());
  return r;
}

// ---- registration (docs/geovis-catalogue.md §4) -------------------------------------------------

namespace {

/// The objects of every `obj` key. GeoViS ignores objtype when intersecting: an object of
/// gpObjTypeLocal inside a plain group is placed in coordinates like any other (appViewMovBall.scm).
std::vector<SceneObjectPtr> group_children(const ParamSet& ps, BuildContext& ctx) {
  std::vector<SceneObjectPtr> out;
  for (const auto& id : ps.get_strings("obj")) out.push_back(ctx.lookup(ctx.objects, id, ps, "obj", "object"));
  return out;
}

const TypeRegistrar<ObjectType> comp_object{{{"comp-object",
                                              {},
                                              "a group of objects",
                                              {{"obj", ParamType::String, "object id", false, true},
                                               {"transform", ParamType::Transform, "transform of the whole group"},
                                               {"id", ParamType::String, "object id"}}},
                                             [](const ParamReader& keys, BuildContext& ctx) -> SceneObjectPtr {
                                               const ParamSet& ps = keys.params();
                                               auto comp = std::make_shared<CompoundObject>(group_children(ps, ctx));
                                               if (ps.has("transform"))
                                                 ps.blame("transform",
                                                          [&] { comp->set_transform(ps.get_transform("transform")); });
                                               comp->id = ps.get_string("id", "");
                                               return comp;
                                             },
                                             true}};

const TypeRegistrar<ObjectType> comp_octree_object{
    {{"comp-octree-object",
      {},
      "a group of objects in an octree (a BVH is used instead)",
      {{"obj", ParamType::String, "object id", false, true},
       {"lower", ParamType::Vec3, "octree box corner (a BVH is used instead)"},
       {"upper", ParamType::Vec3, "octree box corner (a BVH is used instead)"},
       {"subdivs",
        ParamType::Int,
        "octree subdivisions (a BVH is used instead)",
        false,
        false,
        {},
        ParamRange::non_negative()},
       {"id", ParamType::String, "object id"}}},
     [](const ParamReader& keys, BuildContext& ctx) -> SceneObjectPtr {
       auto comp = std::make_shared<CompoundObject>(group_children(keys.params(), ctx));
       comp->id = keys.params().get_string("id", "");
       return comp;
     },
     true}};

}  // namespace

}  // namespace geovis
