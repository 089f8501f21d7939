// The description of a texture type (core/type_registry.h): each texture's file registers one
// TextureType with its keys, defaults (docs/geovis-catalogue.md §5), what a per-frame change may
// set and its factory. make_texture (render/plugins.h) adds the keys every texture has (type, id,
// transform), checks the keys and builds it.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "core/param_reader.h"
#include "core/type_registry.h"
#include "render/build_context.h"
#include "render/textures.h"

namespace geovis {

struct TextureType : TypeDescription {
  /// The texture from its keys (absent keys read as their defaults); referenced ids resolve in ctx.
  std::shared_ptr<Texture2D> (*make)(const ParamReader& keys, BuildContext& ctx) = nullptr;
};
using TextureRegistry = TypeRegistry<TextureType>;

/// type, id, transform: the keys every texture has.
std::vector<ParamSpec> texture_common_keys();
/// `texture`, given twice: the two textures a combining texture (checker, die, ...) alternates.
ParamSpec two_textures_key();
/// The two textures of two_textures_key(); another count is a SceneError.
std::pair<TexturePtr, TexturePtr> two_textures(const ParamSet& ps, BuildContext& ctx);

}  // namespace geovis
