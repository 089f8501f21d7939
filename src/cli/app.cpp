#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/error.h"

namespace geovis::cli {

namespace {
std::vector<std::pair<const char*, CommandSetup>>& registry() {
  static std::vector<std::pair<const char*, CommandSetup>> r;
  return r;
}
}  // namespace

bool register_command(const char* name, CommandSetup setup) {
  registry().emplace_back(name, setup);
  return true;
}

int run(int argc, const char* const* argv) {
  CLI::App app{"geovis - general-relativistic ray tracer (GeoViS-compatible scenes)"};
  app.footer(
      "geovis [render options] [SCENE] is geovis render: without SCENE it renders the built-in scene.\n"
      "geovis SUBCOMMAND --help describes a subcommand's options.");
  app.set_version_flag("--version", std::string("geovis ") + kVersion);
  GlobalOptions opts;
  app.add_flag("-q,--quiet", opts.quiet, "print nothing but errors");
  app.add_flag("-v,--verbose", opts.verbose, "print details (warnings, statistics)");
  auto cmds = registry();
  std::sort(cmds.begin(), cmds.end(), [](auto& a, auto& b) { return std::strcmp(a.first, b.first) < 0; });
  for (auto& [name, setup] : cmds) setup(app, opts);
  app.require_subcommand(0, 1);
  app.fallthrough();  // global options may follow the subcommand

  // Without a subcommand, `geovis [OPTIONS] [SCENE]` means `geovis render [OPTIONS] [SCENE]`
  // (README's first command renders the built-in scene).
  std::vector<std::string> args(argv, argv + argc);
  bool has_command = false;
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-h" || a == "--help" || a == "--version") has_command = true;
    for (auto& [name, setup] : cmds) has_command = has_command || a == name;
  }
  if (!has_command && args.size() > 1 && !args[1].empty() && args[1][0] != '-') {
    // `geovis rendr x.scm`: a first word that is no file and no scene name is a mistyped command.
    const std::string& word = args[1];
    std::error_code ec;
    if (!std::filesystem::exists(word, ec) && to_lower(std::filesystem::path(word).extension().string()) != ".scm") {
      std::vector<std::string> names;
      for (auto& [name, setup] : cmds) names.emplace_back(name);
      std::cerr << "geovis: error: \"" << word << "\" is neither a subcommand (" << join(names) << ") nor a scene file"
                << did_you_mean(word, names) << "\n";
      return 1;
    }
  }
  if (!has_command) args.insert(args.begin() + 1, "render");
  std::vector<const char*> cargs;
  for (auto& a : args) cargs.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(cargs.size()), cargs.data());
  } catch (const CLI::ParseError& e) {
    // --help and --version end the parse with success; every other parse error is reported as
    // geovis reports errors.
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "geovis: error: " << e.what() << " (--help lists the options)\n";
    return 1;
  } catch (const Error& e) {
    std::cerr << "geovis: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    // Sizes are checked against the memory before rendering (render/frame_limits.h); this is
    // what is left (a scene that builds a huge mesh, memory taken by other programs).
    std::cerr << "geovis: error: out of memory (the scene or the resolution needs more memory than is "
                 "available; lower --res or --supersample, or simplify the scene)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "geovis: error: internal error: " << e.what() << "\n";
    return 2;
  }
  return opts.exit_code;
}

}  // namespace geovis::cli
