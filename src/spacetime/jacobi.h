// Jacobi (geodesic deviation) equation along a null geodesic in a parallel-transported Sachs
// basis: T. Müller, Comput. Phys. Commun. 182 (2011) 1386 ("Motion4D-library extended"), and
// Perlick, Living Rev. Relativ. 7 (2004) 9, §4.
//
// State (24 doubles): x^μ (0-3), k^μ (4-7), Sachs vectors s1^μ (8-11), s2^μ (12-15), the Jacobi
// matrix J = (J11 J12 J21 J22) (16-19) and dJ/dλ (20-23). The Jacobi equation in the screen is
//   d²J/dλ² = T J,   T_ab = −R_{μνρσ} s_a^μ k^ν s_b^ρ k^σ   (optical tidal matrix),
// started with J = 0, dJ/dλ = 1 for a bundle converging at the observer.
// Sign: the geodesic deviation equation is D²ξ^α/dλ² = −R^α_{βγδ} k^β ξ^γ k^δ with the MTW
// Riemann convention R^α_{βγδ} = ∂_γ Γ^α_{δβ} − ∂_δ Γ^α_{γβ} + Γ^α_{γε}Γ^ε_{δβ} − Γ^α_{δε}Γ^ε_{γβ}
// (MTW eq. 11.10, 11.12; Metric::riemann); projecting ξ = J_ab s_b onto s_a gives T above. Then
// tr T = −R_{μν} k^μ k^ν (Ricci focusing, Sachs' equation: matter focuses, dJ/dλ decreases) and
// the trace-free part is the Weyl shear. Row a of J = screen component along s_a, column b = the
// Jacobi field started with dξ/dλ = s_b.
#pragma once

#include <cmath>

#include <limits>
#include <utility>

#include "spacetime/dual.h"
#include "spacetime/geodesic.h"
#include "spacetime/metric.h"
#include "spacetime/vec.h"

namespace geovis {

/// Optical tidal matrix T (2x2, row-major) at x for tangent k and screen vectors s1, s2 (through
/// the virtual Metric interface; the integrator uses optical_tidal_matrix_inline).
void optical_tidal_matrix(const Metric& m, const Vec4& x, const Vec4& k, const Vec4& s1,
                          const Vec4& s2, double T[4]);

/// T_ab = −g(s_a, W_b), W_b^α = R^α_{νρσ} k^ν s_b^ρ k^σ (see the header comment).
inline void tidal_from_riemann(const Riemann& R, const Mat4& g, const Vec4& k, const Vec4& s1, const Vec4& s2,
                               double T[4]) {
  const Vec4* s[2] = {&s1, &s2};
  for (int b = 0; b < 2; ++b) {
    Vec4 W{{0, 0, 0, 0}};
    for (int al = 0; al < 4; ++al)
      for (int nu = 0; nu < 4; ++nu) {
        if (k[nu] == 0.0) continue;
        for (int rho = 0; rho < 4; ++rho)
          for (int sg = 0; sg < 4; ++sg) W[al] += R.R[al][nu][rho][sg] * k[nu] * (*s[b])[rho] * k[sg];
      }
    for (int a = 0; a < 2; ++a) T[2 * a + b] = -dot(g, *s[a], W);
  }
}

namespace jacobi_detail {
/// Gauss-Jordan inversion with partial pivoting for a first-order dual matrix; false if singular.
inline bool invert4(const Mat4T<DualD>& a, Mat4T<DualD>& inv) {
  DualD m[4][8];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      m[i][j] = a[i][j];
      m[i][j + 4] = DualD(i == j ? 1.0 : 0.0);
    }
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::fabs(m[r][c].v) > std::fabs(m[p][c].v)) p = r;
    if (std::fabs(m[p][c].v) < 1e-300) return false;
    if (p != c)
      for (int j = 0; j < 8; ++j) std::swap(m[p][j], m[c][j]);
    const DualD piv = DualD(1.0) / m[c][c];
    for (int j = 0; j < 8; ++j) m[c][j] = m[c][j] * piv;
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const DualD f = m[r][c];
      for (int j = 0; j < 8; ++j) m[r][j] = m[r][j] - f * m[c][j];
    }
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) inv[i][j] = m[i][j + 4];
  return true;
}
}  // namespace jacobi_detail

