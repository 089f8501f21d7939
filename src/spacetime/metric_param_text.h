// How a metric parameter's numbers and allowed range are written for people (`geovis metrics`,
// the scene reference).
#pragma once

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "spacetime/metric.h"

namespace geovis {

/// 10 significant digits; "inf" / "-inf" for the unbounded sides.
inline std::string metric_number_text(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream os;
  os << std::setprecision(10) << v;
  return os.str();
}

/// "[lo, hi)", "(0, inf)", or "any".
inline std::string metric_param_range_text(const MetricParam& p) {
  const bool lo = std::isfinite(p.min), hi = std::isfinite(p.max);
  if (!lo && !hi) return "any";
  return std::string(p.min_open || !lo ? "(" : "[") + metric_number_text(p.min) + ", " + metric_number_text(p.max) +
         (p.max_open || !hi ? ")" : "]");
}

}  // namespace geovis
