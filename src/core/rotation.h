// Angles and rotations used by the scene language, the object factories and the motions.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace geovis {

/// π/180 (GeoViS Parser/init.scm DEG_TO_RAD).
inline constexpr double kDegToRad = std::numbers::pi / 180.0;

using Matrix3 = std::array<std::array<double, 3>, 3>;

/// Right-handed rotation by `angle` (radians) about the unit axis n (Rodrigues' formula,
/// R = cos a I + sin a [n]× + (1 − cos a) n nᵀ; Motion4D RotateMat3D, after Pique, "Rotation
/// tools", Graphics Gems (1990) 465–469).
inline Matrix3 rotation_about_axis(const std::array<double, 3>& n, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), k = 1.0 - c;
  return {{{k * n[0] * n[0] + c, k * n[0] * n[1] - s * n[2], k * n[0] * n[2] + s * n[1]},
           {k * n[1] * n[0] + s * n[2], k * n[1] * n[1] + c, k * n[1] * n[2] - s * n[0]},
           {k * n[2] * n[0] - s * n[1], k * n[2] * n[1] + s * n[0], k * n[2] * n[2] + c}}};
}

}  // namespace geovis
