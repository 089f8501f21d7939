// The constraint test of the geodesic system (MetricSystem::constraint, integrators.h) as a template
// over the number type: integrators.h includes this file in namespace geovis for one ray on
// doubles, and simd.h includes it in each SIMD target's namespace (geovis::HWY_NAMESPACE) for a
// packet of rays on SimdD lanes (packet_constraint_simd), where its instantiation must be compiled
// with that target's instruction set. The conditions are bools on doubles and lane masks on SimdD
// (select, all_of, none_of: vec.h and simd.h), and each lane runs the operations of the scalar
// code in the same order, so the packet integrator's constraint stops are the scalar ones to the
// bit (tests/spacetime/test_geodesic_packet.cpp). No include guard: each inclusion defines the
// templates in the namespace it is included in.

/// Σ_{μν} |g_μν k^μ k^ν|, the size of k where neither the slicing observer nor the metric gives
/// one (geodesic_constraint).
template <class T>
GEOVIS_HOT_INLINE T abs_quadratic_form(const Mat4T<T>& g, const Vec4T<T>& k) {
  using std::fabs;
  T h(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) h += fabs(g[i][j] * k[i] * k[j]);
  return h;
}

/// value = g(k,k) − target; scale = a positive-definite size of k (never below |target|), so the
/// constraint test |value| <= constraint_tol·scale is relative and stays meaningful where k^0
/// diverges (horizons) and where the terms of g(k,k) are small or cancel (off-diagonal metrics).
///
/// scale = h(k,k) = g(k,k) + 2 (n·k)², the Euclidean norm² of k in an orthonormal frame of the
/// observer n: n is the unit normal of the slices x^0 = const (the "Eulerian" observer of the
/// 3+1 split, n·k = −α k^0, α² = −1/g^{00} = β^T γ^{-1} β − g_00 with γ_ij = g_ij, β_i = g_0i);
/// for a diagonal metric this is exactly Σ_μ |g_μμ| (k^μ)², the size of the terms that cancel in
/// g(k,k). Where x^0 is no time coordinate (γ not positive definite, e.g. the null coordinate v
/// of EddFinkIn) h = no_observer_norm(): the metric's own size of k (h for an observer of its own,
/// MetricSystem::constraint) or abs_quadratic_form.
template <class T, class NoObserverNorm>
GEOVIS_HOT_INLINE void geodesic_constraint(const Mat4T<T>& g, const Vec4T<T>& k, double target,
                                           const NoObserverNorm& no_observer_norm, T& value, T& scale) {
  using std::fabs;
  T s(0.0);
  for (int i = 0; i < 4; ++i) {
    s += g[i][i] * k[i] * k[i];
    for (int j = i + 1; j < 4; ++j) s += 2.0 * g[i][j] * k[i] * k[j];
  }
  value = s - target;
  T h(-1.0);
  const T b1 = g[0][1], b2 = g[0][2], b3 = g[0][3];
  const auto diagonal = b1 == T(0.0) && b2 == T(0.0) && b3 == T(0.0);
  // α² = −g_00
  if (!none_of(diagonal)) h = select(diagonal && g[0][0] < T(0.0), s - 2.0 * g[0][0] * k[0] * k[0], h);
  // γ positive definite (Sylvester: g_11 > 0, its 2×2 and 3×3 minors > 0) and
  // α² = β^T adj(γ) β / det γ − g_00; the minors only where g_11 > 0 on some lane (not in
  // EddFinkIn, whose g_11 = 0: the null coordinate v).
  const auto g11_positive = !diagonal && g[1][1] > T(0.0);
  if (!none_of(g11_positive)) {
    const T g11 = g[1][1], g12 = g[1][2], g13 = g[1][3], g22 = g[2][2], g23 = g[2][3], g33 = g[3][3];
    const T c11 = g22 * g33 - g23 * g23, c12 = g13 * g23 - g12 * g33, c13 = g12 * g23 - g13 * g22;
    const T c22 = g11 * g33 - g13 * g13, c23 = g12 * g13 - g11 * g23, c33 = g11 * g22 - g12 * g12;
    const T det = g11 * c11 + g12 * c12 + g13 * c13;
    const auto slicing = g11_positive && c33 > T(0.0) && det > T(0.0);
    if (!none_of(slicing)) {
      const T q = b1 * (c11 * b1 + c12 * b2 + c13 * b3) + b2 * (c12 * b1 + c22 * b2 + c23 * b3) +
                  b3 * (c13 * b1 + c23 * b2 + c33 * b3);
      const T alpha2 = q / det - g[0][0];
      h = select(slicing && alpha2 > T(0.0), s + 2.0 * alpha2 * k[0] * k[0], h);
    }
  }
  const auto no_observer = !(h > T(0.0));
  if (!none_of(no_observer)) h = select(no_observer, no_observer_norm(), h);
  // std::max(h, |target|), NaN h kept.
  const T abs_target = fabs(T(target));
  scale = select(h < abs_target, abs_target, h);
}

/// geodesic_constraint for a diagonal metric g = diag(g_0, g_1, g_2, g_3), without the terms of the
/// entries that are identically zero: g(k,k) = Σ_i g_i (k^i)² summed in geodesic_constraint's
/// order, whose skipped terms 2·0·k^i k^j are ±0 for finite k and leave the sum as it is (a sum
/// started at +0 is never −0, and x + ±0 = x otherwise); with β = 0 the observer's h(k,k) is
/// g(k,k) − 2 g_0 (k^0)² where g_0 < 0 (the Sylvester minors are never reached), and the fallback
/// abs_quadratic_form is Σ_i |g_i (k^i)²| (its skipped terms are +0). So value and scale have the
/// bits of geodesic_constraint with abs_quadratic_form for every finite k (where a k^i is ±∞ that
/// one is NaN and this one may be ±∞; both fail the constraint test, which the integrators run on
/// finite accepted states only). Issue 13: −16 % (morristhorne.scm) and −19 % (kastorTraschen.scm)
/// of the packet constraint's instructions (callgrind) against geodesic_constraint.
template <class T>
GEOVIS_HOT_INLINE void diagonal_geodesic_constraint(const T (&g)[4], const Vec4T<T>& k, double target, T& value,
                                                    T& scale) {
  using std::fabs;
  T s(0.0);
  for (int i = 0; i < 4; ++i) s += g[i] * k[i] * k[i];
  value = s - target;
  T h = select(g[0] < T(0.0), s - 2.0 * g[0] * k[0] * k[0], T(-1.0));  // α² = −g_00
  const auto no_observer = !(h > T(0.0));
  if (!none_of(no_observer)) {
    T q(0.0);
    for (int i = 0; i < 4; ++i) q += fabs(g[i] * k[i] * k[i]);
    h = select(no_observer, q, h);
  }
  // std::max(h, |target|), NaN h kept.
  const T abs_target = fabs(T(target));
  scale = select(h < abs_target, abs_target, h);
}
