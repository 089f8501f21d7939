// When a ray has escaped (geodesic.h StopReason::Escaped): an asymptotically flat metric can tell
// that a light ray moving outward beyond a certain radius will never come back, so that nothing
// beyond the scene's bounding sphere can be hit any more and the integration may stop there
// instead of following the ray to r ~ 1e12. A metric declares this by providing
//   bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const;
// (MetricSystem::escaped, integrators.h): true when x lies beyond radius r_min (radius = the
// distance |p| of x from the origin in the metric's pseudo-Cartesian coordinates, the measure of
// the scene's bounds) and the light ray at x moving along k can no longer turn back.
//
// Static spherically symmetric metrics ds² = −A dt² + B dr² + C (dθ² + sin²θ dφ²), A, B, C > 0:
// a light ray lies in a plane through the centre; with E = A dt/dλ and the total angular momentum
// L, g(k,k) = 0 reads
//   A B (dr/dλ)² = E² − L² A/C = E² − L²/h(r)²,   h² = C/A
// (Perlick & Tsupko, Phys. Rep. 947 (2022) 1, §3, with their D = our C; photon spheres are the
// critical points h' = 0). If h is strictly increasing on [r0, ∞) — r0 beyond the outermost photon sphere —
// and dr/dλ > 0 at r0, then for every r > r0: E² − L²/h(r)² > E² − L²/h(r0)² = AB (dr/dλ)²|r0 > 0,
// so dr/dλ never vanishes and r grows monotonically; where AB → 1 (asymptotic flatness)
// (dr/dλ)² stays above a positive bound, so the ray reaches r = ∞. escapes_spherical() below is
// this test; every metric that uses it states its r_photon with the derivation of h' > 0 beyond
// it (test Escape.OutwardRadialRayStopsJustOutsideTheOutermostPhotonSphere finds h' = 0 numerically).
//
// The Kerr family (kerr_mino.h, KerrMinoConstants::no_radial_turning_point_beyond) uses a test
// on the radial potential R(r) = (dr/dσ)² instead, as the photon region is not a sphere there.
#pragma once

namespace geovis {

/// A light ray at areal-type radius r (the metric's radial coordinate, increasing with h), moving
/// with dr/dλ = dr, beyond the outermost photon sphere r_photon (file comment): escaped when also
/// beyond r_min; radius = the ray's |p| (given, since it may be another function of x than r).
inline bool escapes_spherical(double r, double dr, double r_photon, double r_min, double p_norm, double& radius) {
  if (!(r > r_photon && dr > 0.0 && p_norm > r_min)) return false;
  radius = p_norm;
  return true;
}

}  // namespace geovis
