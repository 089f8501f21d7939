// When a light ray is captured: the mirror of escape.h. A ray that moves inward below the
// innermost radius any scene object reaches, and that provably cannot turn back before the
// metric's horizon break radius, can hit nothing any more and ends there with StopReason::Invalid
// ("horizon", the reason and colour it gets when integrated to the break radius). A metric
// declares this by providing
//   bool captures(const Vec4& x, const Vec4& k, const SolverConfig& c) const;
// (MetricSystem::captured, integrators.h): true when x lies below c.capture_radius (radius |p| in
// the metric's pseudo-Cartesian coordinates, as escape_radius), the light ray at x moving along k
// has no radial turning point between its radius and the break radius, and nothing else would end
// the integration first (capture_unobstructed below).
//
// Why this is exact for the picture: every later step lies at |p| below the current radius, so
// its chord (the segment tested against the scene, paper §2.3) lies inside the ball of that
// radius, which holds no object; and the ray's radius decreases monotonically to the break
// radius, where the integration would stop with Invalid (tests Capture.*).
//
// Static spherically symmetric metrics (notation of escape.h: A B (dr/dλ)² = E² − L²/h(r)²,
// h² = C/A): if h is strictly decreasing on (r_break, r_photon] — below the innermost photon
// sphere, down to the horizon — and dr/dλ < 0 at r < r_photon, then for every r' in [r_break, r):
// E² − L²/h(r')² > E² − L²/h(r)² = A B (dr/dλ)²|_r > 0, so dr/dλ never vanishes and r falls
// monotonically; with A B = 1 (Schwarzschild) |dr/dλ| stays above its value at r and the ray
// reaches r_break at finite λ. captured_spherical() below is this test (Schwarzschild,
// Reissner–Nordström with a horizon).
//
// The Kerr family tests Carter's radial potential R(r) on [r_break, r] directly
// (KerrMinoConstants::radial_potential_positive_on, kerr_mino.h).
#pragma once

#include <cmath>

#include "spacetime/geodesic.h"

namespace geovis {

/// A bounding-box limit at least this far out is no limit for a falling ray: GeoViS scenes write
/// "no limit" as ±gpDBLMAX = 2⁶⁴ ≈ 1.8e19. Along the fall from r to the break radius t, θ and φ
/// change by finite amounts far below it: in Boyer–Lindquist terms dt/dr and dφ/dr grow like
/// (r² + a²)/Δ at the horizon, so |Δt|, |Δφ| ≲ (r₊² + a²)/(r₊ − r₋) ln(1/horizon_eps) (≈ 30 M for
/// a = 0.9 M), or ≈ (r₊² + a²)/(horizon_eps r₊) = 2·10⁴ M for the extremal hole; θ passes the
/// axis at most a few times.
constexpr double kOpenBoxLimit = 1e18;

/// Nothing but the break radius ends the fall of a ray from radius r to r_break (r is the
/// coordinate x^radial): no limit on the affine parameter, the scene's bounding box open
/// (kOpenBoxLimit) in every other coordinate and its lower bound in the radial one at most
/// r_break. (The number of steps is no such limit: the capture stop is what the ray would reach
/// with enough of them.)
inline bool capture_unobstructed(const SolverConfig& c, double r_break, int radial = 1) {
  if (std::isfinite(c.lambda_max)) return false;
  for (int i = 0; i < 4; ++i) {
    if (i == radial) continue;
    if (c.box_ll[i] > -kOpenBoxLimit || c.box_ur[i] < kOpenBoxLimit) return false;
  }
  return c.box_ll[radial] <= r_break;
}

/// A light ray at radius r (the metric's areal-type radial coordinate, which is also its |p|)
/// moving with dr/dλ = dr, in a metric whose h (file comment) decreases on (r_break, r_photon]:
/// captured when also below r_max (the scene's innermost radius, SolverConfig::capture_radius).
inline bool captured_spherical(double r, double dr, double r_photon, double r_max) {
  return r < r_photon && r < r_max && dr < 0.0;
}

}  // namespace geovis
