// The options of every command that evaluates a scene (render, check): the sandbox and its limits
// (docs/security.md) and --define, and the checks that render and check share, so that `check`
// reports the errors `render` would.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "scene/builder.h"
#include "scene/scheme.h"

namespace geovis::cli {

struct SceneArgs {
  std::vector<std::string> defines;      ///< --define NAME=VALUE
  std::vector<std::string> scene_paths;  ///< --scene-path DIR
  bool trust_scene = false;              ///< --trust-scene
  double time_limit_seconds = SchemeOptions{}.time_limit_seconds;
  double memory_limit_mib = static_cast<double>(SchemeOptions{}.memory_limit_bytes >> 20);
};

/// Adds --define, --scene-path, --trust-scene, --scene-time-limit and --scene-memory-limit.
void add_scene_options(CLI::App* sub, SceneArgs& args);

/// The evaluation options; throws Error for a malformed --define or a missing --scene-path folder.
/// `quiet` (-q) also discards what the scene prints.
SchemeOptions scheme_options(const SceneArgs& args, Diagnostics* diag, bool quiet);

/// The files of the scene's actions (gvs-print-motion, calc-ray, calc-proj-ray) go to the current
/// folder, as GeoViS writes them, and (unless the scene is trusted) only below it.
void set_action_output(BuildOptions& bopts, const SceneArgs& args);

/// Throws the error `render` gives for a scene it cannot render (no init-device).
void require_devices(const SceneBuilder& builder);

}  // namespace geovis::cli
