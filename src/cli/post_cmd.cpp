// `geovis post DATA [-o OUT --shader NAME] [--range MIN,MAX] [--log] [--colorbar] [--colormap NAME]
//                [--mass M] [--csv FILE --channels A,B,... --pixel X,Y ...] [--quiet]`
//
// Makes pictures from a data file without re-tracing (paper §5, the gvsViewer shaders): DATA is
// the OpenEXR data file of `geovis render --data` (or of a data filter) or a GeoViS .pdz/.jac/.pt/
// .dat file; render/post.h has the shaders, render/colormap.h the colour maps.
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/error.h"
#include "io/image.h"
#include "render/colormap.h"
#include "render/data_exr.h"
#include "render/post.h"

namespace geovis::cli {

namespace {

struct PostArgs {
  std::string data;
  std::string out;
  std::string shader;
  std::string range;
  std::string colormap;
  bool log = false;
  bool colorbar = false;
  double mass = 0;
  std::string csv;
  std::string channels;
  std::vector<std::string> pixels;
  bool quiet = false;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep))
    if (!item.empty()) out.push_back(item);
  return out;
}

double parse_number(const std::string& s, const std::string& what) {
  try {
    size_t used = 0;
    const double v = std::stod(s, &used);
    if (used == s.size()) return v;
  } catch (const std::exception&) {
  }
  throw Error(what + ": expected a number, found \"" + s + "\"");
}

int run_post(const PostArgs& a, const GlobalOptions& g) {
  const bool quiet = a.quiet || g.quiet;
  if (a.out.empty() && a.csv.empty())
    throw Error("nothing to do: give -o OUT.png with --shader NAME, or --csv FILE (or both)");
  if (!a.out.empty() && a.shader.empty())
    throw Error("-o: which picture? add --shader NAME (" + join(post_shader_names()) + ")");
  PostOptions opt;
  opt.shader = a.shader;
  opt.log = a.log;
  opt.colorbar = a.colorbar;
  if (!a.shader.empty()) check_post_shader(a.shader);  // fail before reading the data
  if (!a.colormap.empty()) {
    check_colormap(a.colormap);
    opt.colormap = a.colormap;
  }
  if (!a.range.empty()) {
    const auto parts = split(a.range, ',');
    if (parts.size() != 2) throw Error("--range: expected MIN,MAX, found \"" + a.range + "\"");
    opt.range = std::pair{parse_number(parts[0], "--range"), parse_number(parts[1], "--range")};
  }
  if (a.mass != 0) opt.mass = a.mass;
  std::vector<std::pair<int, int>> pixels;
  for (const auto& p : a.pixels) {
    const auto xy = split(p, ',');
    if (xy.size() != 2) throw Error("--pixel: expected X,Y, found \"" + p + "\"");
    pixels.emplace_back(int(parse_number(xy[0], "--pixel")), int(parse_number(xy[1], "--pixel")));
  }

  const ChannelImage data = read_data_file(a.data);
  if (!a.out.empty()) {
    std::pair<double, double> range;
    const Image img = post_image(data, opt, &range);
    write_image(a.out, img);
    if (!quiet) {
      std::cerr << a.shader << ": " << a.out;
      if (a.shader != "stop") std::cerr << " (range " << range.first << " to " << range.second << ")";
      std::cerr << "\n";
    }
  }
  if (!a.csv.empty()) {
    const std::string text = post_csv(data, split(a.channels, ','), pixels);
    if (a.csv == "-") {
      std::cout << text;
      std::cout.flush();
      if (!std::cout) throw Error("--csv: writing to the standard output failed");
    } else {
      write_file_atomic(a.csv, text);
    }
  }
  return 0;
}

void setup_post(CLI::App& app, GlobalOptions& g) {
  auto a = std::make_shared<PostArgs>();
  CLI::App* sub = app.add_subcommand(
      "post", "pictures and numbers from a data file without re-tracing (redshift, disk flux, time, lensing, stop)");
  sub->add_option("data", a->data, "data file: the .exr of geovis render --data, or a GeoViS .pdz/.jac/.pt/.dat")
      ->required();
  sub->add_option("-o,--output", a->out, "output image (.png, .tif, .ppm, .exr, .jpg)");
  sub->add_option("--shader", a->shader,
                  "redshift (1+z), disk-flux (Page-Thorne flux observed as F/(1+z)^4), time (emission time), "
                  "lensing (magnification), stop (stop reasons)");
  sub->add_option("--range", a->range, "MIN,MAX of the values mapped to the colour map (default: the data's range)");
  sub->add_flag("--log", a->log, "map log10 of the values");
  sub->add_flag("--colorbar", a->colorbar, "draw a labelled colour bar below the image");
  sub->add_option("--colormap", a->colormap, "colour map: " + join(colormap_names()) + " (default per shader)");
  sub->add_option("--mass", a->mass, "mass M of the black hole for disk-flux (default: from the data file, else 1)");
  sub->add_option("--csv", a->csv, "write chosen channels of chosen pixels as CSV to FILE (- = standard output)");
  sub->add_option("--channels", a->channels, "channels for --csv, comma separated (default: all)");
  sub->add_option("--pixel", a->pixels, "pixel X,Y for --csv (repeatable; default: every pixel)")
      ->allow_extra_args(false);
  sub->add_flag("-q,--quiet", a->quiet, "print nothing but errors");
  sub->callback([a, &g]() { g.exit_code = run_post(*a, g); });
}

const bool post_registered = register_command("post", &setup_post);

}  // namespace

}  // namespace geovis::cli
