// −Γ^μ_{ab} k^a k^b of the Morris–Thorne wormhole (the symbols of MorrisThorne::christoffel_closed
// in morris_thorne.cpp written out), once as a template over the number type: morris_thorne.cpp
// includes this file once for doubles (the scalar integrator) and once per SIMD target for SimdD
// (spacetime/simd.h, the packet integrator), so both run the same operations and give the same
// bits. No include guard: each inclusion defines the template in the namespace it is included in.
/// ds² = −dt² + dl² + (b0² + l²)(dθ² + sin²θ dφ²) (morris_thorne.cpp): g_μμ, the diagonal (the
/// packet's constraint test, diagonal_geodesic_constraint).
template <class T>
GEOVIS_HOT_INLINE void morris_thorne_metric_diagonal(double b02, const Vec4T<T>& x, T (&g)[4]) {
  const T r2 = b02 + x[1] * x[1];
  const T st = sin_t(x[2]);
  g[0] = T(-1.0);
  g[1] = T(1.0);
  g[2] = r2;
  g[3] = r2 * st * st;
}

/// The same as the full g_μν: MorrisThorne::g_tmpl on every number type.
template <class T>
GEOVIS_HOT_INLINE void morris_thorne_metric_tensor(double b02, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  T d[4];
  morris_thorne_metric_diagonal(b02, x, d);
  for (int i = 0; i < 4; ++i) g[i][i] = d[i];
}

/// −Γ^μ_{ab} k^a k^b with the symbols of MorrisThorne::christoffel_closed: a^l = l ((k^θ)² +
/// sin²θ (k^φ)²), a^θ = −2 l/(b0² + l²) k^l k^θ + sinθ cosθ (k^φ)², a^φ = −2 l/(b0² + l²) k^l k^φ −
/// 2 cotθ k^θ k^φ. (k^φ)² is formed once, and the factors that wait for sin θ and cos θ (sincos_t is
/// the longest chain of a stage) are multiplied last, cos θ/sin θ divided last (as
/// edd_fink_in_accel; issue 13: two products fewer, −0.7 % of this function's instructions); the
/// products differ from the former order by rounding only (morristhorne.scm's image and steps are
/// unchanged; tests: the symbols against automatic differentiation, test_metrics_other.cpp).
template <class T>
GEOVIS_HOT_INLINE void morris_thorne_accel(double b02, const Vec4T<T>& x, const Vec4T<T>& k, Vec4T<T>& a) {
  const T l = x[1];
  T st, ct;
  sincos_t(x[2], st, ct);
  const T lr2 = l / (b02 + l * l);
  const T k3k3 = k[3] * k[3];
  const T k2k3x2 = 2.0 * k[2] * k[3];
  a[0] = T(0.0);
  a[1] = l * (k[2] * k[2] + st * st * k3k3);
  a[2] = -2.0 * lr2 * k[1] * k[2] + st * ct * k3k3;
  a[3] = -2.0 * lr2 * k[1] * k[3] - k2k3x2 * ct / st;
}
