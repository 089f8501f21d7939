#include "scene/definitions.h"

#include <algorithm>
#include <sstream>

namespace geovis::scene_build {

/// The command table's entry of a recorded command (nullptr for a name it does not know).
const SceneCommand* command_entry(const std::string& command) { return find_scene_command(command); }

bool is_definition(const SceneCommand* c) {
  return c && (c->role == CommandRole::Definition || c->role == CommandRole::Container);
}

/// Objects that contain other objects (built after their parts; they consume no objID).
bool is_container(const std::string& command) {
  const SceneCommand* c = command_entry(command);
  return c && c->role == CommandRole::Container;
}

/// Keys the builder checks itself: every command but the definitions whose factory checks its
/// own keys (metrics, cameras, lights, textures, shaders, objects) and set-parameter (whose keys
/// are parameter names). The evaluator gives every call an id (a generated "unknownN" when the
/// scene gave none), so `id` is always accepted. Unknown keys are warnings (errors under
/// --strict) naming the closest valid key; wrong shapes are errors.
std::optional<std::vector<ParamSpec>> builder_checked_keys(const SceneCommand& c, const ParamSet& ps) {
  if (!c.keys) return std::nullopt;
  if (is_definition(&c) && c.kind != Kind::Solver && c.kind != Kind::RayGen && c.kind != Kind::Tetrad &&
      c.kind != Kind::Projector && c.kind != Kind::Motion)
    return std::nullopt;
  std::vector<ParamSpec> keys = c.keys(ps.get_string("type", std::string()));
  if (std::none_of(keys.begin(), keys.end(), [](const ParamSpec& p) { return p.key == "id"; }))
    keys.push_back({"id", ParamType::String, "id"});
  return keys;
}

const std::vector<RefKey>& ref_keys(Kind k) {
  static const std::vector<RefKey> none;
  static const std::vector<RefKey> object = {{"shader", Kind::Shader},      {"motion", Kind::Motion},
                                             {"localtetrad", Kind::Tetrad}, {"obj", Kind::Object},
                                             {"obj1", Kind::Object},        {"obj2", Kind::Object}};
  static const std::vector<RefKey> shader = {{"objcolor", Kind::Texture}, {"normalmap", Kind::Texture}};
  static const std::vector<RefKey> texture = {{"texture", Kind::Texture}};
  static const std::vector<RefKey> lightmgr = {{"light", Kind::Light}};
  switch (k) {
    case Kind::Object: return object;
    case Kind::Shader: return shader;
    case Kind::Texture: return texture;
    case Kind::LightMgr: return lightmgr;
    default: return none;
  }
}

// ---- errors ------------------------------------------------------------------------------------

[[noreturn]] void rethrow_at(const ParamSet& ps, std::string_view key, const std::exception& e) {
  if (dynamic_cast<const SceneError*>(&e)) throw;
  ps.fail(key, e.what());
}

std::string fmt_vec(const double* v, int n) {
  std::ostringstream os;
  os << "(";
  for (int i = 0; i < n; ++i) os << (i ? ", " : "") << v[i];
  os << ")";
  return os.str();
}

}  // namespace geovis::scene_build
