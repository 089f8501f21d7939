// Factories for the scene objects, textures, shaders and lights of a GeoViS scene (catalogue §1,
// §4–§7). Each reads a ParamSet (keys, types and defaults of the catalogue), validates it
// (unknown keys warn with the closest valid key; wrong shapes and missing required keys are
// SceneErrors "file:line: command: key: ...") and resolves referenced ids through the
// BuildContext. The caller (scene builder) stores the results under their `id`.
#pragma once

#include <string>
#include <vector>

#include "core/params.h"
#include "render/build_context.h"
#include "render/object.h"
#include "render/shader.h"
#include "render/texture.h"

namespace geovis {

/// init-texture: UniTex, CheckerT2D, ChequeredT2D, ChequeredTimeT2D, DieT2D, ColorGradTex, Image.
TexturePtr make_texture(const ParamSet& ps, BuildContext& ctx);
/// init-shader: SurfShader.
ShaderPtr make_shader(const ParamSet& ps, BuildContext& ctx);
/// solid-ellipsoid, solid-box, solid-cylinder, solid-ring, solid-background, plane-ring,
/// plane-triangle, plane-parallelogram, mesh-obj, csg-object, comp-object, comp-octree-object,
/// local-comp-object (dispatch on ps.command()).
SceneObjectPtr make_object(const ParamSet& ps, BuildContext& ctx);
/// init-light (type PointLight).
PointLight make_point_light(const ParamSet& ps, BuildContext& ctx);
/// init-light-mgr.
LightManager make_light_manager(const ParamSet& ps, BuildContext& ctx);

/// Valid names, for error messages and listings.
std::vector<std::string> texture_types();
std::vector<std::string> shader_types();
std::vector<std::string> object_commands();
std::vector<std::string> light_types();

/// The key specs of each factory (for documentation/listings); `what` is a texture type, shader
/// type, light type or object command. Empty when unknown.
std::vector<ParamSpec> texture_keys(const std::string& type);
std::vector<ParamSpec> object_keys(const std::string& command);
std::vector<ParamSpec> shader_keys();
std::vector<ParamSpec> light_keys();
std::vector<ParamSpec> light_manager_keys();

}  // namespace geovis
