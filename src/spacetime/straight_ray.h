// Geodesics of a flat metric in inertial Cartesian coordinates (MetricInfo::inertial_cartesian,
// e.g. Minkowski) without an integrator. There Γ = 0, so the systems of geodesic.h have the exact
// solution, for every λ,
//   x(λ) = x0 + (λ − λ0) k,  k, parallel-transported vectors and Sachs vectors constant,
//   Y_a(λ) = Y_a(λ0) + (λ − λ0) Y'_a,  Y'_a constant  (Jacobi equation Y'' = −R(k, Y) k = 0),
// (geodesic equation d²x/dλ² = −Γ k k, Misner, Thorne & Wheeler eq. 16.4a). An integrator computes
// the same line step by step; this hands it to the callback as ONE step from the start to where
// the integrator would have stopped, in one evaluation.
//
// Where it stops: the stop conditions of integrate_with (integrators.h) are tested at the ends of
// the steps the integrator would take — fixed steps of cfg.step_size, or, with step control, steps
// growing by the controller's maximal factor 5 from step_size up to step_max (the error estimate of
// any Runge–Kutta pair vanishes on a straight line) — in the integrator's order: the step budget
// max_steps before each step, then the bounding box, λ_max and the escape sphere after it. So the
// ray covers the same stretch of the line as the integrated one (a ray that would run out of steps
// ends where the integrator's would, and an object beyond stays unseen, as with GeoViS) and stops
// for the same reason; the one step spans all of it, the callback sees it whole.
#pragma once

#include "spacetime/geodesic.h"

namespace geovis {

/// The exact geodesic of `sys` (y of system_dim(sys) components, updated in place to the end state)
/// of a flat metric in inertial Cartesian coordinates, from affine parameter lambda0, as one step
/// handed to `cb` (see the file comment). `escapes`: the metric declares asymptotic flatness
/// (Metric::asymptotically_flat), so that a light ray beyond cfg.escape_radius moving outward stops
/// with StopReason::Escaped as the integrator's does. GeodesicResult::steps counts the steps handed
/// to the callback (0 or 1), rhs_evals is 0.
GeodesicResult integrate_straight(const SolverConfig& cfg, GeodesicSystem sys, double* y, double lambda0, bool escapes,
                                  StepCallback cb);

}  // namespace geovis
