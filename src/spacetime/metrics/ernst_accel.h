// g_μμ, their r- and θ-derivatives and −Γ^μ_{ab} k^a k^b of Ernst (ernst.cpp), once as a template
// over the number type: ernst.cpp includes this file once for doubles (the scalar integrator) and
// once per SIMD target for SimdD (spacetime/simd.h, the packet integrator), after
// diagonal_metric_accel.h in the same namespace, so both run the same operations and give the
// same bits. No include guard: each inclusion defines the templates in the namespace it is
// included in.

/// g_μν of Ernst (ernst.cpp): Ernst::g_tmpl on every number type, and on SIMD lanes the packet
/// integrator's constraint test.
template <class T>
GEOVIS_HOT_INLINE void ernst_metric_tensor(double B2, double rs, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T& r = x[1];
  const T st = sin_t(x[2]);
  const T f = 1.0 - rs / r;
  const T L = 1.0 + B2 * r * r * st * st;
  const T L2 = L * L;
  g[0][0] = -L2 * f;
  g[1][1] = L2 / f;
  g[2][2] = L2 * r * r;
  g[3][3] = r * r * st * st / L2;
}

/// g_μμ of ds² = Λ² [−f dt² + dr²/f + r² dθ²] + r² sin²θ / Λ² dφ² (Catalogue of Spacetimes,
/// "Ernst spacetime") and their derivatives, with Λ_r = 2B² r sin²θ, Λ_θ = 2B² r² sinθ cosθ,
/// f_r = 2M/r² (product and quotient rule on the line element).
template <class T>
GEOVIS_HOT_INLINE void ernst_diagonal(double B2, double rs, const Vec4T<T>& x, DiagonalMetricT<T>& d) {
  const T r = x[1];
  T st, ct;
  sincos_t(x[2], st, ct);
  const T f = 1.0 - rs / r, df = rs / (r * r);
  const T L = 1.0 + B2 * r * r * st * st;
  const T Lr = 2.0 * B2 * r * st * st, Lth = 2.0 * B2 * r * r * st * ct;
  const T L2 = L * L;
  for (int c = 0; c < 4; ++c)
    for (int mu = 0; mu < 4; ++mu) d.dh[c][mu] = T(0.0);
  d.h[0] = -L2 * f;
  d.h[1] = L2 / f;
  d.h[2] = L2 * r * r;
  d.h[3] = r * r * st * st / L2;
  // ∂_r
  d.dh[1][0] = -(2.0 * L * Lr * f + L2 * df);
  d.dh[1][1] = 2.0 * L * Lr / f - L2 * df / (f * f);
  d.dh[1][2] = 2.0 * L * Lr * r * r + 2.0 * L2 * r;
  d.dh[1][3] = 2.0 * r * st * st / L2 - 2.0 * r * r * st * st * Lr / (L2 * L);
  // ∂_θ
  d.dh[2][0] = -2.0 * L * Lth * f;
  d.dh[2][1] = 2.0 * L * Lth / f;
  d.dh[2][2] = 2.0 * L * Lth * r * r;
  d.dh[2][3] = 2.0 * r * r * st * ct / L2 - 2.0 * r * r * st * st * Lth / (L2 * L);
}

template <class T>
GEOVIS_HOT_INLINE void ernst_accel(double B2, double rs, const Vec4T<T>& x, const Vec4T<T>& k, Vec4T<T>& a) {
  DiagonalMetricT<T> d;
  ernst_diagonal(B2, rs, x, d);
  diagonal_accel(d, k, a);
}
