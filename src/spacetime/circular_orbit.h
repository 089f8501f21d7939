// Circular equatorial geodesic orbits: the four-velocity of the matter of a thin Keplerian disk
// (paper §5: Luminet's disk of particles on timelike circular geodesics), used for the emitter
// velocity of plane rings with `emitter "keplerian"`.
#pragma once

#include "spacetime/metric.h"
#include "spacetime/vec.h"

namespace geovis {

/// Four-velocity u = u^t (∂_t + Ω ∂_φ) of the circular geodesic through the equatorial point
/// (t, r, π/2, φ) of x (x^2 is replaced by π/2) in a stationary, axisymmetric, equatorially
/// symmetric metric in spherical-like coordinates (t, r, θ, φ). Ω is the positive root of
/// Γ^r_tt + 2 Γ^r_tφ Ω + Γ^r_φφ Ω² = 0 (the r-component of the geodesic equation with
/// u^r = u^θ = 0), so the disk turns in +φ: prograde for Kerr with a ≥ 0 (Bardeen, Press &
/// Teukolsky, ApJ 178 (1972) 347, eq. 2.16: Ω = √M / (r^{3/2} + a√M)); u^t from g(u, u) = −1.
/// Returns false where no timelike circular orbit exists (inside the photon orbit) or the metric
/// is not defined there.
bool circular_orbit_velocity(const Metric& m, const Vec4& x, Vec4& u);

}  // namespace geovis
