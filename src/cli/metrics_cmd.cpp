// `geovis metrics [--json]`: every registered metric (spacetime/metric_registry.h) with its
// coordinates, coordinate type, natural tetrads (GeoViS `localframe` values) and parameters
// (name, default, allowed range, meaning) — Motion4D's `m4d-metriclist` with the details.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/command.h"
#include "core/error.h"
#include "spacetime/metric_registry.h"

namespace geovis::cli {

namespace {

std::string number(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream os;
  os << std::setprecision(10) << v;
  return os.str();
}

std::string range_text(const MetricParam& p) {
  const bool lo = std::isfinite(p.min), hi = std::isfinite(p.max);
  if (!lo && !hi) return "any";
  return std::string(p.min_open || !lo ? "(" : "[") + number(p.min) + ", " + number(p.max) +
         (p.max_open || !hi ? ")" : "]");
}

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
  os << "  christoffel: " << (m.has_closed_form_christoffel() ? "closed form" : "automatic differentiation")
     << "\n";
  if (info.params.empty()) {
    os << "  parameters:  none\n";
    return;
  }
  os << "  parameters:\n";
  size_t w = 0;
  for (const auto& p : info.params) w = std::max(w, p.name.size());
  for (const auto& p : info.params)
    os << "    " << std::left << std::setw(static_cast<int>(w)) << p.name << " = " << std::setw(10) << number(p.def)
       << " " << std::setw(18) << range_text(p) << " " << p.doc << "\n";
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

void setup(CLI::App& app, GlobalOptions& g) {
  auto json = std::make_shared<bool>(false);
  CLI::App* sub = app.add_subcommand(
      "metrics", "list every metric with coordinates, natural tetrads and parameters (default, range, meaning)");
  sub->add_flag("--json", *json, "print the list as JSON");
  sub->callback([json, &g]() {
    g.exit_code = run_metrics(*json);  // errors are reported by run() (app.cpp)
  });
}

const bool registered = register_command("metrics", &setup);

}  // namespace

}  // namespace geovis::cli
