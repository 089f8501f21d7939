// g_μν, the constraint test's size of k (EddFinkIn::constraint_norm) and −Γ^μ_{ab} k^a k^b (the
// symbols of EddFinkIn::christoffel_closed written out) of Schwarzschild in ingoing
// Eddington–Finkelstein coordinates (edd_fink_in.cpp), once as templates over the number type:
// edd_fink_in.cpp includes this file once for doubles and dual numbers (the scalar integrator,
// g_tmpl) and once per SIMD target for SimdD (spacetime/simd.h, the packet integrator), so both run
// the same operations and give the same bits. No include guard: each inclusion defines the
// templates in the namespace it is included in.

/// ds² = −(1 − r_s/r) dv² + 2 dv dr + r² (dθ² + sin²θ dφ²) (edd_fink_in.cpp).
template <class T>
GEOVIS_HOT_INLINE void edd_fink_in_metric_tensor(double rs, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T& r = x[1];
  const T st = sin_t(x[2]);
  g[0][0] = -(1.0 - rs / r);
  g[0][1] = g[1][0] = T(1.0);
  g[2][2] = r * r;
  g[3][3] = r * r * st * st;
}

/// h(k,k) = g(k,k) + 2E² of the free-falling observer (EddFinkIn::constraint_norm, which says
/// why), E = k^v − k^r/(1 + w), w = sqrt(r_s/r); g(k,k) summed as vec.h's dot.
template <class T>
GEOVIS_HOT_INLINE T edd_fink_in_constraint_norm(double rs, const Vec4T<T>& x, const Mat4T<T>& g, const Vec4T<T>& k) {
  using std::sqrt;
  const T w = sqrt(rs / x[1]);
  const T E = k[0] - k[1] / (1.0 + w);
  T gkk(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) gkk += g[i][j] * k[i] * k[j];
  return gkk + 2.0 * E * E;
}

template <class T>
GEOVIS_HOT_INLINE void edd_fink_in_accel(double rs, const Vec4T<T>& x, const Vec4T<T>& k, Vec4T<T>& a) {
  const T r = x[1];
  T st, ct;
  sincos_t(x[2], st, ct);
  const T rmrs = r - rs;
  const T ang = k[2] * k[2] + st * st * k[3] * k[3];
  a[0] = -rs / (2.0 * r * r) * k[0] * k[0] + r * ang;
  a[1] = -rs * rmrs / (2.0 * r * r * r) * k[0] * k[0] + rs / (r * r) * k[0] * k[1] + rmrs * ang;
  a[2] = -2.0 / r * k[1] * k[2] + st * ct * k[3] * k[3];
  a[3] = -2.0 / r * k[1] * k[3] - 2.0 * ct / st * k[2] * k[3];
}
