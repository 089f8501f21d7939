// `geovis reference [-o FILE]`: the scene reference (every command, type and key; the text of
// docs/scene-reference.md) from the command table, on standard output or written atomically.
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "io/atomic_file.h"
#include "scene/scene_reference.h"

namespace geovis::cli {

namespace {

void setup_reference(CLI::App& app, GlobalOptions& g) {
  auto out = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand("reference", "print the scene reference: every command, type and key (Markdown)");
  sub->add_option("-o,--output", *out, "write it to this file instead of standard output");
  sub->callback([out, &g]() {
    const std::string text = scene_reference_markdown();
    if (out->empty()) {
      std::cout << text;
    } else {
      write_file_atomic(*out, text);
      if (!g.quiet) std::cerr << "geovis: wrote " << *out << "\n";
    }
    g.exit_code = 0;
  });
}

const bool reference_registered = register_command("reference", &setup_reference);

}  // namespace

}  // namespace geovis::cli
