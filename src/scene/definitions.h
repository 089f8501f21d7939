// What the scene builder stores while it reads a scene's calls: definitions (with the changes
// made to them), devices and actions, and the command-table questions the builder asks
// (docs/geovis-catalogue.md §1, §10). Internal to src/scene/.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/params.h"
#include "scene/command_table.h"
#include "scene/description.h"

namespace geovis::scene_build {

using Kind = DefinitionKind;

/// The command table's entry of a recorded command (nullptr for a name it does not know).
const SceneCommand* command_entry(const std::string& command);
bool is_definition(const SceneCommand* c);
/// Objects that contain other objects (built after their parts; they consume no objID).
bool is_container(const std::string& command);
/// The keys the builder checks for a call (nullopt: the command's factory checks them).
std::optional<std::vector<ParamSpec>> builder_checked_keys(const SceneCommand& c, const ParamSet& ps);

/// A key whose value is the id of another definition of `kind`.
struct RefKey {
  const char* key;
  Kind kind;
};
const std::vector<RefKey>& ref_keys(Kind k);

// ---- stored definitions ------------------------------------------------------------------------

struct Def {
  Kind kind = Kind::Object;
  std::string id;
  int seq = 0;  ///< index of the creating call
  ParamSet ps;  ///< as called, patched by set-parameter / add-object / this frame's setparams
  /// Metric and camera changes are applied through Metric::set_param / Camera::set_param after
  /// construction (the key is the parameter name); other kinds are patched in `ps`.
  std::vector<Param> changes;
};
using DefPtr = std::shared_ptr<const Def>;
using DefMap = std::map<std::string, DefPtr>;

struct DeviceDef {
  int seq = 0;
  ParamSet ps;                   ///< the init-device call
  std::vector<Param> setparams;  ///< its setparam entries plus set-changeobj additions
  std::shared_ptr<const DefMap> defs;
};

struct ActionDef {
  int seq = 0;
  CommandCall call;
  std::shared_ptr<const DefMap> defs;
};

/// Rethrows `e` as a SceneError at `key` of `ps` (a SceneError passes unchanged).
[[noreturn]] void rethrow_at(const ParamSet& ps, std::string_view key, const std::exception& e);
/// "(v0, v1, ...)".
std::string fmt_vec(const double* v, int n);

}  // namespace geovis::scene_build
