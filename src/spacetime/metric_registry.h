// Registry of metrics by Motion4D database name (catalogue §12). Mitsuba-style: each metric is one
// file in spacetime/metrics/ defining make_metric_<Name>(), plus one line in metric_registry.cpp.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "spacetime/metric.h"

namespace geovis {

/// Names of all registered metrics, in registry order.
std::vector<std::string> metric_names();

/// Creates a metric with default parameters. Unknown name -> Error with the closest valid name and
/// the list of all names.
std::unique_ptr<Metric> make_metric(const std::string& name);

/// Creates a metric and sets parameters (keys case-insensitive). Unknown keys and out-of-range
/// values -> Error naming the valid keys / range.
std::unique_ptr<Metric> make_metric(const std::string& name, const std::vector<std::pair<std::string, double>>& params);

}  // namespace geovis
