// `geovis check SCENE [--define NAME=VALUE]... [--texture-path DIR]... [--strict]
//   [scene options: cli/scene_options.h]`:
// evaluates the scene, builds every device and runs its actions without rendering or writing a
// file (so every error a render would meet while setting up is found), then prints a summary.
// Exit status 0 when fine.
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "cli/scene_options.h"
#include "core/error.h"
#include "scene/builder.h"
#include "scene/scheme.h"

namespace geovis::cli {

namespace {

namespace fs = std::filesystem;

struct CheckArgs {
  std::string scene;
  std::vector<std::string> texture_paths;
  SceneArgs scene_args;
  bool strict = false;
  bool quiet = false;
};

int run_check(const CheckArgs& a, const GlobalOptions& g) {
  const bool quiet = a.quiet || g.quiet;
  Diagnostics diag;
  diag.strict = a.strict;
  const SchemeOptions sopts = scheme_options(a.scene_args, &diag, quiet);
  for (const auto& dir : a.texture_paths)
    if (!fs::is_directory(dir)) throw Error("--texture-path: \"" + dir + "\" is not a directory");
  if (!fs::exists(a.scene)) throw Error("scene file \"" + a.scene + "\" does not exist");
  SceneDescription scene = evaluate_scene_file(a.scene, sopts);

  BuildOptions bopts;
  const std::string dir = fs::path(a.scene).parent_path().string();
  bopts.search_paths.push_back(dir.empty() ? "." : dir);
  for (const auto& t : a.texture_paths) bopts.search_paths.push_back(t);
  bopts.search_paths.push_back(".");
  bopts.diag = &diag;
  set_action_output(bopts, a.scene_args);
  bopts.write_action_files = false;
  SceneBuilder builder(std::move(scene), bopts);
  require_devices(builder);
  int images = 0;
  for (int d = 0; d < builder.device_count(); ++d) images += static_cast<int>(builder.build(d).size());
  std::ostringstream action_log;  // gvs-print output: what render prints, not a check result
  builder.run_actions(action_log);
  if (!quiet) {
    std::set<std::string> printed;  // a camera rebuilt for every frame repeats its warnings
    for (const auto& w : diag.warnings())
      if (printed.insert(w).second) std::cerr << w << "\n";
    std::cout << builder.summary();
    std::cout << "images:   " << images << "\n";
    std::cout << "ok\n";
  }
  return 0;
}

void setup_check(CLI::App& app, GlobalOptions& g) {
  auto a = std::make_shared<CheckArgs>();
  CLI::App* sub = app.add_subcommand("check", "evaluate a scene and build every frame without rendering");
  sub->add_option("scene", a->scene, "GeoViS scene file (.scm)")->required();
  sub->add_option("--texture-path", a->texture_paths,
                  "extra folder to search for textures and meshes (a file the scene names by a path that "
                  "does not exist here is looked up by its file name)")
      ->allow_extra_args(false);
  add_scene_options(sub, a->scene_args);
  sub->add_flag("--strict", a->strict, "treat warnings (unknown keys, ...) as errors");
  sub->add_flag("-q,--quiet", a->quiet, "print nothing but errors");
  sub->callback([a, &g]() {
    try {
      g.exit_code = run_check(*a, g);
    } catch (const SceneExit& e) {
      // The scene called (exit [code]): GeoViS stops there without rendering. Not an error;
      // the exit status is the scene's code.
      if (!(a->quiet || g.quiet)) std::cerr << "geovis: " << e.what() << "\n";
      g.exit_code = e.code();
    }  // other errors reach run() (app.cpp), which reports them and sets the exit status
  });
}

const bool check_registered = register_command("check", &setup_check);

}  // namespace

}  // namespace geovis::cli
