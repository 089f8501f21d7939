// Closed-form Christoffel symbols, geodesic acceleration and orthonormal tetrad of a DIAGONAL
// metric g = diag(h_0, h_1, h_2, h_3), given the h_μ and their partial derivatives written out by
// hand in each metric file. Used by the diagonal metrics of spacetime/metrics/ (isotropic
// Schwarzschild, Reissner-Nordström, Kottler, Barriola-Vilenkin, Janis-Newman-Winicour, Ernst).
//
// For a diagonal metric, Γ^μ_{ab} = ½ g^{μμ} (∂_a g_{μb} + ∂_b g_{μa} − ∂_μ g_{ab}) reduces to
// (no sum; direct evaluation of the formula with g_{μν} = 0 for μ ≠ ν):
//   Γ^i_{ii} = ∂_i h_i / (2 h_i),   Γ^i_{ij} = ∂_j h_i / (2 h_i),   Γ^i_{jj} = −∂_i h_j / (2 h_i)
// (i ≠ j), all others zero. Everything here is inline, allocation free and branch free apart
// from the zero tests, so it is fit for the integrator's hot path. The metric functions and the
// acceleration are templates over the number type (diagonal_metric_accel.h), so a metric writes
// its g_μμ once for the scalar and the SIMD packet integrator.
#pragma once

#include <cmath>

#include "spacetime/fast_math.h"
#include "spacetime/vec.h"

namespace geovis {

// DiagonalMetricT, spherical_diagonal and diagonal_accel, templates over the number type: here
// for doubles, and per SIMD target in the metric files that give packets of rays a SIMD
// acceleration (reissner_nordstrom.cpp, ...).
#include "spacetime/metrics/diagonal_metric_accel.h"

using DiagonalMetric = DiagonalMetricT<double>;

/// All Γ^μ_{ab} of a diagonal metric (formulas in the file comment).
inline void diagonal_christoffel(const DiagonalMetric& d, Christoffel& G) {
  G = Christoffel{};
  for (int i = 0; i < 4; ++i) {
    const double inv2h = 0.5 / d.h[i];
    for (int j = 0; j < 4; ++j) {
      if (j == i) {
        G.G[i][i][i] = d.dh[i][i] * inv2h;
      } else {
        G.G[i][i][j] = G.G[i][j][i] = d.dh[j][i] * inv2h;
        G.G[i][j][j] = -d.dh[i][j] * inv2h;
      }
    }
  }
}

/// The tetrad of observers at rest in the chart, e_(μ) = ∂_μ / sqrt(|g_μμ|) (paper eq. 2 for the
/// diagonal case). Returns false when the signature is not (−,+,+,+) at this point (e.g. a static
/// observer inside a horizon), so the caller can throw its own error.
inline bool diagonal_static_tetrad(const double h[4], Tetrad& e) {
  if (!(h[0] < 0.0) || !(h[1] > 0.0) || !(h[2] > 0.0) || !(h[3] > 0.0)) return false;
  e = Tetrad{};
  e[0][0] = 1.0 / std::sqrt(-h[0]);
  for (int i = 1; i < 4; ++i) e[i][i] = 1.0 / std::sqrt(h[i]);
  return true;
}

}  // namespace geovis
