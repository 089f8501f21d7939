#include <algorithm>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

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
  if (!has_command) args.insert(args.begin() + 1, "render");
  std::vector<const char*> cargs;
  for (auto& a : args) cargs.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(cargs.size()), cargs.data());
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const Error& e) {
    std::cerr << "geovis: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "geovis: internal error: " << e.what() << "\n";
    return 2;
  }
  return opts.exit_code;
}

}  // namespace geovis::cli
