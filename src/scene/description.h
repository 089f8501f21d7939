// The evaluated scene: every GeoViS command call in the order the Scheme program made it, each as
// a plain parameter set (pbrt-v4 style: the scene language is turned into parameter sets before
// any rendering object is built). Produced by scene/scheme_* (Guile), consumed by
// scene/builder (which creates metrics, cameras, objects, ... per device/frame).
#pragma once

#include <string>
#include <vector>

#include "core/params.h"

namespace geovis {

struct CommandCall {
  /// GeoViS command name, e.g. "init-metric", "solid-ellipsoid", "init-device", "set-parameter".
  /// params.command() is the same name; params.loc() is where the call was made.
  std::string command;
  /// The call's '(key value) pairs, keys lower-cased, in order (repeated keys kept, e.g.
  /// `texture`, `obj`, `light`, `setparam`). The object's id is the `id` key; when the scene gave
  /// none, the evaluator adds a generated one ("unknownN", as GeoViS) so every call has an id.
  ParamSet params;
};

struct SceneDescription {
  std::string file;                ///< the scene file (as given)
  std::string dir;                 ///< its folder (for relative texture and mesh paths)
  std::vector<CommandCall> calls;  ///< in evaluation order
};

}  // namespace geovis
