// g_μμ, their r-derivatives and −Γ^μ_{ab} k^a k^b of the Barriola–Vilenkin monopole
// (barriola_vilenkin.cpp), once as a template over the number type: barriola_vilenkin.cpp
// includes this file once for doubles (the scalar integrator) and once per SIMD target for SimdD
// (spacetime/simd.h, the packet integrator), after diagonal_metric_accel.h in the same namespace,
// so both run the same operations and give the same bits. No include guard: each inclusion
// defines the templates in the namespace it is included in.

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
