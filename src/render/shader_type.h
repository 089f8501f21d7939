// The description of a shader type (core/type_registry.h): each shader's file registers one
// ShaderType with its keys, defaults (docs/geovis-catalogue.md §6) and factory; make_shader
// (render/plugins.h) adds type and id, checks the keys and builds it.
#pragma once

#include "core/param_reader.h"
#include "core/type_registry.h"
#include "render/build_context.h"
#include "render/shader.h"

namespace geovis {

struct ShaderType : TypeDescription {
  /// The shader from its keys (absent keys read as their defaults); texture ids resolve in ctx.
  ShaderPtr (*make)(const ParamReader& keys, BuildContext& ctx) = nullptr;
};
using ShaderRegistry = TypeRegistry<ShaderType>;

}  // namespace geovis
