#include "spacetime/circular_orbit.h"

#include <cmath>

namespace geovis {

bool circular_orbit_velocity(const Metric& m, const Vec4& x, Vec4& u) {
  const Vec4 xe{{x[0], x[1], M_PI / 2, x[3]}};
  if (!m.is_valid(xe)) return false;
  Christoffel G;
  m.christoffel(xe, G);
  const double a = G.G[1][3][3], b = G.G[1][0][3], c = G.G[1][0][0];
  const double disc = b * b - a * c;
  if (!(disc >= 0) || a == 0) return false;
  // The two roots (−b ± √disc)/a; the larger one is the orbit turning in +φ.
  const double r1 = (-b + std::sqrt(disc)) / a, r2 = (-b - std::sqrt(disc)) / a;
  const double omega = std::max(r1, r2);
  Mat4 g;
  m.metric_tensor(xe, g);
  const double norm2 = -(g[0][0] + 2 * g[0][3] * omega + g[3][3] * omega * omega);
  if (!(norm2 > 0) || !std::isfinite(norm2)) return false;
  const double ut = 1.0 / std::sqrt(norm2);
  u = Vec4{{ut, 0, 0, ut * omega}};
  return true;
}

}  // namespace geovis
