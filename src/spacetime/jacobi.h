// Jacobi (geodesic deviation) equation along a null geodesic in a parallel-transported Sachs
// basis: T. Müller, Comput. Phys. Commun. 182 (2011) 1386 ("Motion4D-library extended"), and
// Perlick, Living Rev. Relativ. 7 (2004) 9, §4.
//
// State (24 doubles): x^μ (0-3), k^μ (4-7), Sachs vectors s1^μ (8-11), s2^μ (12-15), the Jacobi
// matrix J = (J11 J12 J21 J22) (16-19) and dJ/dλ (20-23). The Jacobi equation in the screen is
//   d²J/dλ² = T J,   T_ab = −R_{μνρσ} s_a^μ k^ν s_b^ρ k^σ   (optical tidal matrix),
// started with J = 0, dJ/dλ = 1 for a bundle converging at the observer.
#pragma once

#include <cmath>

#include "spacetime/vec.h"

namespace geovis {

class Metric;

/// Optical tidal matrix T (2x2, row-major) at x for tangent k and screen vectors s1, s2.
void optical_tidal_matrix(const Metric& m, const Vec4& x, const Vec4& k, const Vec4& s1,
                          const Vec4& s2, double T[4]);

template <class M>
struct JacobiRHS {
  static constexpr int N = 24;
  const M& m;
  void operator()(const double* y, double* dy) const {
    const Vec4 x{{y[0], y[1], y[2], y[3]}};
    const Vec4 k{{y[4], y[5], y[6], y[7]}};
    Christoffel G;
    m.christoffel_inline(x, G);
    for (int i = 0; i < 4; ++i) dy[i] = k[i];
    for (int v = 0; v < 3; ++v) {  // k, s1, s2 are parallel transported
      const double* e = y + 4 + 4 * v;
      for (int mu = 0; mu < 4; ++mu) {
        double s = 0;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) s += G.G[mu][a][b] * k[a] * e[b];
        dy[4 + 4 * v + mu] = -s;
      }
    }
    const Vec4 s1{{y[8], y[9], y[10], y[11]}};
    const Vec4 s2{{y[12], y[13], y[14], y[15]}};
    double T[4];
    optical_tidal_matrix(m, x, k, s1, s2, T);
    const double* J = y + 16;
    const double* dJ = y + 20;
    for (int i = 0; i < 4; ++i) dy[16 + i] = dJ[i];
    // (T J)_{ij} = Σ_k T_ik J_kj
    dy[20] = T[0] * J[0] + T[1] * J[2];
    dy[21] = T[0] * J[1] + T[1] * J[3];
    dy[22] = T[2] * J[0] + T[3] * J[2];
    dy[23] = T[2] * J[1] + T[3] * J[3];
  }
};

/// Lensing parameters of a Jacobi matrix (Motion4D calcJacobiParams): the circle of unit radius
/// at the observer maps to an ellipse with semi-axes d+ ≥ d- (singular values of J), magnification
/// μ = λ²/(d+ d-) relative to flat space at the same affine distance, the angle of the major axis
/// in the screen, and the ellipticity |d+ − d-|/|d+ + d-|.
struct JacobiParams {
  double d_plus = 0, d_minus = 0, mu = 0, angle = 0, ellipticity = 0;
};
JacobiParams jacobi_params(const double J[4], double lambda);

}  // namespace geovis
