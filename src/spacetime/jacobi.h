// Jacobi (geodesic deviation) equation along a null geodesic with a parallel-transported Sachs
// basis: T. Müller, Comput. Phys. Commun. 182 (2011) 1386 ("Motion4D-library extended"), and
// Perlick, Living Rev. Relativ. 7 (2004) 9, §4.
//
// State (32 doubles, the layout and variables of Motion4D's GeodesicGSL::calcSachsJacobi, which
// GeoViS's FilterRGBjac integrates): x^μ (0-3), k^μ (4-7), Sachs vectors s1^μ (8-11), s2^μ
// (12-15), and two Jacobi fields in coordinates with their λ-derivatives, Y1^μ (16-19), Y1'^μ
// (20-23), Y2^μ (24-27), Y2'^μ (28-31). k, s1, s2 are parallel transported,
//   k' = −Γ(k, k),  s_a' = −Γ(k, s_a),
// and each Jacobi field obeys the geodesic equation linearised about the ray (the coordinate form
// of the geodesic deviation equation D²Y/dλ² = −R^α_{βγδ} k^β Y^γ k^δ; Motion4D func_jacobi),
//   Y''^μ = −2 Γ^μ_{ab} k^a Y'^b − ∂_ν Γ^μ_{ab} k^a k^b Y^ν,
// started with Y_b = 0, Y_b' = s_b: a bundle with its vertex at the observer. The Jacobi matrix
// is the screen projection J_ab = g(s_a, Y_b) (row a = component along s_a, column b = field b;
// J(0) = 0, dJ/dλ(0) = 1), Motion4D's calcJacobiParams up to an overall sign, which no lensing
// parameter sees. The Riemann convention is MTW's (eq. 11.12; Metric::riemann):
// R^α_{βγδ} = ∂_γ Γ^α_{δβ} − ∂_δ Γ^α_{γβ} + Γ^α_{γε}Γ^ε_{δβ} − Γ^α_{δε}Γ^ε_{γβ}; in the screen,
// d²J/dλ² = T J with the optical tidal matrix T_ab = −R_{μνρσ} s_a^μ k^ν s_b^ρ k^σ, whose trace
// −R_{μν} k^μ k^ν is the Ricci focusing of Sachs' equation and whose trace-free part is the Weyl
// shear (optical_tidal_matrix).
#pragma once

#include <cmath>

#include <limits>
#include <utility>

#include "spacetime/dual.h"
#include "spacetime/geodesic.h"
#include "spacetime/metric.h"
#include "spacetime/metric_kernel.h"
#include "spacetime/vec.h"

