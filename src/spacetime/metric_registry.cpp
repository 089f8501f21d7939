#include "spacetime/metric_registry.h"

#include "core/error.h"

// One line per metric: X(ClassName, "DatabaseName"). make_metric_<ClassName>() is defined in
// spacetime/metrics/<file>.cpp.
#define GEOVIS_METRICS(X)                       \
  X(Minkowski, "Minkowski")                     \
  X(Schwarzschild, "Schwarzschild")

namespace geovis {

#define GEOVIS_DECLARE(cls, name) std::unique_ptr<Metric> make_metric_##cls();
GEOVIS_METRICS(GEOVIS_DECLARE)
#undef GEOVIS_DECLARE

namespace {
struct Entry {
  const char* name;
  std::unique_ptr<Metric> (*make)();
};
const std::vector<Entry>& entries() {
#define GEOVIS_ENTRY(cls, name) Entry{name, &make_metric_##cls},
  static const std::vector<Entry> list = {GEOVIS_METRICS(GEOVIS_ENTRY)};
#undef GEOVIS_ENTRY
  return list;
}
}  // namespace

std::vector<std::string> metric_names() {
  std::vector<std::string> out;
  for (const auto& e : entries()) out.emplace_back(e.name);
  return out;
}

std::unique_ptr<Metric> make_metric(const std::string& name) {
  for (const auto& e : entries())
    if (name == e.name) return e.make();
  throw Error("unknown metric \"" + name + "\"" + did_you_mean(name, metric_names()) +
              " (valid metrics: " + join(metric_names()) + ")");
}

std::unique_ptr<Metric> make_metric(const std::string& name,
                                    const std::vector<std::pair<std::string, double>>& params) {
  auto m = make_metric(name);
  for (const auto& [k, v] : params) m->set_param(k, v);
  return m;
}

}  // namespace geovis
