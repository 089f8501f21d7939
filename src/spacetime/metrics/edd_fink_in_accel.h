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
/// why), E = k^v − k^r/(1 + w), w = sqrt(r_s/r); g(k,k) = Σ_ij g_ij k^i k^j summed in the order
/// i, j of vec.h's dot, over the entries of edd_fink_in_metric_tensor that are not identically
/// zero: the others add g_ij k^i k^j = ±0, which leaves the sum as it is (a sum started at +0 is
/// never −0, and x + ±0 = x otherwise), so the result has the same bits as the full sum for every
/// finite k. (Where a k^i is ±∞ the full sum is NaN and this one may be ±∞; both fail the
/// constraint test, which the integrators run on finite accepted states only.)
template <class T>
GEOVIS_HOT_INLINE T edd_fink_in_constraint_norm(double rs, const Vec4T<T>& x, const Mat4T<T>& g, const Vec4T<T>& k) {
  using std::sqrt;
  const T w = sqrt(rs / x[1]);
  const T E = k[0] - k[1] / (1.0 + w);
  T gkk(0.0);
  gkk += g[0][0] * k[0] * k[0];
  gkk += g[0][1] * k[0] * k[1];
  gkk += g[1][0] * k[1] * k[0];
  gkk += g[2][2] * k[2] * k[2];
  gkk += g[3][3] * k[3] * k[3];
  return gkk + 2.0 * E * E;
}

/// −Γ^μ_{ab} k^a k^b with the symbols of EddFinkIn::christoffel_closed (Catalogue of Spacetimes,
/// Eddington–Finkelstein coordinates), with u = 1/r:
///   Γ^v_vv = −Γ^r_vr = r_s/(2r²) = ½ r_s u·u,   Γ^r_vv = r_s (r − r_s)/(2r³) = Γ^v_vv·(r − r_s) u,
///   Γ^θ_rθ = Γ^φ_rφ = u,   Γ^φ_θφ k^θ k^φ = k^θ k^φ cos θ / sin θ.
/// Two divisions instead of five (issue 13: the divider is the slowest unit of a stage), and the
/// factors that wait for sin θ and cos θ (the last to be known: sincos_t is the longest chain of a
/// stage) multiplied last. The products differ from the quotients by rounding only (tests: the
/// symbols against automatic differentiation, test_metrics_registry.cpp).
template <class T>
GEOVIS_HOT_INLINE void edd_fink_in_accel(double rs, const Vec4T<T>& x, const Vec4T<T>& k, Vec4T<T>& a) {
  const T r = x[1];
  T st, ct;
  sincos_t(x[2], st, ct);
  const T inv_r = 1.0 / r;
  const T rmrs = r - rs;
  const T G_vvv = 0.5 * (rs * inv_r * inv_r);  // Γ^v_vv = −Γ^r_vr
  const T G_rvv = G_vvv * (rmrs * inv_r);      // Γ^r_vv
  const T k3k3 = k[3] * k[3];
  const T ang = k[2] * k[2] + st * st * k3k3;  // −Γ^v_θθ k^θ k^θ − Γ^v_φφ k^φ k^φ, divided by r
  a[0] = -G_vvv * k[0] * k[0] + r * ang;
  a[1] = -G_rvv * k[0] * k[0] + 2.0 * G_vvv * k[0] * k[1] + rmrs * ang;
  a[2] = -2.0 * inv_r * k[1] * k[2] + st * ct * k3k3;
  a[3] = -2.0 * inv_r * k[1] * k[3] - 2.0 * k[2] * k[3] * ct / st;
}
