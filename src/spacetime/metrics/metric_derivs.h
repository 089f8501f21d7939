// Closed-form Christoffel symbols of a non-diagonal metric from g_{μν} and its partial derivatives
// ∂_c g_{ab}, both written out by hand in the metric's file:
//   Γ^μ_{ab} = g^{μν} Γ_{νab},  Γ_{νab} = ½ (∂_a g_{νb} + ∂_b g_{νa} − ∂_ν g_{ab}).
// The inverse metric comes from the cofactor formula of a symmetric 4×4 matrix. Everything is
// inline and allocation free (fit for the integrator's hot path); no automatic differentiation.
#pragma once

#include "spacetime/vec.h"

namespace geovis {

/// dg[c][a][b] = ∂_c g_{ab} (symmetric in a, b).
struct MetricDerivs {
  Mat4 g{};
  double dg[4][4][4] = {};
};

/// Inverse of a symmetric 4×4 matrix by cofactors (exact up to rounding; the caller's metric is
/// non-degenerate inside its validity domain).
inline Mat4 inverse_symmetric4(const Mat4& m) {
  const double a00 = m[0][0], a01 = m[0][1], a02 = m[0][2], a03 = m[0][3];
  const double a11 = m[1][1], a12 = m[1][2], a13 = m[1][3];
  const double a22 = m[2][2], a23 = m[2][3], a33 = m[3][3];
  // 2×2 minors of rows 2, 3 and of rows 0, 1.
  const double s0 = a00 * a11 - a01 * a01, s1 = a00 * a12 - a02 * a01, s2 = a00 * a13 - a03 * a01;
  const double s3 = a01 * a12 - a02 * a11, s4 = a01 * a13 - a03 * a11, s5 = a02 * a13 - a03 * a12;
  const double c5 = a22 * a33 - a23 * a23, c4 = a12 * a33 - a13 * a23, c3 = a12 * a23 - a13 * a22;
  const double c2 = a02 * a33 - a03 * a23, c1 = a02 * a23 - a03 * a22, c0 = a02 * a13 - a03 * a12;
  const double det = s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
  const double id = 1.0 / det;
  Mat4 r;
  r[0][0] = (a11 * c5 - a12 * c4 + a13 * c3) * id;
  r[0][1] = (-a01 * c5 + a12 * c2 - a13 * c1) * id;
  r[0][2] = (a13 * s5 - a23 * s4 + a33 * s3) * id;
  r[0][3] = (-a12 * s5 + a22 * s4 - a23 * s3) * id;
  r[1][1] = (a00 * c5 - a02 * c2 + a03 * c1) * id;
  r[1][2] = (-a03 * s5 + a23 * s2 - a33 * s1) * id;
  r[1][3] = (a02 * s5 - a22 * s2 + a23 * s1) * id;
  r[2][2] = (a03 * s4 - a13 * s2 + a33 * s0) * id;
  r[2][3] = (-a03 * s3 + a13 * s1 - a23 * s0) * id;
  r[3][3] = (a02 * s3 - a12 * s1 + a22 * s0) * id;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < i; ++j) r[i][j] = r[j][i];
  return r;
}

/// All Γ^μ_{ab} from g and ∂g (formula in the file comment).
inline void christoffel_from_derivs(const MetricDerivs& d, Christoffel& G) {
  const Mat4 gi = inverse_symmetric4(d.g);
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      double low[4];
      for (int n = 0; n < 4; ++n) low[n] = 0.5 * (d.dg[a][n][b] + d.dg[b][n][a] - d.dg[n][a][b]);
      for (int mu = 0; mu < 4; ++mu) {
        const double v = gi[mu][0] * low[0] + gi[mu][1] * low[1] + gi[mu][2] * low[2] + gi[mu][3] * low[3];
        G.G[mu][a][b] = G.G[mu][b][a] = v;
      }
    }
}

}  // namespace geovis
