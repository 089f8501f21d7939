// g_μμ, their derivatives and −Γ^μ_{ab} k^a k^b of Schwarzschild pierced by a cosmic string
// (cosmic_string_schwarzschild.cpp), once as a template over the number type:
// cosmic_string_schwarzschild.cpp includes this file once for doubles (the scalar integrator) and
// once per SIMD target for SimdD (spacetime/simd.h, the packet integrator), after
// diagonal_metric_accel.h in the same namespace, so both run the same operations and give the
// same bits. No include guard: each inclusion defines the templates in the namespace it is
// included in.

/// g_μν of CosmicStringSchwarzschild (cosmic_string_schwarzschild.cpp):
/// CosmicStringSchwarzschild::g_tmpl on every number type, and on SIMD lanes the packet
/// integrator's constraint test.
template <class T>
GEOVIS_HOT_INLINE void cosmic_string_schwarzschild_metric_tensor(double rs, double b2, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T& r = x[1];
  const T f = 1.0 - rs / r;
  const T st = sin_t(x[2]);
  g[0][0] = -f;
  g[1][1] = 1.0 / f;
  g[2][2] = r * r;
  g[3][3] = b2 * r * r * st * st;
}

/// Schwarzschild's A = f = 1 − r_s/r, B = 1/f, C = r², with g_φφ and its derivatives multiplied by
/// β² (the conical deficit; Aryal, Ford & Vilenkin, Phys. Rev. D 34 (1986) 2263).
template <class T>
GEOVIS_HOT_INLINE void cosmic_string_schwarzschild_diagonal(double rs, double b2, const Vec4T<T>& x,
                                                            DiagonalMetricT<T>& d) {
  const T r = x[1], f = 1.0 - rs / r, df = rs / (r * r);
  spherical_diagonal<T>(f, df, 1.0 / f, -df / (f * f), r * r, 2.0 * r, x[2], d);
  d.h[3] *= b2;
  for (int c = 0; c < 4; ++c) d.dh[c][3] *= b2;
}

template <class T>
GEOVIS_HOT_INLINE void cosmic_string_schwarzschild_accel(double rs, double b2, const Vec4T<T>& x, const Vec4T<T>& k,
                                                         Vec4T<T>& a) {
  DiagonalMetricT<T> d;
  cosmic_string_schwarzschild_diagonal(rs, b2, x, d);
  diagonal_accel(d, k, a);
}
