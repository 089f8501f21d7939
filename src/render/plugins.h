// Factories for the scene objects, textures, shaders and lights of a GeoViS scene
// (docs/geovis-catalogue.md §1, §4–§7). The types are registered beside their classes
// (render/object_type.h, texture_type.h, shader_type.h, light_type.h); each factory looks the type
// up, validates the ParamSet against its keys (unknown keys warn with the closest valid key; wrong
// shapes, numbers outside a key's range and missing required keys are SceneErrors
// "file:line: command: key: ..."), reads absent keys as their defaults and resolves referenced ids
// through the BuildContext. The caller (scene builder) stores the results under their `id`.
#pragma once

#include <string>
#include <vector>

#include "core/params.h"
#include "render/build_context.h"
#include "render/object.h"
#include "render/shader.h"
#include "render/texture.h"

namespace geovis {

/// init-texture: the registered texture types (GeoViS: UniTex, CheckerT2D, ChequeredT2D, ChequeredTimeT2D,
/// DieT2D, ColorGradTex, Image).
TexturePtr make_texture(const ParamSet& ps, BuildContext& ctx);
/// init-shader: SurfShader.
ShaderPtr make_shader(const ParamSet& ps, BuildContext& ctx);
/// The registered object command named by ps.command() (solid-ellipsoid, mesh-obj, csg-object, ...).
SceneObjectPtr make_object(const ParamSet& ps, BuildContext& ctx);
/// init-light (type PointLight).
PointLight make_point_light(const ParamSet& ps, BuildContext& ctx);
/// init-light-mgr.
LightManager make_light_manager(const ParamSet& ps, BuildContext& ctx);

/// Registered names (sorted), for error messages and listings.
std::vector<std::string> texture_types();
std::vector<std::string> shader_types();
std::vector<std::string> object_commands();
std::vector<std::string> light_types();

/// The key specs of each factory (for documentation/listings); `what` is a texture type, shader
/// type, light type or object command. Empty when unknown.
std::vector<ParamSpec> texture_keys(const std::string& type);
std::vector<ParamSpec> object_keys(const std::string& command);
std::vector<ParamSpec> shader_keys(const std::string& type);  ///< "" = the default type
std::vector<ParamSpec> light_keys(const std::string& type);   ///< "" = the default type
std::vector<ParamSpec> light_manager_keys();

}  // namespace geovis
