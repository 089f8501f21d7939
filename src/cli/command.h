// Subcommands of the `geovis` program register themselves (one file per subcommand in src/cli/).
#pragma once

// CLI11 is a large header (about 10 s of compile time per file that includes it): only the
// subcommand files include it, not the tests and main.cpp, which only call run().
namespace CLI {
class App;
}

namespace geovis::cli {

/// The program version (`geovis --version`, the data files' header).
inline constexpr const char* kVersion = "0.1.0";

struct GlobalOptions {
  bool quiet = false;
  bool verbose = false;
  int exit_code = 0;  ///< set by the subcommand's callback
};

/// Adds the subcommand to `app`; its callback runs the command and sets opts.exit_code.
using CommandSetup = void (*)(CLI::App& app, GlobalOptions& opts);

/// Registers a subcommand (call from a namespace-scope initializer in the command's file, named
/// `<command>_registered` with the setup function `setup_<command>`: the command files are compiled
/// as one unity unit, CMakeLists.txt).
bool register_command(const char* name, CommandSetup setup);

/// Runs the program (also used by tests). No arguments = `geovis render` of the built-in scene.
int run(int argc, const char* const* argv);

}  // namespace geovis::cli
