// −Γ^μ_{ab} k^a k^b of the Kastor–Traschen spacetime (the symbols of KastorTraschen::christoffel_closed
// in kastor_traschen.cpp contracted by hand), once as a template over the number type:
// kastor_traschen.cpp includes this file once for doubles (the scalar integrator) and once per
// SIMD target for SimdD (spacetime/simd.h, the packet integrator), so both run the same operations
// and give the same bits; the scale factor a = e^{Ht} is exp_t, fast_exp on doubles and its
// lane-by-lane twin on SimdD (fast_math.h). No include guard: each inclusion defines the template
// in the namespace it is included in.
//
// With spatial indices i, j, ∂_μ Ω = (Ω_t, Ω_i), Ω·k = Σ_i Ω_i k^i and |k|² = Σ_i (k^i)², the
// symbols (kastor_traschen.cpp) give
//   a^t = (Ω_t (k^t)² + 2 k^t Ω·k)/Ω − Ω³a²(Ω_t + HΩ) |k|²,
//   a^i = Ω_i (k^t)²/(Ω⁵a²) − 2(Ω_t/Ω + H) k^t k^i − (2 k^i Ω·k − Ω_i |k|²)/Ω,
// the last term being Σ_j Γ^i_jj (k^j)² + 2 Σ_{j≠i} Γ^i_ij k^i k^j = (Ω_i(2(k^i)² − |k|²) +
// 2k^i(Ω·k − Ω_i k^i))/Ω.
/// ds² = −dt²/Ω² + a² Ω² (dx² + dy² + dz²) (kastor_traschen.cpp): g_μμ, the diagonal (the packet's
/// constraint test, diagonal_geodesic_constraint).
template <class T>
GEOVIS_HOT_INLINE void kastor_traschen_metric_diagonal(const KastorTraschenParams& p, const Vec4T<T>& x, T (&g)[4]) {
  using std::sqrt;
  const T a = exp_t(p.h * x[0]);
  const T d1 = x[3] - p.z1, d2 = x[3] - p.z2;
  const T rho2 = x[1] * x[1] + x[2] * x[2];
  const T r1 = sqrt(rho2 + d1 * d1), r2 = sqrt(rho2 + d2 * d2);
  const T Om = 1.0 + (p.m1 / r1 + p.m2 / r2) / a;
  g[0] = -1.0 / (Om * Om);
  const T s = a * a * Om * Om;
  g[1] = s;
  g[2] = s;
  g[3] = s;
}

/// The same as the full g_μν: KastorTraschen::g_tmpl on every number type.
template <class T>
GEOVIS_HOT_INLINE void kastor_traschen_metric_tensor(const KastorTraschenParams& p, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  T d[4];
  kastor_traschen_metric_diagonal(p, x, d);
  for (int i = 0; i < 4; ++i) g[i][i] = d[i];
}

/// KastorTraschen::is_valid (kastor_traschen.cpp, which says why) on any number type: the
/// validity domain without the black holes' break margins (r_break1, r_break2) and where the
/// squared redshift factor 1/Ω² falls below horizon_eps; a bool on doubles, a lane mask on SimdD.
template <class T>
GEOVIS_HOT_INLINE auto kastor_traschen_valid(const KastorTraschenParams& p, double r_break1, double r_break2,
                                             double horizon_eps, const Vec4T<T>& x) {
  using std::isfinite;
  using std::sqrt;
  auto valid = isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]) && isfinite(x[3]);
  const T rho2 = x[1] * x[1] + x[2] * x[2];
  const T d1 = x[3] - p.z1, d2 = x[3] - p.z2;
  const T q1 = rho2 + d1 * d1, q2 = rho2 + d2 * d2;
  if (p.m1 > 0) valid = valid && q1 > T(r_break1 * r_break1);
  if (p.m2 > 0) valid = valid && q2 > T(r_break2 * r_break2);
  const T sum = (p.m1 > 0 ? p.m1 / sqrt(q1) : T(0.0)) + (p.m2 > 0 ? p.m2 / sqrt(q2) : T(0.0));
  const T Om = 1.0 + sum / exp_t(p.h * x[0]);
  return valid && 1.0 / (Om * Om) > T(horizon_eps);
}

template <class T>
GEOVIS_HOT_INLINE void kastor_traschen_accel(const KastorTraschenParams& p, const Vec4T<T>& x, const Vec4T<T>& k,
                                             Vec4T<T>& acc) {
  using std::sqrt;
  const T a = exp_t(p.h * x[0]);
  const T ia = 1.0 / a;
  const T d1 = x[3] - p.z1, d2 = x[3] - p.z2;
  const T rho2 = x[1] * x[1] + x[2] * x[2];
  const T ir1 = 1.0 / sqrt(rho2 + d1 * d1), ir2 = 1.0 / sqrt(rho2 + d2 * d2);
  const T s1 = p.m1 * ir1, s2 = p.m2 * ir2;                    // m_i / r_i
  const T q1 = s1 * ir1 * ir1 * ia, q2 = s2 * ir2 * ir2 * ia;  // m_i / (a r_i³)
  const T om1 = (s1 + s2) * ia;                                // Ω − 1
  const T om = 1.0 + om1;
  const T q12 = q1 + q2;
  // ∂_μ Ω: Ω_i = −Σ m_k (x − x_k)_i / (a r_k³), Ω_t = −H (Ω − 1).
  const T dt = -p.h * om1, dx = -q12 * x[1], dy = -q12 * x[2], dz = -(q1 * d1 + q2 * d2);
  const T iom = 1.0 / om;
  const T om2 = om * om;
  const T a2 = a * a;
  const T kk = k[1] * k[1] + k[2] * k[2] + k[3] * k[3];
  const T ok = dx * k[1] + dy * k[2] + dz * k[3];
  const T kt2 = k[0] * k[0];
  acc[0] = (dt * kt2 + 2.0 * k[0] * ok) * iom - om2 * om * a2 * (dt + p.h * om) * kk;
  const T c_tt = kt2 * iom / (om2 * om2 * a2);  // (k^t)²/(Ω⁵a²)
  const T c_ti = 2.0 * (dt * iom + p.h) * k[0];
  acc[1] = dx * c_tt - c_ti * k[1] - (2.0 * k[1] * ok - dx * kk) * iom;
  acc[2] = dy * c_tt - c_ti * k[2] - (2.0 * k[2] * ok - dy * kk) * iom;
  acc[3] = dz * c_tt - c_ti * k[3] - (2.0 * k[3] * ok - dz * kk) * iom;
}
