// The Jacobi system (jacobi.h) as the integrators of integrators.h see it, on a metric's function
// table (metric_kernel.h): the scalar integrator (integrate_jacobi_on_kernel, jacobi.cpp) and each
// lane of the packet integrator (integrate_jacobi_packet_on_kernel, geodesic_packet.cpp) run this
// one system, its steps and tolerance scales.
#pragma once

#include <algorithm>
#include <cmath>

#include "spacetime/integrators.h"
#include "spacetime/jacobi.h"
#include "spacetime/metric_kernel.h"

namespace geovis {

/// The Jacobi system as the driver sees it, with per-component tolerance scales (integrators.h
/// ErrorScale): x, k and the Sachs basis keep eps_abs as in the geodesic system, each Jacobi field
/// (Y_f, Y_f') is held to eps_abs relative to its own size max(1, max_i |(Y_f, Y_f')_i|). Why:
/// the Jacobi equation is linear, the fields' scale is the arbitrary normalisation J'(0) = 1, and
/// what the lensing parameters need is J = g(s_a, Y_b) to a relative accuracy (μ = λ²/det J,
/// d± its singular values); Y grows like λ, and an absolute tolerance on it made the fields, not
/// the ray, set the step (Kerr disk: 1.75x the steps of x, k, s alone; docs/PERFORMANCE.md).
struct JacobiSystem : MetricSystem<MetricKernel, JacobiRHS<MetricKernel>> {
  void tolerance_inv_scale(const double* y, double* is) const {
    for (int i = 0; i < kJacobiY1; ++i) is[i] = 1.0;
    for (int f = 0; f < 2; ++f) {
      const double* Y = y + kJacobiY1 + 8 * f;  // Y_f (4) then Y_f' (4)
      double size = 1.0;
      for (int i = 0; i < 8; ++i) size = std::max(size, std::fabs(Y[i]));
      const double inv = 1.0 / size;
      for (int i = 0; i < 8; ++i) is[kJacobiY1 + 8 * f + i] = inv;
    }
  }
};

}  // namespace geovis
