// g_μμ, their r-derivatives and −Γ^μ_{ab} k^a k^b of Reissner–Nordström (reissner_nordstrom.cpp),
// once as a template over the number type: reissner_nordstrom.cpp includes this file once for
// doubles (the scalar integrator) and once per SIMD target for SimdD (spacetime/simd.h, the packet
// integrator), after diagonal_metric_accel.h in the same namespace, so both run the same
// operations and give the same bits. No include guard: each inclusion defines the templates in the
// namespace it is included in.

/// g_μν of ReissnerNordstrom (reissner_nordstrom.cpp): ReissnerNordstrom::g_tmpl on every number
/// type, and on SIMD lanes the packet integrator's constraint test.
template <class T>
GEOVIS_HOT_INLINE void reissner_nordstrom_metric_tensor(double M, double Q2, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T& r = x[1];
  const T f = 1.0 - 2.0 * M / r + Q2 / (r * r);
  const T st = sin_t(x[2]);
  g[0][0] = -f;
  g[1][1] = 1.0 / f;
  g[2][2] = r * r;
  g[3][3] = r * r * st * st;
}

/// f = 1 − 2M/r + Q²/r², f' = 2M/r² − 2Q²/r³, (1/f)' = −f'/f² (Catalogue of Spacetimes,
/// "Reissner-Nordström").
template <class T>
GEOVIS_HOT_INLINE void reissner_nordstrom_diagonal(double M, double Q2, const Vec4T<T>& x, DiagonalMetricT<T>& d) {
  const T r = x[1];
  const T f = 1.0 - 2.0 * M / r + Q2 / (r * r);
  const T df = 2.0 * M / (r * r) - 2.0 * Q2 / (r * r * r);
  spherical_diagonal<T>(f, df, 1.0 / f, -df / (f * f), r * r, 2.0 * r, x[2], d);
}

template <class T>
GEOVIS_HOT_INLINE void reissner_nordstrom_accel(double M, double Q2, const Vec4T<T>& x, const Vec4T<T>& k,
                                                Vec4T<T>& a) {
  DiagonalMetricT<T> d;
  reissner_nordstrom_diagonal(M, Q2, x, d);
  diagonal_accel(d, k, a);
}
