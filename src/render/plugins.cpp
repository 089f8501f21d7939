// The factories of init-texture, init-shader, init-light, init-light-mgr and the object commands.
// The types themselves — their names, keys, defaults and constructors — are registered beside
// their classes (render/texture_type.h, shader_type.h, light_type.h, object_type.h); this file
// adds the keys every type of a kind has, checks a command's keys and calls the type's factory.
#include "render/plugins.h"

#include "core/param_reader.h"
#include "render/light_type.h"
#include "render/object_type.h"
#include "render/shader_type.h"
#include "render/texture_type.h"

namespace geovis {

namespace {

std::vector<ParamSpec> with(std::vector<ParamSpec> a, const std::vector<ParamSpec>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

Color color3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

/// type and id: the keys of every shader and light. GeoViS's init-shader and init-light default
/// `type` to their only type (SurfShader, PointLight).
std::vector<ParamSpec> typed_keys(std::string_view what, std::string def_type, const std::vector<ParamSpec>& own) {
  return with({{"type", ParamType::String, std::string(what) + " type", false, false, std::move(def_type)},
               {"id", ParamType::String, std::string(what) + " id"}},
              own);
}

}  // namespace

// ---- textures -----------------------------------------------------------------------------------

std::vector<std::string> texture_types() { return TextureRegistry::instance().names(); }

std::vector<ParamSpec> texture_keys(const std::string& type) {
  const TextureType* t = TextureRegistry::instance().find(type);
  return t ? with(texture_common_keys(), t->keys) : std::vector<ParamSpec>{};
}

TexturePtr make_texture(const ParamSet& ps, BuildContext& ctx) {
  const TextureType& type = TextureRegistry::instance().get(ps, "type", ps.get_string("type"), "texture type");
  const std::vector<ParamSpec> specs = with(texture_common_keys(), type.keys);
  ps.validate(specs, ctx.diagnostics());
  std::shared_ptr<Texture2D> tex = type.make(ParamReader(ps, specs), ctx);
  if (ps.has("transform")) tex->uv_transform = UVTransform::from(ps.get_transform("transform"));
  return tex;
}

// ---- shaders and lights -------------------------------------------------------------------------

std::vector<std::string> shader_types() { return ShaderRegistry::instance().names(); }
std::vector<std::string> light_types() { return LightRegistry::instance().names(); }

std::vector<ParamSpec> shader_keys(const std::string& type) {
  const ShaderType* t = ShaderRegistry::instance().find(type.empty() ? "SurfShader" : type);
  return t ? typed_keys("shader", "SurfShader", t->keys) : std::vector<ParamSpec>{};
}

std::vector<ParamSpec> light_keys(const std::string& type) {
  const LightType* t = LightRegistry::instance().find(type.empty() ? "PointLight" : type);
  return t ? typed_keys("light", "PointLight", t->keys) : std::vector<ParamSpec>{};
}

std::vector<ParamSpec> light_manager_keys() {
  return {{"id", ParamType::String, "light manager id"},
          {"ambient", ParamType::Vec3, "ambient light", false, false, std::vector<double>{1, 1, 1}},
          {"diffuse", ParamType::Vec3, "diffuse light from the observer", false, false, std::vector<double>{1, 1, 1}},
          {"light", ParamType::String, "light id", false, true},
          {"shadows", ParamType::Bool, "point-light shadow rays (Minkowski only)", false, false, false}};
}

ShaderPtr make_shader(const ParamSet& ps, BuildContext& ctx) {
  const ShaderType& type =
      ShaderRegistry::instance().get(ps, "type", ps.get_string("type", "SurfShader"), "shader type");
  const std::vector<ParamSpec> specs = typed_keys("shader", "SurfShader", type.keys);
  ps.validate(specs, ctx.diagnostics());
  return type.make(ParamReader(ps, specs), ctx);
}

PointLight make_point_light(const ParamSet& ps, BuildContext& ctx) {
  const LightType& type = LightRegistry::instance().get(ps, "type", ps.get_string("type", "PointLight"), "light type");
  const std::vector<ParamSpec> specs = typed_keys("light", "PointLight", type.keys);
  ps.validate(specs, ctx.diagnostics());
  return type.make(ParamReader(ps, specs));
}

LightManager make_light_manager(const ParamSet& ps, BuildContext& ctx) {
  const std::vector<ParamSpec> specs = light_manager_keys();
  ps.validate(specs, ctx.diagnostics());
  const ParamReader keys(ps, specs);
  LightManager m;
  m.ambient = color3(keys.vector("ambient", 3));
  m.diffuse = color3(keys.vector("diffuse", 3));
  for (const auto& id : ps.get_strings("light")) m.lights.push_back(ctx.lookup(ctx.lights, id, ps, "light", "light"));
  m.shadows = keys.boolean("shadows");
  return m;
}

// ---- objects ------------------------------------------------------------------------------------

std::vector<std::string> object_commands() { return ObjectRegistry::instance().names(); }

std::vector<ParamSpec> object_keys(const std::string& command) {
  const ObjectType* t = ObjectRegistry::instance().find(command);
  return t ? t->keys : std::vector<ParamSpec>{};
}

SceneObjectPtr make_object(const ParamSet& ps, BuildContext& ctx) {
  const ObjectType* type = ObjectRegistry::instance().find(ps.command());
  if (!type) ps.fail("", ObjectRegistry::instance().unknown_message(ps.command(), "object command"));
  ps.validate(type->keys, ctx.diagnostics());
  return type->make(ParamReader(ps, type->keys), ctx);
}

}  // namespace geovis