/// Riemann tensor R^a_{bcd} (MTW convention, as Metric::riemann) from the metric's templated
/// g_{μν} by second-order forward automatic differentiation, without virtual calls or heap
/// allocation (for the Jacobi right-hand side): Γ^μ_{ab} = ½ g^{μν}(∂_a g_{νb} + ∂_b g_{νa} −
/// ∂_ν g_{ab}) carried as first-order duals gives ∂_c Γ, then
/// R^a_{bcd} = ∂_c Γ^a_{db} − ∂_d Γ^a_{cb} + Γ^a_{ce} Γ^e_{db} − Γ^a_{de} Γ^e_{cb}.
/// A singular metric yields NaN (the integrator then stops with NotFinite).
template <class M>
inline void riemann_inline(const M& m, const Vec4& x, Riemann& out) {
  const Vec4T<Dual2> x2 = seed(seed(x));
  Mat4T<Dual2> g2;
  m.g_tmpl(x2, g2);
  Mat4T<DualD> g1, ginv;
  DualD dg[4][4][4];  // dg[c][a][b] = ∂_c g_ab (with its own derivatives)
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      g1[a][b] = g2[a][b].v;
      for (int c = 0; c < 4; ++c) dg[c][a][b] = g2[a][b].d[c];
    }
  if (!jacobi_detail::invert4(g1, ginv)) {
    for (auto& r1 : out.R)
      for (auto& r2 : r1)
        for (auto& r3 : r2)
          for (double& v : r3) v = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  DualD G[4][4][4];
  for (int mu = 0; mu < 4; ++mu)
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b) {
        DualD s(0.0);
        for (int nu = 0; nu < 4; ++nu) s = s + ginv[mu][nu] * (dg[a][nu][b] + dg[b][nu][a] - dg[nu][a][b]);
        G[mu][a][b] = s * DualD(0.5);
        G[mu][b][a] = G[mu][a][b];
      }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 4; ++d) {
          double r = G[a][d][b].d[c] - G[a][c][b].d[d];
          for (int e = 0; e < 4; ++e) r += G[a][c][e].v * G[e][d][b].v - G[a][d][e].v * G[e][c][b].v;
          out.R[a][b][c][d] = r;
        }
}

/// optical_tidal_matrix for a concrete metric type (inlined into JacobiRHS).
template <class M>
inline void optical_tidal_matrix_inline(const M& m, const Vec4& x, const Vec4& k, const Vec4& s1, const Vec4& s2,
                                        double T[4]) {
  Riemann R;
  riemann_inline(m, x, R);
  Mat4 g;
  m.metric_tensor_inline(x, g);
  tidal_from_riemann(R, g, k, s1, s2, T);
}

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
    optical_tidal_matrix_inline(m, x, k, s1, s2, T);
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

/// Lensing parameters of a Jacobi matrix (Motion4D calcJacobiParams; catalogue §3 FilterRGBjac):
/// the circle of unit radius at the observer maps to an ellipse with semi-axes d+ ≥ d- (singular
/// values of J), magnification μ = λ²/(d+ d-) relative to flat space at the same affine distance
/// (1 at λ = 0, +∞ on a caustic), the angle of the major axis in the screen basis (s1, s2) in
/// (−π/2, π/2], and the ellipticity |d+ − d-|/|d+ + d-|.
struct JacobiParams {
  double d_plus = 0, d_minus = 0, mu = 0, angle = 0, ellipticity = 0;
};
JacobiParams jacobi_params(const double J[4], double lambda);

// ---- setting up and evaluating the Jacobi system per ray ----------------------------------------

/// Indices into the 24-component Jacobi state.
constexpr int kJacobiX = 0, kJacobiK = 4, kJacobiS1 = 8, kJacobiS2 = 12, kJacobiJ = 16, kJacobiDJ = 20;

/// Sachs basis at the observer for the local (spatial) ray direction d relative to the observer
/// tetrad e (as Motion4D Geodesic::calcSachsBasis): b1 = ẑ × d̂ / |ẑ × d̂|, b2 = b1 × d̂ (b1 = ŷ,
/// b2 = x̂ when d̂ ∥ ẑ), s_a = b_a^i e_(i). Both are unit, orthogonal to each other, to the observer
/// four-velocity e_(0) and to k = ±e_(0) + d̂^i e_(i).
void sachs_basis(const Tetrad& e, const Vec3& d, Vec4& s1, Vec4& s2);

/// Initial Jacobi state for a ray leaving the observer (position x, tetrad e) in local direction
/// d: k = −e_(0) + d̂^i e_(i) (past-directed, paper eq. 7, so −g(k, e_(0)) = −1 and the affine
/// parameter λ ≥ 0 measures distance back in time), Sachs basis from sachs_basis, J = 0,
/// dJ/dλ = 1 (a bundle with its vertex at the observer). Integrate with
/// metric.integrate(cfg, GeodesicSystem::Jacobi, y, 0, cb) and direction +1.
void jacobi_initial_state(const Vec4& x, const Tetrad& e, const Vec3& d, double y[24]);

/// Jacobi parameters of a state of the Jacobi system at affine parameter λ (distance from the
/// observer's event).
inline JacobiParams jacobi_params_from_state(const double* y, double lambda) {
  return jacobi_params(y + kJacobiJ, lambda);
}

/// Convenience for one ray (tests, the `geovis ray` tools): integrates the Jacobi system from the
/// observer in direction d with cfg (type lightlike, direction +1) until |λ| reaches lambda_end
/// or the integration stops; returns the parameters at the final point and writes the final
/// state to y_out when given.
JacobiParams trace_jacobi(const Metric& m, const SolverConfig& cfg, const Vec4& x, const Tetrad& e, const Vec3& d,
                          double lambda_end, double* y_out = nullptr, GeodesicResult* result = nullptr);

}  // namespace geovis
