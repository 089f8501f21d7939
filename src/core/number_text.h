// Numbers as text, the same way everywhere: 10 significant digits in messages, 17 where a file or a
// reply must give the double back exactly (17 significant decimal digits identify every IEEE 754
// binary64 value: Goldberg, "What every computer scientist should know about floating-point
// arithmetic", ACM Comput. Surv. 23 (1991) 5, theorem 15).
#pragma once

#include <cstdio>
#include <string>

namespace geovis {

/// v as %.10g: for messages.
inline std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

/// v as %.17g: reads back as the same double.
inline std::string exact_number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace geovis
