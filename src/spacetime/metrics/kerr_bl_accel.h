// g_μν and −Γ^μ_{ab} k^a k^b of Kerr in Boyer–Lindquist coordinates, the latter through the
// derivatives of g (see KerrBL::accel_closed in kerr_bl.cpp for the method), written once as
// templates over the number type: kerr_bl.cpp includes this file once for doubles and dual numbers
// (the scalar integrator, g_tmpl) and once per SIMD target for SimdD (spacetime/simd.h, the packet
// integrator), so both run the same operations and give the same bits. No include guard: each
// inclusion defines the templates in the namespace it is included in.

/// The Kerr line element in Boyer–Lindquist coordinates (kerr_bl.cpp), r_s = 2M.
template <class T>
GEOVIS_HOT_INLINE void kerr_bl_metric_tensor(double rs, double a, double a2, const Vec4T<T>& x, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T& r = x[1];
  T st, ct;
  sincos_t(x[2], st, ct);
  const T st2 = st * st;
  const T sigma = r * r + a2 * (ct * ct);
  const T delta = r * r - rs * r + a2;
  const T u = rs * r / sigma;  // one division (the constraint test evaluates g every step)
  g[0][0] = u - 1.0;
  g[0][3] = g[3][0] = -a * st2 * u;
  g[1][1] = sigma / delta;
  g[2][2] = sigma;
  g[3][3] = (r * r + a2 + a2 * st2 * u) * st2;
}
//
// The position (r, θ) and the direction k may have different number types T and K: doubles, SIMD
// lanes (T = K = SimdD), or dual numbers in r and θ with a plain k (KerrBL::jacobi_terms_closed: the
// derivative of the acceleration along the Jacobi fields).
template <class T, class K, class Acc>
GEOVIS_HOT_INLINE void kerr_bl_accel(double rs, double a, double a2, const T& r, const T& theta, const K& kt,
                                     const K& kr, const K& kth, const K& kph, Acc& acc) {
  T st, ct;
  sincos_t(theta, st, ct);
  const T r2 = r * r, s2 = st * st, sc = st * ct, a2c2 = a2 * ct * ct;
  const T sigma = r2 + a2c2, delta = r2 - rs * r + a2;
  const T is = 1.0 / sigma;
  const T u = rs * r * is;
  const T ur = rs * (a2c2 - r2) * is * is;         // ∂_r u
  const T uth = 2.0 * rs * r * a2 * sc * is * is;  // ∂_θ u
  // Metric components.
  const T gtt = u - 1.0, gtp = -a * s2 * u, B = r2 + a2 + a2 * s2 * u, gpp = B * s2;
  // r-derivatives.
  const T idd = 1.0 / (delta * s2);  // 1/(Δ sin²θ)
  const T id = idd * s2;             // 1/Δ
  const T gtt_r = ur, gtp_r = -a * s2 * ur, grr_r = (2.0 * r - sigma * (2.0 * r - rs) * id) * id, ghh_r = 2.0 * r,
          gpp_r = (2.0 * r + a2 * s2 * ur) * s2;
  // θ-derivatives (∂_θ Σ = −2a² sinθ cosθ).
  const T dsig = -2.0 * a2 * sc;
  const T gtt_h = uth, gtp_h = -a * (2.0 * sc * u + s2 * uth), grr_h = dsig * id, ghh_h = dsig,
          gpp_h = a2 * (2.0 * sc * u + s2 * uth) * s2 + 2.0 * B * sc;
  // D_X[ν] = ∂_X g_νb k^b and Q_X = ∂_X g_ab k^a k^b.
  const T Drt = gtt_r * kt + gtp_r * kph, Drr = grr_r * kr, Drh = ghh_r * kth, Drp = gtp_r * kt + gpp_r * kph;
  const T Dht = gtt_h * kt + gtp_h * kph, Dhr = grr_h * kr, Dhh = ghh_h * kth, Dhp = gtp_h * kt + gpp_h * kph;
  const T Qr = Drt * kt + Drr * kr + Drh * kth + Drp * kph;
  const T Qh = Dht * kt + Dhr * kr + Dhh * kth + Dhp * kph;
  const T Ft = -kr * Drt - kth * Dht;
  const T Fr = 0.5 * Qr - kr * Drr - kth * Dhr;
  const T Fh = 0.5 * Qh - kr * Drh - kth * Dhh;
  const T Fp = -kr * Drp - kth * Dhp;
  acc[0] = (gtp * Fp - gpp * Ft) * idd;
  acc[1] = Fr * delta * is;
  acc[2] = Fh * is;
  acc[3] = (gtp * Ft - gtt * Fp) * idd;
}
