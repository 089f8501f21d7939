// g_μν and −Γ^μ_{ab} k^a k^b of Schwarzschild (Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184, §2.2.1, contracted with k), written once as templates over the number type:
// schwarzschild.cpp includes this file once for doubles (the scalar integrator) and once per SIMD
// target for SimdD (spacetime/simd.h, the packet integrator), so both run the same operations and
// give the same bits. No include guard: each inclusion defines the templates in the namespace it is
// included in.
template <class T>
GEOVIS_HOT_INLINE void schwarzschild_accel(double rs, const Vec4T<T>& x, const Vec4T<T>& k, Vec4T<T>& a) {
  const T r = x[1];
  T st, ct;
  sincos_t(x[2], st, ct);
  const T rmrs = r - rs;
  const T c_ttr = rs / (2.0 * r * rmrs);
  a[0] = -2.0 * c_ttr * k[0] * k[1];
  a[1] = -(rs * rmrs / (2.0 * r * r * r)) * k[0] * k[0] + c_ttr * k[1] * k[1] +
         rmrs * (k[2] * k[2] + st * st * k[3] * k[3]);
  a[2] = -2.0 / r * k[1] * k[2] + st * ct * k[3] * k[3];
  a[3] = -2.0 / r * k[1] * k[3] - 2.0 * ct / st * k[2] * k[3];
}

/// g_μν of Schwarzschild (schwarzschild.cpp): Schwarzschild::g_tmpl on every number type, and on
/// SIMD lanes the packet integrator's constraint test.
template <class T>
GEOVIS_HOT_INLINE void schwarzschild_metric_tensor(double rs, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T& r = x[1];
  const T f = 1.0 - rs / r;
  const T st = sin_t(x[2]);
  g[0][0] = -f;
  g[1][1] = 1.0 / f;
  g[2][2] = r * r;
  g[3][3] = r * r * st * st;
}
