// The description of a scene-object command (core/type_registry.h): each object's file registers
// one ObjectType — the command name (solid-ellipsoid, mesh-obj, csg-object, ...), its keys and
// defaults (docs/geovis-catalogue.md §4), what a per-frame change may set and its factory. The
// command table (scene/command_table.cpp) makes a scene command of every entry; make_object
// (render/plugins.h) checks the keys and builds it. The helpers below are what the primitives share.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "core/param_reader.h"
#include "core/type_registry.h"
#include "render/build_context.h"
#include "render/object.h"
#include "render/shapes.h"

namespace geovis {

struct ObjectType : TypeDescription {
  /// The object from its keys (absent keys read as their defaults); ids resolve in ctx.
  SceneObjectPtr (*make)(const ParamReader& keys, BuildContext& ctx) = nullptr;
  /// Built from other objects (csg-object, comp-object, ...): the builder builds it after them.
  bool container = false;
};
using ObjectRegistry = TypeRegistry<ObjectType>;

/// objtype, id, shader, metric, transform, chart (and motion): the keys of every primitive.
std::vector<ParamSpec> primitive_keys(bool with_motion = true);
/// primitive_keys() followed by `own`.
std::vector<ParamSpec> primitive_keys_and(const std::vector<ParamSpec>& own);

/// Applies the primitive keys to a new primitive — shader, objtype, transform (after
/// `pre_rotation` when given), chart, id, the next objID — and wraps it in a moving frame when
/// `motion` is given (a ConstVelocity motion outside Minkowski acts on pseudo-Cartesian
/// coordinates, as GeoViS does: render/local_object.h).
SceneObjectPtr finish_primitive(const ParamReader& keys, BuildContext& ctx, std::shared_ptr<SceneObject> obj,
                                PrimitiveData& data, const Transform* pre_rotation = nullptr);
template <class T>
SceneObjectPtr finish_primitive(const ParamReader& keys, BuildContext& ctx, std::shared_ptr<T> obj) {
  return finish_primitive(keys, ctx, obj, *obj);
}

/// gpObjTypeLocal or gpObjTypeInCoords of an object (a group is local when one of its children is).
ObjType object_type_of(const SceneObject& o);
/// The metric of the device being built; without one a SceneError at `key`.
std::shared_ptr<const Metric> require_metric(const ParamSet& ps, BuildContext& ctx, std::string_view key);
/// A 3-vector key as Vec3.
Vec3 vec3_key(const ParamReader& keys, std::string_view key);

}  // namespace geovis
