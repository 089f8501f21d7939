// Closed-form Christoffel symbols, geodesic acceleration and orthonormal tetrad of a DIAGONAL
// metric g = diag(h_0, h_1, h_2, h_3), given the h_μ and their partial derivatives written out by
// hand in each metric file. Used by the diagonal metrics of spacetime/metrics/ (isotropic
// Schwarzschild, Reissner-Nordström, Kottler, Barriola-Vilenkin, Janis-Newman-Winicour, Ernst).
//
// For a diagonal metric, Γ^μ_{ab} = ½ g^{μμ} (∂_a g_{μb} + ∂_b g_{μa} − ∂_μ g_{ab}) reduces to
// (no sum; direct evaluation of the formula with g_{μν} = 0 for μ ≠ ν):
//   Γ^i_{ii} = ∂_i h_i / (2 h_i),   Γ^i_{ij} = ∂_j h_i / (2 h_i),   Γ^i_{jj} = −∂_i h_j / (2 h_i)
// (i ≠ j), all others zero. Everything here is inline, allocation free and branch free apart
// from the zero tests, so it is fit for the integrator's hot path.
#pragma once

#include <cmath>

#include "spacetime/fast_math.h"
#include "spacetime/vec.h"

namespace geovis {

/// h[μ] = g_{μμ}; dh[c][μ] = ∂_c g_{μμ}.
struct DiagonalMetric {
  double h[4];
  double dh[4][4];
};

/// Fills d for a static, spherically symmetric line element in (t, r, θ, φ):
///   ds² = −A(r) dt² + B(r) dr² + C(r) (dθ² + sin²θ dφ²),
/// given A, B, C and their r-derivatives.
inline void spherical_diagonal(double A, double dA, double B, double dB, double C, double dC, double theta,
                               DiagonalMetric& d) {
  double st, ct;
  fast_sincos(theta, st, ct);
  d = DiagonalMetric{};
  d.h[0] = -A;
  d.h[1] = B;
  d.h[2] = C;
  d.h[3] = C * st * st;
  d.dh[1][0] = -dA;
  d.dh[1][1] = dB;
  d.dh[1][2] = dC;
  d.dh[1][3] = dC * st * st;
  d.dh[2][3] = 2.0 * C * st * ct;
}

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

/// a^i = −Γ^i_{ab} k^a k^b = −(1 / 2h_i) (2 k^i Σ_j ∂_j h_i k^j − Σ_j ∂_i h_j (k^j)²), which is the
/// contraction of the three cases above (the j = i terms of both sums give Γ^i_{ii}). Always
/// inlined: it is the hot path of every diagonal metric, and in a unity unit of several metrics
/// (CMakeLists.txt) GCC stopped inlining it into their integrators.
GEOVIS_HOT_INLINE void diagonal_accel(const DiagonalMetric& d, const Vec4& k, Vec4& a) {
  for (int i = 0; i < 4; ++i) {
    double s1 = 0, s2 = 0;
    for (int j = 0; j < 4; ++j) {
      s1 += d.dh[j][i] * k[j];
      s2 += d.dh[i][j] * k[j] * k[j];
    }
    a[i] = -(2.0 * k[i] * s1 - s2) * (0.5 / d.h[i]);
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