namespace geovis {

/// Optical tidal matrix T (2x2, row-major) at x for tangent k and screen vectors s1, s2, from the
/// full Riemann tensor (Metric::riemann): T_ab = −g(s_a, W_b), W_b^α = R^α_{νρσ} k^ν s_b^ρ k^σ.
void optical_tidal_matrix(const Metric& m, const Vec4& x, const Vec4& k, const Vec4& s1, const Vec4& s2, double T[4]);

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

/// Γ^μ_{ab} at x with its first partial derivatives, G.G[μ][a][b].d[c] = ∂_c Γ^μ_{ab}, for a
/// metric without closed-form symbols, without virtual calls or heap allocation: from the templated
/// g_{μν} by second-order forward differentiation, Γ^μ_{ab} = ½ g^{μν}(∂_a g_{νb} + ∂_b g_{νa} −
/// ∂_ν g_{ab}) carried as first-order duals (as Metric::christoffel_derivs_ad). A singular metric
/// yields NaN (the integrator then stops with NotFinite).
template <class M>
inline void christoffel_with_derivs(const M& m, const Vec4& x, ChristoffelT<DualD>& G) {
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
    for (auto& g3 : G.G)
      for (auto& g4 : g3)
        for (DualD& v : g4) v = DualD(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  for (int mu = 0; mu < 4; ++mu)
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b) {
        DualD s(0.0);
        for (int nu = 0; nu < 4; ++nu) s = s + ginv[mu][nu] * (dg[a][nu][b] + dg[b][nu][a] - dg[nu][a][b]);
        G.G[mu][a][b] = s * DualD(0.5);
        G.G[mu][b][a] = G.G[mu][a][b];
      }
}

namespace jacobi_detail {
/// Gk[μ][b] = Γ^μ_{bc} k^c (values) and Gkk^μ = Γ^μ_{ab} k^a k^b with its dual parts.
template <class D>
inline void contract_with_k(const ChristoffelT<D>& G, const Vec4& k, double Gk[4][4], D Gkk[4]) {
  for (int mu = 0; mu < 4; ++mu) {
    D kk(0.0);
    for (int b = 0; b < 4; ++b) {
      D s = G.G[mu][b][0] * k[0];
      for (int c = 1; c < 4; ++c) s += G.G[mu][b][c] * k[c];
      Gk[mu][b] = s.v;
      kk += s * k[b];
    }
    Gkk[mu] = kk;
  }
}
}  // namespace jacobi_detail

/// The Jacobi system's terms from a metric's acceleration template a^μ = accel(x, k) = −Γ^μ_{ab} k^a k^b
/// on any number type (the templates of metrics/*_accel.h), by one evaluation on first-order duals
/// with six slots: x seeded along Y_1 and Y_2 (slots 0, 1), k along the coordinate directions
/// (slots 2-5). Since Γ^μ_{ab} is symmetric in a, b, ∂a^μ/∂k^b = −2 Γ^μ_{bc} k^c, so
/// Gk[μ][b] = −½ a^μ.d[2+b]; and Y_f^ν ∂_ν a^μ = −Y_f^ν ∂_ν Γ^μ_{ab} k^a k^b, so dGkk[f][μ] =
/// −a^μ.d[f]. Both are exact derivatives of the closed-form symbols (no differences). The packet
/// integrator's packet_jacobi_terms_simd (simd.h) runs the same operations on SIMD lanes.
template <class Accel>
inline void jacobi_terms_from_accel(const Accel& accel, const Vec4& x, const Vec4& k, const Vec4 (&Y)[2],
                                    JacobiTerms& t) {
  using D = Dual<double, 6>;
  Vec4T<D> xd, kd, a;
  for (int i = 0; i < 4; ++i) {
    xd[i] = D(x[i]);
    xd[i].d[0] = Y[0][i];
    xd[i].d[1] = Y[1][i];
    kd[i] = D(k[i]);
    kd[i].d[2 + i] = 1.0;
  }
  accel(xd, kd, a);
  for (int mu = 0; mu < 4; ++mu) {
    for (int b = 0; b < 4; ++b) t.Gk[mu][b] = a[mu].d[2 + b] * -0.5;
    for (int f = 0; f < 2; ++f) t.dGkk[f][mu] = -a[mu].d[f];
  }
}

/// The Jacobi system's terms (JacobiTerms, metric_kernel.h) without virtual calls or heap
/// allocation. A metric may write them out (jacobi_terms_closed, e.g. KerrBL: twenty symbols, no
/// zeros); a metric with closed-form symbols on any number type (has_christoffel_tmpl) evaluates
/// them on duals seeded along Y_1 and Y_2 (seed_directions: two derivative slots, not four, and
/// dGkk comes out directly); any other metric differentiates g twice (christoffel_with_derivs)
/// and contracts ∂_ν with Y_f^ν.
template <class M>
inline void jacobi_terms(const M& m, const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) {
  if constexpr (requires { m.jacobi_terms_closed(x, k, Y, t); }) {
    m.jacobi_terms_closed(x, k, Y, t);
  } else if constexpr (has_christoffel_tmpl<M>) {
    using D = Dual<double, 2>;
    ChristoffelT<D> G;
    m.template christoffel_tmpl<D>(seed_directions(x, Y), G);
    D Gkk[4];
    jacobi_detail::contract_with_k(G, k, t.Gk, Gkk);
    for (int f = 0; f < 2; ++f)
      for (int mu = 0; mu < 4; ++mu) t.dGkk[f][mu] = Gkk[mu].d[f];
  } else {
    ChristoffelT<DualD> G;
    christoffel_with_derivs(m, x, G);
    DualD Gkk[4];
    jacobi_detail::contract_with_k(G, k, t.Gk, Gkk);
    for (int f = 0; f < 2; ++f)
      for (int mu = 0; mu < 4; ++mu) {
        double s = 0;
        for (int nu = 0; nu < 4; ++nu) s += Gkk[mu].d[nu] * Y[f][nu];
        t.dGkk[f][mu] = s;
      }
  }
}

/// The same through a metric's function table (the Jacobi system compiled once, jacobi.cpp).
inline void jacobi_terms(const MetricKernel& m, const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) {
  m.jacobi_terms(x, k, Y, t);
}

/// The Jacobi system (header comment). One evaluation of the Γ terms per stage (jacobi_terms)
/// serves the transport of k, s1, s2 and both Jacobi fields: with Gk[μ][b] = Γ^μ_{bc} k^c and
/// dGkk[f][μ] = Y_f^ν ∂_ν Γ^μ_{ab} k^a k^b, the field equation is
/// Y_f''^μ = −2 Gk[μ][b] Y_f'^b − dGkk[f][μ].
template <class M>
struct JacobiRHS {
  static constexpr int N = kJacobiDim;
  const M& m;
  void operator()(const double* y, double* dy) const {
    const Vec4 x{{y[0], y[1], y[2], y[3]}};
    const Vec4 k{{y[kJacobiK], y[kJacobiK + 1], y[kJacobiK + 2], y[kJacobiK + 3]}};
    const Vec4 Y[2] = {Vec4{{y[kJacobiY1], y[kJacobiY1 + 1], y[kJacobiY1 + 2], y[kJacobiY1 + 3]}},
                       Vec4{{y[kJacobiY2], y[kJacobiY2 + 1], y[kJacobiY2 + 2], y[kJacobiY2 + 3]}}};
    JacobiTerms t;
    jacobi_terms(m, x, k, Y, t);
    for (int i = 0; i < 4; ++i) dy[i] = k[i];
    for (int v = 0; v < 3; ++v) {  // k, s1, s2: e' = −Γ(k, e)
      const double* e = y + kJacobiK + 4 * v;
      for (int mu = 0; mu < 4; ++mu)
        dy[kJacobiK + 4 * v + mu] =
            -(t.Gk[mu][0] * e[0] + t.Gk[mu][1] * e[1] + t.Gk[mu][2] * e[2] + t.Gk[mu][3] * e[3]);
    }
    for (int f = 0; f < 2; ++f) {
      const double* dY = y + kJacobiDY1 + 8 * f;
      for (int mu = 0; mu < 4; ++mu) {
        dy[kJacobiY1 + 8 * f + mu] = dY[mu];
        dy[kJacobiDY1 + 8 * f + mu] =
            -(2.0 * (t.Gk[mu][0] * dY[0] + t.Gk[mu][1] * dY[1] + t.Gk[mu][2] * dY[2] + t.Gk[mu][3] * dY[3]) +
              t.dGkk[f][mu]);
      }
    }
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

/// Sachs basis at the observer for the local (spatial) ray direction d relative to the observer
/// tetrad e (as Motion4D Geodesic::calcSachsBasis): b1 = ẑ × d̂ / |ẑ × d̂|, b2 = b1 × d̂ (b1 = ŷ,
/// b2 = x̂ when d̂ ∥ ẑ), s_a = b_a^i e_(i). Both are unit, orthogonal to each other, to the observer
/// four-velocity e_(0) and to k = ±e_(0) + d̂^i e_(i).
void sachs_basis(const Tetrad& e, const Vec3& d, Vec4& s1, Vec4& s2);

/// Initial Jacobi state for a ray leaving the observer (position x, tetrad e) in local direction
/// d: k = −e_(0) + d̂^i e_(i) (past-directed, paper eq. 7, so −g(k, e_(0)) = −1 and the affine
/// parameter λ ≥ 0 measures distance back in time), Sachs basis from sachs_basis, Y_b = 0,
/// Y_b' = s_b (a bundle with its vertex at the observer). Integrate with
/// metric.integrate(cfg, GeodesicSystem::Jacobi, y, 0, cb) and direction +1.
void jacobi_initial_state(const Vec4& x, const Tetrad& e, const Vec3& d, double y[kJacobiDim]);

/// Jacobi matrix J_ab = g(s_a, Y_b) of a state of the Jacobi system (header comment).
void jacobi_matrix(const Metric& m, const double* y, double J[4]);

/// Jacobi parameters of a state of the Jacobi system at affine parameter λ (distance from the
/// observer's event).
inline JacobiParams jacobi_params_from_state(const Metric& m, const double* y, double lambda) {
  double J[4];
  jacobi_matrix(m, y, J);
  return jacobi_params(J, lambda);
}

/// Convenience for one ray (tests, the `geovis ray` tools): integrates the Jacobi system from the
/// observer in direction d with cfg (type lightlike, direction +1) until |λ| reaches lambda_end
/// or the integration stops; returns the parameters at the final point and writes the final
/// state to y_out when given.
JacobiParams trace_jacobi(const Metric& m, const SolverConfig& cfg, const Vec4& x, const Tetrad& e, const Vec3& d,
                          double lambda_end, double* y_out = nullptr, GeodesicResult* result = nullptr);

}  // namespace geovis
