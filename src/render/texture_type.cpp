#include "render/texture_type.h"

namespace geovis {

std::vector<ParamSpec> texture_common_keys() {
  return {{"type", ParamType::String, "texture type: " + join(TextureRegistry::instance().names()), true},
          {"id", ParamType::String, "texture id"},
          {"transform", ParamType::Transform, "2D transform of (u, v) (scale-obj, rotate-obj, translate-obj)"}};
}

ParamSpec two_textures_key() { return {"texture", ParamType::String, "texture id (give two)", true, true}; }

std::pair<TexturePtr, TexturePtr> two_textures(const ParamSet& ps, BuildContext& ctx) {
  const auto ids = ps.get_strings("texture");
  if (ids.size() != 2)
    ps.fail("texture", "expected two texture ids (give the key twice), found " + std::to_string(ids.size()));
  return {ctx.lookup(ctx.textures, ids[0], ps, "texture", "texture"),
          ctx.lookup(ctx.textures, ids[1], ps, "texture", "texture")};
}

}  // namespace geovis
