// `geovis metrics [--json]`: every registered metric (spacetime/metric_registry.h) with its
// description and reference, coordinates, coordinate type, natural tetrads (GeoViS `localframe`
// values), sample observer position and parameters (name, default, allowed range, meaning) —
// Motion4D's `m4d-metriclist` with the details.
// `geovis metrics --info NAME`: one metric with the extras Motion4D offers (Metric::functions:
// effective potential, circular-orbit velocity, embedding function, tabulated) and the tidal
// matrix of its default observer at the sample position.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/error.h"
#include "spacetime/metric_param_text.h"
#include "spacetime/metric_registry.h"

namespace geovis::cli {

namespace {

std::string number(double v) { return metric_number_text(v); }

/// JSON null for an unbounded side of a range (JSON has no infinity).
nlohmann::json bound(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json metric_json(const Metric& m) {
  const MetricInfo& info = m.info();
  nlohmann::json j;
  j["name"] = info.name;
  j["doc"] = info.doc;
  j["coordinates"] = info.coords;
  j["coordinate_type"] = coord_type_name(info.coord_type);
  nlohmann::json tetrads = nlohmann::json::array();
  for (TetradKind k : info.tetrads) tetrads.push_back(tetrad_kind_name(k));
  j["tetrads"] = tetrads;
  j["closed_form_christoffel"] = m.has_closed_form_christoffel();
  const Vec4& x = info.sample_pos;
  j["sample_position"] = {x[0], x[1], x[2], x[3]};
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : info.params)
    params.push_back({{"name", p.name},
                      {"default", p.def},
                      {"min", bound(p.min)},
                      {"max", bound(p.max)},
                      {"min_open", p.min_open},
                      {"max_open", p.max_open},
                      {"doc", p.doc}});
  j["params"] = params;
  return j;
}

void print_text(const Metric& m, std::ostream& os) {
  const MetricInfo& info = m.info();
  os << info.name << "\n";
  if (!info.doc.empty()) os << "  " << info.doc << "\n";
  os << "  coordinates: " << info.coords[0] << ", " << info.coords[1] << ", " << info.coords[2] << ", "
     << info.coords[3] << " (" << coord_type_name(info.coord_type) << ")\n";
  std::vector<std::string> tetrads;
  for (TetradKind k : info.tetrads) tetrads.push_back(tetrad_kind_name(k));
  os << "  tetrads:     " << join(tetrads) << "\n";
  os << "  christoffel: " << (m.has_closed_form_christoffel() ? "closed form" : "automatic differentiation") << "\n";
  const Vec4& x = info.sample_pos;
  os << "  sample position: (" << number(x[0]) << ", " << number(x[1]) << ", " << number(x[2]) << ", " << number(x[3])
     << ")\n";
  if (info.params.empty()) {
    os << "  parameters:  none\n";
    return;
  }
  os << "  parameters:\n";
  size_t w = 0;
  for (const auto& p : info.params) w = std::max(w, p.name.size());
  for (const auto& p : info.params)
    os << "    " << std::left << std::setw(static_cast<int>(w)) << p.name << " = " << std::setw(10) << number(p.def)
       << " " << std::setw(18) << metric_param_range_text(p) << " " << p.doc << "\n";
}

/// `--info NAME`: the metric, its extras tabulated at 11 points, and the tidal matrix.
int run_info(const std::string& name) {
  const std::unique_ptr<Metric> m = make_metric(name);
  print_text(*m, std::cout);
  const std::vector<MetricFunction> fs = m->functions();
  if (fs.empty()) std::cout << "  extras:      none (Motion4D offers no effective potential or embedding here)\n";
  for (const MetricFunction& f : fs) {
    std::cout << "  " << f.name << ":\n";
    constexpr int kPoints = 11;
    for (int i = 0; i < kPoints; ++i) {
      const double v = f.lo + (f.hi - f.lo) * i / (kPoints - 1);
      std::cout << "    " << f.variable << " = " << std::setw(12) << number(v) << "  " << number(f.f(v)) << "\n";
    }
  }
  const Vec4& x = m->info().sample_pos;
  std::cout << "  tidal matrix T_ij = R^(i)_(0)(j)(0) of the default observer at the sample position "
               "(d^2 xi^i/dtau^2 = -T_ij xi^j):\n";
  try {
    const auto T = tidal_matrix(*m, x, m->natural_tetrad(x, TetradKind::Default));
    for (const auto& row : T)
      std::cout << "    " << std::setw(14) << number(row[0]) << " " << std::setw(14) << number(row[1]) << " "
                << std::setw(14) << number(row[2]) << "\n";
  } catch (const Error& e) {
    std::cout << "    not available: " << e.what() << "\n";
  }
  return 0;
}

int run_metrics(bool json) {
  const std::vector<std::string> names = metric_names();
  if (json) {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& n : names) all.push_back(metric_json(*make_metric(n)));
    std::cout << all.dump(2) << "\n";
    return 0;
  }
  bool first = true;
  for (const auto& n : names) {
    if (!first) std::cout << "\n";
    first = false;
    print_text(*make_metric(n), std::cout);
  }
  return 0;
}

void setup_metrics(CLI::App& app, GlobalOptions& g) {
  auto json = std::make_shared<bool>(false);
  auto info = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "metrics", "list every metric with coordinates, natural tetrads and parameters (default, range, meaning)");
  sub->add_flag("--json", *json, "print the list as JSON");
  sub->add_option("--info", *info,
                  "one metric with Motion4D's extras (effective potential, circular orbits, embedding) and the "
                  "tidal matrix at its sample position");
  sub->callback([json, info, &g]() {
    // errors are reported by run() (app.cpp)
    g.exit_code = info->empty() ? run_metrics(*json) : run_info(*info);
  });
}

const bool metrics_registered = register_command("metrics", &setup_metrics);

}  // namespace

}  // namespace geovis::cli
