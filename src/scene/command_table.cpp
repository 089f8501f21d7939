// The commands of the scene language (command_table.h), with the keys of the commands no plugin
// factory checks (docs/geovis-catalogue.md §1); the factories' keys come from their own files.
#include "scene/command_table.h"

#include <algorithm>
#include <cfloat>
#include <limits>

#include "render/camera_factory.h"
#include "render/camera_type.h"
#include "render/plugins.h"
#include "render/light_type.h"
#include "render/object_type.h"
#include "render/shader_type.h"
#include "render/texture_type.h"
#include "spacetime/geodesic.h"
#include "spacetime/metric.h"
#include "spacetime/metric_registry.h"
#include "spacetime/motion_factory.h"
#include "spacetime/solver_type.h"
#include "spacetime/tetrad.h"

namespace geovis {

const char* definition_kind_name(DefinitionKind k) {
  switch (k) {
    case DefinitionKind::Metric: return "metric";
    case DefinitionKind::Solver: return "solver";
    case DefinitionKind::Camera: return "camera";
    case DefinitionKind::RayGen: return "raygen";
    case DefinitionKind::Tetrad: return "local tetrad";
    case DefinitionKind::Projector: return "projector";
    case DefinitionKind::Light: return "light";
    case DefinitionKind::LightMgr: return "light manager";
    case DefinitionKind::Texture: return "texture";
    case DefinitionKind::Shader: return "shader";
    case DefinitionKind::Object: return "scene object";
    case DefinitionKind::Motion: return "motion";
  }
  return "object";
}

namespace {

// ---- keys of the commands the builder checks itself ------------------------------------------

/// The bounding box of init-solver and init-raygen; GeoViS's default is (±DBL_MAX, ±50, ±50, ±50)
/// (catalogue §1).
std::vector<ParamSpec> bounding_box_keys() {
  using T = ParamType;
  return {{"boundboxll", T::Vec4, "lower corner of the bounding box", false, false,
           std::vector<double>{-DBL_MAX, -50, -50, -50}},
          {"boundboxur", T::Vec4, "upper corner of the bounding box", false, false,
           std::vector<double>{DBL_MAX, 50, 50, 50}}};
}

std::vector<ParamSpec> keys_init_solver(const std::string&) {
  using T = ParamType;
  const SolverConfig d;  // GeoViS's defaults (spacetime/geodesic.h), except max_step (below)
  std::vector<ParamSpec> keys = {
      {"type", T::String, "integrator name (GeoViS nickname or full name)", true},
      {"id", T::String, "id"},
      {"metric", T::String, "metric id (the device's metric is used)"},
      {"geodtype", T::String, "lightlike, timelike or spacelike", false, false, std::string("lightlike")},
      {"geoddir", T::String, "forward or backward", false, false, std::string("forward")},
      {"step_ctrl", T::Bool, "adaptive step size control", false, false, d.step_ctrl},
      {"step_size", T::Number, "initial or fixed step size", false, false, d.step_size, ParamRange::positive()},
      {"max_step", T::Number,
       "maximal step size in the affine parameter (GeoViS's default 1); Carter's separated equations (separable "
       "#t) take it only when it is given",
       false, false, 1.0, ParamRange::positive()},
      {"eps_abs", T::Number, "absolute tolerance", false, false, d.eps_abs, ParamRange::non_negative()},
      {"eps_rel", T::Number, "relative tolerance", false, false, d.eps_rel, ParamRange::non_negative()},
      {"separable", T::Bool,
       "geovis extension: KerrBL and Schwarzschild geodesics through Carter's separated equations in Mino "
       "time; #f: the coordinate geodesic equation, as GeoViS",
       false, false, d.separable}};
  const auto box = bounding_box_keys();
  keys.insert(keys.end(), box.begin(), box.end());
  return keys;
}

std::vector<ParamSpec> keys_init_raygen(const std::string&) {
  using T = ParamType;
  std::vector<ParamSpec> keys = {{"type", T::String, "RayGenSimple", false, false, std::string("RayGenSimple")},
                                 {"id", T::String, "id"},
                                 {"solver", T::String, "solver id"},
                                 {"maxnumpoints", T::Int, "maximal number of ray points", false, false, 3000.0,
                                  ParamRange{2, std::numeric_limits<double>::infinity(), false, true}}};
  const auto box = bounding_box_keys();
  keys.insert(keys.end(), box.begin(), box.end());
  return keys;
}

std::vector<ParamSpec> keys_local_tetrad(const std::string&) {
  using T = ParamType;
  std::vector<ParamSpec> keys = {{"id", T::String, "id"}, {"metric", T::String, "metric id"}};
  const auto& tetrad = tetrad_param_specs();
  keys.insert(keys.end(), tetrad.begin(), tetrad.end());
  return keys;
}

std::vector<ParamSpec> keys_init_projector(const std::string&) {
  using T = ParamType;
  std::vector<ParamSpec> keys = {
      {"id", T::String, "id"},
      {"raygen", T::String, "ray generator id"},
      {"localtetrad", T::String, "observer's local tetrad id"},
      {"motion", T::String, "observer's motion id"},
      {"actualpos", T::Int, "point of the motion the observer is at", false, false, 0.0, ParamRange::non_negative()},
      {"color", T::Vec3, "background colour", false, false, std::vector<double>{0, 0, 0}},
      {"errcolor", T::Vec3, "colour of rays stopped by an integration error (default: the background)"},
      {"cstrcolor", T::Vec3, "colour of rays stopped by the constraint check (default: black)"},
      {"breakcolor", T::Vec3, "colour of rays stopped by the metric's break condition (default: cstrcolor, else black)"}};
  // The observer's own tetrad, instead of localtetrad.
  const auto tetrad = tetrad_param_specs({"pos", "e0", "e1", "e2", "e3", "incoords", "localframe"});
  keys.insert(keys.end(), tetrad.begin(), tetrad.end());
  return keys;
}

std::vector<ParamSpec> keys_init_device(const std::string&) {
  using T = ParamType;
  return {{"type", T::String, "standard or standard_manual"},
          {"id", T::String, "id"},
          {"camera", T::String, "camera id"},
          {"projector", T::String, "projector id"},
          {"metric", T::String, "metric id"},
          {"lightmgr", T::String, "light manager id"},
          {"obj", T::String, "scene object id"},
          {"setparam", T::List, "(\"objID\" \"param\" value)", false, true}};
}

std::vector<ParamSpec> keys_set_changeobj(const std::string&) {
  using T = ParamType;
  return {{"device", T::String, "device id", true}, {"setparam", T::List, "(\"objID\" \"param\" value)", false, true}};
}

std::vector<ParamSpec> keys_add_object(const std::string&) {
  using T = ParamType;
  return {{"add-to", T::String, "compound id", true}, {"obj", T::String, "object id", false, true}};
}

std::vector<ParamSpec> keys_calc_ray(const std::string&) {
  using T = ParamType;
  return {{"filename", T::String, "output file", true},
          {"raygen", T::String, "ray generator id"},
          {"locted", T::String, "local tetrad id"},
          {"pos", T::Any, "start position"},
          {"dir", T::Vec2, "direction (ksi, chi) in degrees"}};
}

std::vector<ParamSpec> keys_calc_proj_ray(const std::string&) {
  using T = ParamType;
  return {{"filename", T::String, "output file", true},
          {"raygen", T::String, "ray generator id"},
          {"projector", T::String, "projector id"},
          {"dir", T::Vec3, "local direction"},
          {"cartesian", T::Bool, "write Cartesian coordinates"}};
}

std::vector<ParamSpec> keys_gvs_print_motion(const std::string&) {
  using T = ParamType;
  return {{"id", T::String, "motion id", true}, {"file", T::String, "output file", true}};
}

std::vector<ParamSpec> keys_gvs_print(const std::string&) {
  using T = ParamType;
  return {{"id", T::String, "id", true}};
}

// ---- keys and types that live with their factories ----------------------------------------------

std::vector<ParamSpec> keys_init_metric(const std::string& type) {
  std::vector<ParamSpec> keys = {{"type", ParamType::String, "metric name (geovis metrics)", true},
                                 {"id", ParamType::String, "id"}};
  if (type.empty()) return keys;
  const auto metric = make_metric(type);
  for (const MetricParam& p : metric->info().params) keys.push_back({p.name, ParamType::Number, p.doc});
  return keys;
}

std::vector<std::string> solver_types() { return SolverRegistry::instance().names(); }

/// The entry of `type` in a registry (core/type_registry.h), as the base every entry shares.
template <class Registry>
const TypeDescription* registry_entry(const std::string& type) {
  return Registry::instance().find(type);
}
/// What a per-frame change may set, as the type's registry entry lists it.
template <class Registry>
std::vector<std::string> registry_changeable(const std::string& type) {
  const auto* e = Registry::instance().find(type);
  return e ? e->changeable : std::vector<std::string>{};
}

std::vector<ParamSpec> keys_init_camera(const std::string& type) {
  return camera_param_specs(type.empty() ? "PinHoleCam" : type);
}
std::vector<std::string> camera_types() { return camera_type_names(); }
std::vector<ParamSpec> keys_init_texture(const std::string& type) { return texture_keys(type); }
std::vector<ParamSpec> keys_init_shader(const std::string& type) { return shader_keys(type); }
std::vector<std::string> shader_type_list() { return shader_types(); }
std::vector<ParamSpec> keys_init_light(const std::string& type) { return light_keys(type); }
std::vector<std::string> light_type_list() { return light_types(); }
std::vector<ParamSpec> keys_init_light_mgr(const std::string&) { return light_manager_keys(); }
std::vector<ParamSpec> keys_init_motion(const std::string& type) { return motion_param_specs(type); }
std::vector<std::string> raygen_types() { return {"RayGenSimple"}; }
std::vector<std::string> device_types() { return {"standard", "standard_manual"}; }

// ---- what a per-frame change may set (docs/geovis-catalogue.md §10) ----------------------------

std::vector<std::string> tetrad_changeable(const std::string&) {
  return {"pos", "time", "e0", "e1", "e2", "e3", "localvel", "calc"};
}
std::vector<std::string> projector_changeable(const std::string&) { return {"actualpos"}; }

/// The scene command of an object type registered beside its class (render/object_type.h).
SceneCommand object_command(const ObjectType& t) {
  SceneCommand c{t.name, t.container ? CommandRole::Container : CommandRole::Definition, DefinitionKind::Object,
                 t.geovis_extension, t.doc};
  c.keys = [&t](const std::string&) { return t.keys; };
  c.changeable = [&t](const std::string&) { return t.changeable; };
  return c;
}

}  // namespace

const std::vector<SceneCommand>& scene_commands() {
  using R = CommandRole;
  using K = DefinitionKind;
  using C = Changeable;
  static const std::vector<SceneCommand> commands = [] {
    std::vector<SceneCommand> list = {
        {"init-metric", R::Definition, K::Metric, false,
         "the spacetime: `type` names a metric, its parameters are keys", keys_init_metric, metric_names,
         C::TypeParameters},
        {"init-solver", R::Definition, K::Solver, false, "the geodesic integrator and its step control",
         keys_init_solver, solver_types, C::Listed, nullptr, registry_entry<SolverRegistry>},
        {"init-camera", R::Definition, K::Camera, false, "the camera: type, resolution, field of view, filter",
         keys_init_camera, camera_types, C::TypeParameters, nullptr, registry_entry<CameraRegistry>},
        {"init-raygen", R::Definition, K::RayGen, false, "the ray generator: solver, bounding box, maximal points",
         keys_init_raygen, raygen_types},
        {"init-projector", R::Definition, K::Projector, false,
         "the observer: local tetrad or motion, background colours", keys_init_projector, nullptr, C::Listed,
         projector_changeable},
        {"local-tetrad", R::Definition, K::Tetrad, false, "a local tetrad (observer frame) at an event",
         keys_local_tetrad, nullptr, C::Listed, tetrad_changeable},
        {"init-light-mgr", R::Definition, K::LightMgr, false, "ambient and diffuse light, point lights, shadows",
         keys_init_light_mgr},
        {"init-light", R::Definition, K::Light, false, "a point light", keys_init_light, light_type_list, C::Listed,
         nullptr, registry_entry<LightRegistry>},
        {"init-texture", R::Definition, K::Texture, false, "a texture (colour, checker, gradient, image, ...)",
         keys_init_texture, texture_types, C::Listed, registry_changeable<TextureRegistry>,
         registry_entry<TextureRegistry>},
        {"init-shader", R::Definition, K::Shader, false, "a surface shader: object colour, normal map, reflectances",
         keys_init_shader, shader_type_list, C::Listed, nullptr, registry_entry<ShaderRegistry>},
        {"add-object", R::Modifier, K::Object, false, "adds objects to a comp-object or comp-octree-object",
         keys_add_object},
        {"init-motion", R::Definition, K::Motion, false, "a motion: geodesic, constant velocity or world line",
         keys_init_motion, motion_type_names, C::Listed, nullptr, registry_entry<MotionRegistry>},
        {"init-device", R::Device, K::Object, false,
         "one image or sequence: camera, projector, scene, per-frame changes", keys_init_device, device_types},
        {"set-parameter", R::Modifier, K::Object, false,
         "changes parameters of the definition `id`: every other key is a parameter name and its new value"},
        {"set-changeobj", R::Modifier, K::Object, false, "adds per-frame changes to an earlier device",
         keys_set_changeobj},
        {"gvs-print-motion", R::Action, K::Object, false, "writes a motion's points to a file", keys_gvs_print_motion},
        {"calc-ray", R::Action, K::Object, false, "writes one light ray from a tetrad and direction to a file",
         keys_calc_ray},
        {"calc-proj-ray", R::Action, K::Object, false,
         "writes the light ray of a projector's local direction to a file", keys_calc_proj_ray},
        {"gvs-print", R::Action, K::Object, false, "prints a definition", keys_gvs_print},
        {"get-parameter", R::Immediate, K::Object, false, "the value of a definition's parameter"},
        {"vec3", R::Immediate, K::Object, false, "a 3-vector #(x y z)"},
        {"vec4", R::Immediate, K::Object, false, "a 4-vector #(t x y z)"},
        {"translate-obj", R::Immediate, K::Object, false, "a translation matrix"},
        {"rotate-obj", R::Immediate, K::Object, false, "a rotation matrix (axis, angle in degrees)"},
        {"scale-obj", R::Immediate, K::Object, false, "a scaling matrix"},
        {"m4d-metriclist", R::Immediate, K::Object, false, "prints the metric names"},
        {"m4d-solverlist", R::Immediate, K::Object, false, "prints the integrator names"},
    };
    // The object commands, after the other definitions they refer to (catalogue §1 order).
    auto at = std::find_if(list.begin(), list.end(), [](const SceneCommand& c) { return c.name == "init-shader"; }) + 1;
    for (const ObjectType* t : ObjectRegistry::instance().entries()) at = list.insert(at, object_command(*t)) + 1;
    return list;
  }();
  return commands;
}

const SceneCommand* find_scene_command(std::string_view name) {
  for (const SceneCommand& c : scene_commands())
    if (c.name == name) return &c;
  return nullptr;
}

std::vector<std::string> scene_command_list() {
  std::vector<std::string> names;
  for (const SceneCommand& c : scene_commands()) names.emplace_back(c.name);
  return names;
}

const std::vector<std::pair<std::string, std::string>>& scene_constant_bindings() {
  // Defined in scheme_prelude.cpp (GeoViS Parser/init.scm), bound under these names in a scene.
  static const std::vector<std::pair<std::string, std::string>> bindings = {
      {"gpobjtypelocal", "gpobjtypelocal"},
      {"gpobjtypeincoords", "gpobjtypeincoords"},
      {"gpcsgdifferobj", "gpcsgdifferobj"},
      {"gpcsgunifiedobj", "gpcsgunifiedobj"},
      {"gpcsgintersecobj", "gpcsgintersecobj"},
      {"gptetraddefault", "gptetraddefault"},
      {"gptetradstatic", "gptetradstatic"},
      {"gptetradlnrf", "gptetradlnrf"},
      {"gptetradfreefall", "gptetradfreefall"},
      {"gptetradcomoving", "gptetradcomoving"},
      {"gptetradcylinder", "gptetradcylinder"},
      {"gptetradcartesian", "gptetradcartesian"},
      {"pi", "pi"},
      {"pihalf", "pihalf"},
      {"pi2", "pi2"},
      {"gpdblmax", "gpdblmax"},
      {"deg_to_rad", "deg_to_rad"},
      {"rad_to_deg", "rad_to_deg"},
      {"radians", "radians"},
      {"degrees", "degrees"},
      {"calchfov", "calchfov"},
      {"do", "gv-do"},
      {"load", "gv-load"},
      {"exit", "gv-exit"},
      {"quit", "gv-quit"},
      {"primitive-exit", "gv-exit"},
      {"primitive-_exit", "gv-exit"},
      {"getenv", "gv-getenv"},
  };
  return bindings;
}

std::string scheme_command_definitions() {
  std::string text = ";; Generated from scene_commands() (command_table.cpp).\n";
  for (const SceneCommand& c : scene_commands())
    text += "(%gv-define-command " + std::string(c.name) + " \"" + std::string(c.name) + "\")\n";
  text += "(define %gv-scene-bindings\n  '(";
  for (const auto& [scene_name, prelude_name] : scene_constant_bindings())
    text += "(" + scene_name + " . " + prelude_name + ")\n    ";
  for (const SceneCommand& c : scene_commands())
    text += "(" + std::string(c.name) + " . " + std::string(c.name) + ")\n    ";
  text += "))\n";
  return text;
}

}  // namespace geovis
