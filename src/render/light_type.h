// The description of a light type (core/type_registry.h): each light's file registers one
// LightType with its keys, defaults (docs/geovis-catalogue.md §7) and factory; make_point_light
// (render/plugins.h) adds type and id, checks the keys and builds it.
#pragma once

#include "core/param_reader.h"
#include "core/type_registry.h"
#include "render/build_context.h"
#include "render/shader.h"

namespace geovis {

struct LightType : TypeDescription {
  /// The light from its keys (absent keys read as their defaults).
  PointLight (*make)(const ParamReader& keys) = nullptr;
};
using LightRegistry = TypeRegistry<LightType>;

}  // namespace geovis
