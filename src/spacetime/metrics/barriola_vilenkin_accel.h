// g_μμ, their r-derivatives and −Γ^μ_{ab} k^a k^b of the Barriola–Vilenkin monopole
// (barriola_vilenkin.cpp), once as a template over the number type: barriola_vilenkin.cpp
// includes this file once for doubles (the scalar integrator) and once per SIMD target for SimdD
// (spacetime/simd.h, the packet integrator), after diagonal_metric_accel.h in the same namespace,
// so both run the same operations and give the same bits. No include guard: each inclusion
// defines the templates in the namespace it is included in.

/// g_μν of BarriolaVilenkin (barriola_vilenkin.cpp): BarriolaVilenkin::g_tmpl on every number type,
/// and on SIMD lanes the packet integrator's constraint test.
template <class T>
GEOVIS_HOT_INLINE void barriola_vilenkin_metric_tensor(double k2, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T& r = x[1];
  const T st = sin_t(x[2]);
  g[0][0] = T(-1.0);
  g[1][1] = T(1.0);
  g[2][2] = k2 * r * r;
  g[3][3] = k2 * r * r * st * st;
}

/// A = B = 1, C = k² r², C' = 2k² r (Catalogue of Spacetimes, "Barriola-Vilenkin monopole").
template <class T>
GEOVIS_HOT_INLINE void barriola_vilenkin_diagonal(double k2, const Vec4T<T>& x, DiagonalMetricT<T>& d) {
  const T r = x[1];
  spherical_diagonal<T>(1.0, 0.0, 1.0, 0.0, k2 * r * r, 2.0 * k2 * r, x[2], d);
}

template <class T>
GEOVIS_HOT_INLINE void barriola_vilenkin_accel(double k2, const Vec4T<T>& x, const Vec4T<T>& k, Vec4T<T>& a) {
  DiagonalMetricT<T> d;
  barriola_vilenkin_diagonal(k2, x, d);
  diagonal_accel(d, k, a);
}
