// Linear RGB colour with components in [0, 1] (GeoViS clamps on output).
#pragma once

#include <algorithm>

namespace geovis {

struct Color {
  double r = 0, g = 0, b = 0;
  constexpr Color operator+(const Color& o) const { return {r + o.r, g + o.g, b + o.b}; }
  constexpr Color operator*(const Color& o) const { return {r * o.r, g * o.g, b * o.b}; }
  constexpr Color operator*(double s) const { return {r * s, g * s, b * s}; }
  Color& operator+=(const Color& o) { return *this = *this + o; }
  constexpr bool operator==(const Color&) const = default;
  Color clamped() const { return {std::clamp(r, 0.0, 1.0), std::clamp(g, 0.0, 1.0), std::clamp(b, 0.0, 1.0)}; }
};
constexpr Color operator*(double s, const Color& c) { return c * s; }

}  // namespace geovis
