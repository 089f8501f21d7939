#include "cli/scene_options.h"

#include <cmath>
#include <filesystem>

#include "core/error.h"

namespace geovis::cli {

void add_scene_options(CLI::App* sub, SceneArgs& args) {
  sub->add_option("--define", args.defines, "override a top-level (define NAME ...) of the scene")
      ->allow_extra_args(false);
  sub->add_option("--scene-path", args.scene_paths,
                  "extra folder from which the scene may (load \"file.scm\") (looked up there when not next "
                  "to the loading file)")
      ->allow_extra_args(false);
  sub->add_flag("--trust-scene", args.trust_scene,
                "evaluate the scene with full Guile instead of the sandbox (it may then run programs and "
                "read, write and delete files: only for scenes you trust; see docs/security.md)");
  sub->add_option("--scene-time-limit", args.time_limit_seconds,
                  "seconds the scene's evaluation may take (0 = no limit)")
      ->capture_default_str();
  sub->add_option("--scene-memory-limit", args.memory_limit_mib,
                  "MiB of memory the scene's evaluation may use (0 = no limit)")
      ->capture_default_str();
}

SchemeOptions scheme_options(const SceneArgs& args, Diagnostics* diag, bool quiet) {
  SchemeOptions opts;
  for (const auto& d : args.defines) {
    const size_t eq = d.find('=');
    if (eq == std::string::npos || eq == 0) throw Error("--define: expected NAME=VALUE, found \"" + d + "\"");
    opts.defines.emplace_back(d.substr(0, eq), d.substr(eq + 1));
  }
  for (const auto& dir : args.scene_paths) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) throw Error("--scene-path: \"" + dir + "\" is not a directory");
  }
  if (!(args.time_limit_seconds >= 0) || !std::isfinite(args.time_limit_seconds))
    throw Error("--scene-time-limit: expected a number of seconds >= 0, found " +
                std::to_string(args.time_limit_seconds));
  if (!(args.memory_limit_mib >= 0) || !(args.memory_limit_mib < 1e9))
    throw Error("--scene-memory-limit: expected a number of MiB >= 0, found " + std::to_string(args.memory_limit_mib));
  opts.load_paths = args.scene_paths;
  opts.trusted = args.trust_scene;
  opts.time_limit_seconds = args.time_limit_seconds;
  opts.memory_limit_bytes = static_cast<size_t>(args.memory_limit_mib * 1024 * 1024);
  opts.print_output = !quiet;
  opts.diag = diag;
  return opts;
}

void set_action_output(BuildOptions& bopts, const SceneArgs& args) {
  bopts.output_dir.clear();
  bopts.confine_output = !args.trust_scene;
}

void require_devices(const SceneBuilder& builder) {
  if (builder.device_count() == 0) throw Error("the scene has no init-device: nothing to render");
}

}  // namespace geovis::cli
