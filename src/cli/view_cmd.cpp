// `geovis view DATA [--port P] [--scene FILE] [--quiet]`
//
// Explore a data file in the browser (the paper's §5 gvsViewer, with its outlook's link to the
// geodesic: click a pixel to see its light ray). DATA is an OpenEXR data file, a folder of frames,
// or a GeoViS .pdz/.jac/.pt/.dat file. Serves the page on 127.0.0.1 only (cli/view_server.h) and
// runs until Ctrl-C (or SIGTERM), which stops it cleanly with exit status 0.
#include <chrono>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "cli/interrupt.h"
#include "cli/view_server.h"
#include "core/error.h"

namespace geovis::cli {

namespace {

struct ViewArgs {
  std::string data;
  int port = 8765;
  std::string scene;
  bool quiet = false;
};

int run_view(const ViewArgs& a, const GlobalOptions& g) {
  if (view_assets().empty())
    throw Error(std::string("the viewer's page is not part of this build: ") + view_page_missing_reason() +
                "; install Node.js and npm (scripts/setup.sh) and configure and build geovis again");
  ViewServer server(find_view_frames(a.data), view_assets(), a.scene);
  server.load_first_frame();
  const int port = server.bind(a.port);
  InterruptHandler interrupt;
  bool ok = true;
  std::thread listener([&server, &ok] { ok = server.run(); });
  if (!(a.quiet || g.quiet)) {
    std::cout << "geovis view: http://127.0.0.1:" << port << "/  (Ctrl-C stops; over SSH: ssh -L " << port
              << ":127.0.0.1:" << port << " HOST)" << std::endl;
  }
  while (!interrupt.flag()->load()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  server.stop();
  listener.join();
  if (!(a.quiet || g.quiet)) std::cerr << "geovis view: stopped" << std::endl;
  if (!ok) throw Error("the server on 127.0.0.1:" + std::to_string(port) + " failed");
  return 0;
}

void setup_view(CLI::App& app, GlobalOptions& g) {
  auto a = std::make_shared<ViewArgs>();
  CLI::App* sub = app.add_subcommand(
      "view", "explore a data file in the browser: channels, colour maps, post shaders, and each pixel's light ray");
  sub->add_option("data", a->data,
                  "the .exr of geovis render --data, a folder of frames, or a GeoViS .pdz/.jac/.pt/.dat")
      ->required();
  sub->add_option("--port", a->port, "port on 127.0.0.1 (0 = any free port)")->capture_default_str();
  sub->add_option("--scene", a->scene,
                  "scene file for the rays (default: the one the data file names; its hash must match)");
  sub->add_flag("-q,--quiet", a->quiet, "print nothing but errors");
  sub->callback([a, &g]() { g.exit_code = run_view(*a, g); });
}

const bool view_registered = register_command("view", &setup_view);

}  // namespace

}  // namespace geovis::cli
