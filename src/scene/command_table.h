// The commands of the scene language, described once (docs/geovis-catalogue.md §1).
//
// This table is the only list of command names (the object commands come from the registry of
// object types, render/object_type.h, where each object registers itself): the Scheme bindings (scheme_prelude.cpp's
// command macros and scene bindings), the evaluator's "did you mean", the builder's dispatch and key checks, and the
// generated scene reference (docs/scene-reference.md, `geovis reference`) all read it. Adding a command is adding its
// entry here and its handling where its role says.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/params.h"
#include "core/type_registry.h"

namespace geovis {

/// What a definition command defines (the kind of thing its `id` names).
enum class DefinitionKind {
  Metric,
  Solver,
  Camera,
  RayGen,
  Tetrad,
  Projector,
  Light,
  LightMgr,
  Texture,
  Shader,
  Object,
  Motion
};

/// Human-readable name of a kind ("local tetrad", "scene object", ...), for error messages.
const char* definition_kind_name(DefinitionKind k);

enum class CommandRole {
  Definition,  ///< records a call that defines a thing under its `id`
  Container,   ///< a definition whose parts are other objects (built after them)
  Modifier,    ///< records a change to earlier definitions or devices (add-object, set-parameter, ...)
  Device,      ///< init-device: one rendered image/sequence
  Action,      ///< runs when the scene is built, writes a file or prints (calc-ray, gvs-print, ...)
  Immediate,   ///< returns a value to the scene, records nothing (vec3, get-parameter, ...)
};

/// Which names a per-frame change (setparam of init-device/set-changeobj, set-parameter) may use.
enum class Changeable {
  Listed,          ///< the names returned by `changeable(type)`
  TypeParameters,  ///< every parameter of the named type (metric parameters, camera keys)
};

struct SceneCommand {
  std::string_view name;  ///< lower case, as the reader folds symbols
  CommandRole role;
  DefinitionKind kind = DefinitionKind::Object;  ///< for Definition and Container
  bool geovis_extension = false;                 ///< not a GeoViS command
  std::string_view doc;                          ///< one line
  /// Keys the command accepts; `type` is the value of its `type` key (ignored by untyped commands).
  std::function<std::vector<ParamSpec>(const std::string& type)> keys = nullptr;
  /// Valid `type` values (empty for untyped commands).
  std::function<std::vector<std::string>()> types = nullptr;
  Changeable change_rule = Changeable::Listed;
  /// Names a per-frame change may set for a definition of this type (empty: none).
  std::function<std::vector<std::string>(const std::string& type)> changeable = nullptr;
  /// The registry entry of a `type` value (doc, aliases, keys; core/type_registry.h), nullptr for
  /// an unknown type; empty for a command whose types have no registry.
  std::function<const TypeDescription*(const std::string& type)> describe = nullptr;
};

/// Every command, in catalogue order.
const std::vector<SceneCommand>& scene_commands();

/// The entry of `name` (lower case), nullptr when there is none.
const SceneCommand* find_scene_command(std::string_view name);

/// Names of every command, for "did you mean" suggestions.
std::vector<std::string> scene_command_list();

/// Names the scene language binds besides the commands (Parser/init.scm constants and helpers)
/// as (name in a scene, name in the prelude).
const std::vector<std::pair<std::string, std::string>>& scene_constant_bindings();

/// The Scheme text that defines every command as a location-recording macro and lists what a
/// scene module gets (%gv-scene-bindings); spliced into the prelude (scheme_prelude.cpp).
std::string scheme_command_definitions();

}  // namespace geovis
