// g_μμ, their derivatives and −Γ^μ_{ab} k^a k^b of Schwarzschild in isotropic coordinates
// (schwarzschild_isotropic.cpp), once as a template over the number type:
// schwarzschild_isotropic.cpp includes this file once for doubles (the scalar integrator) and
// once per SIMD target for SimdD (spacetime/simd.h, the packet integrator), after
// diagonal_metric_accel.h in the same namespace, so both run the same operations and give the
// same bits. No include guard: each inclusion defines the templates in the namespace it is
// included in.

/// g_μν of SchwarzschildIsotropic (schwarzschild_isotropic.cpp): SchwarzschildIsotropic::g_tmpl on
/// every number type, and on SIMD lanes the packet integrator's constraint test.
template <class T>
GEOVIS_HOT_INLINE void schwarzschild_isotropic_metric_tensor(double rho_s, const Vec4T<T>& x, Mat4T<T>& g) {
  using std::sqrt;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T rho = sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  const T alpha = (rho - rho_s) / (rho + rho_s);  // (1 − ρ_s/ρ)/(1 + ρ_s/ρ)
  const T psi = 1.0 + rho_s / rho;
  const T psi2 = psi * psi;
  g[0][0] = -alpha * alpha;
  g[1][1] = g[2][2] = g[3][3] = psi2 * psi2;
}

/// ∂_j g_tt = −2α α' n_j with α' = 2ρ_s/(ρ + ρ_s)²; ∂_j g_ii = 4ψ³ ψ' n_j with ψ' = −ρ_s/ρ²,
/// n_j = x_j/ρ (α = (ρ − ρ_s)/(ρ + ρ_s), ψ = 1 + ρ_s/ρ: Catalogue of Spacetimes, "Schwarzschild
/// spacetime / Isotropic coordinates").
template <class T>
GEOVIS_HOT_INLINE void schwarzschild_isotropic_diagonal(double rho_s, const Vec4T<T>& x, DiagonalMetricT<T>& d) {
  using std::sqrt;
  const T rho = sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  const T rp = rho + rho_s;
  const T alpha = (rho - rho_s) / rp;
  const T dalpha = 2.0 * rho_s / (rp * rp);
  const T psi = 1.0 + rho_s / rho;
  const T psi3 = psi * psi * psi;
  const T dpsi = -rho_s / (rho * rho);
  const T dtt = -2.0 * alpha * dalpha, dss = 4.0 * psi3 * dpsi;
  for (int mu = 0; mu < 4; ++mu) d.dh[0][mu] = T(0.0);
  d.h[0] = -alpha * alpha;
  d.h[1] = d.h[2] = d.h[3] = psi3 * psi;
  for (int j = 1; j < 4; ++j) {
    const T n = x[j] / rho;
    d.dh[j][0] = dtt * n;
    d.dh[j][1] = d.dh[j][2] = d.dh[j][3] = dss * n;
  }
}

template <class T>
GEOVIS_HOT_INLINE void schwarzschild_isotropic_accel(double rho_s, const Vec4T<T>& x, const Vec4T<T>& k, Vec4T<T>& a) {
  DiagonalMetricT<T> d;
  schwarzschild_isotropic_diagonal(rho_s, x, d);
  diagonal_accel(d, k, a);
}
