// The number-type templates of diagonal_metric.h (formulas there): the diagonal g_μμ and their
// derivatives, the static spherical line element, and a^i = −Γ^i_{ab} k^a k^b. diagonal_metric.h
// includes this file for doubles in namespace geovis (the scalar integrator); a metric file that
// Highway compiles per SIMD target includes it again in geovis::HWY_NAMESPACE for SimdD
// (spacetime/simd.h, the packet integrator), so both paths run the same operations and give the
// same bits (as kastor_traschen_accel.h). No include guard: each inclusion defines the templates
// in the namespace it is included in.

/// h[μ] = g_{μμ}; dh[c][μ] = ∂_c g_{μμ}.
template <class T>
struct DiagonalMetricT {
  T h[4];
  T dh[4][4];
};

/// Fills d for a static, spherically symmetric line element in (t, r, θ, φ):
///   ds² = −A(r) dt² + B(r) dr² + C(r) (dθ² + sin²θ dφ²),
/// given A, B, C and their r-derivatives.
template <class T>
GEOVIS_HOT_INLINE void spherical_diagonal(const T& A, const T& dA, const T& B, const T& dB, const T& C, const T& dC,
                                          const T& theta, DiagonalMetricT<T>& d) {
  T st, ct;
  sincos_t(theta, st, ct);
  for (int c = 0; c < 4; ++c)
    for (int mu = 0; mu < 4; ++mu) d.dh[c][mu] = T(0.0);
  d.h[0] = -A;
  d.h[1] = B;
  d.h[2] = C;
  d.h[3] = C * st * st;
  d.dh[1][0] = -dA;
  d.dh[1][1] = dB;
  d.dh[1][2] = dC;
  d.dh[1][3] = dC * st * st;
  d.dh[2][3] = 2.0 * C * st * ct;
}

/// a^i = −Γ^i_{ab} k^a k^b = −(1 / 2h_i) (2 k^i Σ_j ∂_j h_i k^j − Σ_j ∂_i h_j (k^j)²), which is the
/// contraction of the three cases of diagonal_metric.h (the j = i terms of both sums give
/// Γ^i_{ii}). Always inlined: it is the hot path of every diagonal metric, and in a unity unit of
/// several metrics (CMakeLists.txt) GCC stopped inlining it into their integrators.
template <class T>
GEOVIS_HOT_INLINE void diagonal_accel(const DiagonalMetricT<T>& d, const Vec4T<T>& k, Vec4T<T>& a) {
  for (int i = 0; i < 4; ++i) {
    T s1 = 0.0, s2 = 0.0;
    for (int j = 0; j < 4; ++j) {
      s1 += d.dh[j][i] * k[j];
      s2 += d.dh[i][j] * k[j] * k[j];
    }
    a[i] = -(2.0 * k[i] * s1 - s2) * (0.5 / d.h[i]);
  }
}
