#include "render/object_type.h"

#include "render/compound.h"
#include "render/csg.h"
#include "render/local_object.h"
#include "spacetime/metric_registry.h"

namespace geovis {

std::vector<ParamSpec> primitive_keys(bool with_motion) {
  using T = ParamType;
  std::vector<ParamSpec> s = {
      {"objtype", T::Int, "gpObjTypeInCoords (1) or gpObjTypeLocal (0)", false, false, 1.0, ParamRange{0, 1}},
      {"id", T::String, "object id"},
      {"shader", T::String, "surface shader id"},
      {"metric", T::String, "metric id (the device's metric is used)"},
      {"transform", T::Transform, "object-to-coordinates transform", false, false, Transform::identity(3)},
      {"chart", T::Int, "coordinate chart of the object", false, false, 0.0}};
  if (with_motion) s.push_back({"motion", T::String, "motion id (e.g. ConstVelocity)"});
  return s;
}

std::vector<ParamSpec> primitive_keys_and(const std::vector<ParamSpec>& own) {
  std::vector<ParamSpec> s = primitive_keys();
  s.insert(s.end(), own.begin(), own.end());
  return s;
}

Vec3 vec3_key(const ParamReader& keys, std::string_view key) {
  const auto v = keys.vector(key, 3);
  return {v[0], v[1], v[2]};
}

ObjType object_type_of(const SceneObject& o) {
  if (auto* p = dynamic_cast<const PrimitiveData*>(&o)) return p->objtype;
  if (auto* c = dynamic_cast<const CompoundObject*>(&o)) {
    for (const auto& ch : c->children())
      if (object_type_of(*ch) == ObjType::Local) return ObjType::Local;
    return ObjType::InCoords;
  }
  if (auto* csg = dynamic_cast<const CsgObject*>(&o)) return object_type_of(*csg->first);
  return ObjType::InCoords;  // local-comp-object and moving objects are placed in coordinates
}

std::shared_ptr<const Metric> require_metric(const ParamSet& ps, BuildContext& ctx, std::string_view key) {
  if (!ctx.metric) ps.fail(key, "needs a metric: define one with init-metric before this command");
  return ctx.metric;
}

SceneObjectPtr finish_primitive(const ParamReader& keys, BuildContext& ctx, std::shared_ptr<SceneObject> obj,
                                PrimitiveData& data, const Transform* pre_rotation) {
  const ParamSet& ps = keys.params();
  if (ps.has("shader")) {
    data.shader_owner = ctx.ref(ctx.shaders, ps, "shader", "shader");
    data.shader = data.shader_owner.get();
  }
  data.objtype = keys.integer("objtype") == 0 ? ObjType::Local : ObjType::InCoords;
  if (ps.has("transform") || pre_rotation) {
    ps.blame("transform", [&] {
      const Transform t = ps.get_transform("transform", Transform::identity(3));
      data.set_transform(pre_rotation ? t * *pre_rotation : t);
    });
  }
  obj->chart = keys.integer("chart");
  obj->id = ps.get_string("id", "");
  data.object_id = ctx.next_object_id();
  if (ps.has("motion")) {
    const MotionPtr& motion = ctx.ref(ctx.motions, ps, "motion", "motion");
    auto metric = require_metric(ps, ctx, "motion");
    return ps.blame("motion", [&]() -> SceneObjectPtr {
      const bool pseudo_cartesian =
          std::string_view(motion->type_name()) == "ConstVelocity" && !metric->info().inertial_cartesian;
      if (pseudo_cartesian) {
        ctx.diagnostics().warn(ps.loc(), ps.command(), "motion",
                               "the ConstVelocity motion \"" + ps.get_string("motion") +
                                   "\" is special-relativistic; in the " + metric->name() +
                                   " metric it is applied, as GeoViS does, to the pseudo-Cartesian coordinates (t, "
                                   "x, y, z) of the rays as if they were Minkowski coordinates: a kinematic effect, "
                                   "not a motion of this spacetime");
        metric = make_metric("Minkowski");
      }
      auto moving = std::make_shared<LocalObject>(obj, LocalFrame(metric, motion));
      moving->id = obj->id;
      moving->chart = obj->chart;
      if (pseudo_cartesian) return std::make_shared<PseudoCartesianMotionObject>(moving);
      return moving;
    });
  }
  return obj;
}

}  // namespace geovis
