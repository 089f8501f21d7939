// The Boyer–Lindquist view of a Mino-time state (kerr_mino.h: kerr_mino_to_bl) as templates over
// the number type: double for one ray, SimdD (spacetime/simd.h) for the step ends of a packet's
// lanes at once (geodesic_packet.cpp, MinoPacket). Included (no include guard) by kerr_mino.h into
// namespace geovis and by the packet integrator into each SIMD target's namespace, as
// kerr_mino_rhs.h. Per-ray choices are select(cond, a, b) (fast_math.h for a bool, simd.h for a
// lane mask), and asin, sine and cosine are fast_math.h's (asin_t, sincos_t), whose SIMD twins
// give the same bits: one formula, the same bits on the scalar and the packet path (test
// GeodesicPacket.*, Mino time).

/// θ = acos z ∈ [0, π] from ζ = z − pole (PolarOffset::acos_z): accurate near the poles through
/// 1 ∓ z = 2 sin²(θ/2) resp. 2 cos²(θ/2), i.e. θ = 2 asin √(∓ζ/2) from the nearer pole (clamped,
/// for the L = 0 rays that overshoot the pole by the integration error).
template <class T>
GEOVIS_HOT_INLINE T kerr_mino_acos_z(const T& pole, const T& zeta) {
  using std::sqrt;
  constexpr double kPi = 3.14159265358979323846;
  const T u = -pole * zeta * 0.5;
  const T half = 2.0 * asin_t(sqrt(select(u < 0.0, T(0.0), select(1.0 < u, T(1.0), u))));  // std::clamp(u, 0, 1)
  return select(pole > 0.0, half, kPi - half);
}

/// The pseudo-Cartesian position r (sin θ cos φ, sin θ sin φ, cos θ) (Metric::to_pseudo_cartesian)
/// of Mino state y (ζ relative to `pole`) on the θ branch of sign `sign`, as kerr_mino_bl_view
/// gives it (there: p), with the same operations, so the same bits: cos θ = z (clamped),
/// sin θ = sign·√(1 − z²), one sine and cosine, of φ. For the packet's steps whose BL view is asked
/// for only where a caller reads it (PacketRays::states_on_request): the position alone, for every
/// step.
template <class T>
GEOVIS_HOT_INLINE void kerr_mino_position(const T& pole, const T& sign, const T* y, T* p) {
  using std::sqrt;
  enum { W = 0, Z = 1, PHI = 5 };
  const T zeta = y[Z], z_raw = pole + zeta;
  const T z = select(z_raw < -1.0, T(-1.0), select(1.0 < z_raw, T(1.0), z_raw));  // std::clamp(z, −1, 1)
  const T r = 1.0 / y[W];
  const T s2_raw = -zeta * (2.0 * pole + zeta);                // sin²θ (PolarOffset::sin2)
  const T s_abs = sqrt(select(0.0 < s2_raw, s2_raw, T(0.0)));  // |sin θ|
  T sp, cp;
  sincos_t(y[PHI], sp, cp);
  const T st = sign * s_abs;
  p[0] = r * st * cp;
  p[1] = r * st * sp;
  p[2] = r * z;
}

/// kerr_mino_to_bl (kerr_mino.h, where the formulas are derived) on any number type T: BL position
/// x and tangent k of Mino state y = (w, ζ, w', z', t, φ, λ) (ζ relative to `pole`) with
/// σ-derivative dy, on the θ branch θ = offset + sign·acos z (ThetaBranch); dk/dλ when dk is given,
/// and when p is given the pseudo-Cartesian position r (sin θ cos φ, sin θ sin φ, cos θ)
/// (Metric::to_pseudo_cartesian) from cos θ = z and sin θ = sign·√(1 − z²) (offset is a multiple
/// of 2π), with one sine and cosine, of φ. `axis` (L = 0: a bool or a lane mask) picks the forms
/// without 1/sin θ.
template <class T, class Cond>
GEOVIS_HOT_INLINE void kerr_mino_bl_view(const KerrMinoCoeffs<T>& c, const Cond& axis, const T& pole, const T& sign,
                                         const T& offset, const T* y, const T* dy, T* x, T* k, T* dk, T* p) {
  using std::copysign;
  using std::sqrt;
  enum { W = 0, Z = 1, DW = 2, DZ = 3, TT = 4, PHI = 5, LAM = 6 };
  const T zeta = y[Z], z_raw = pole + zeta;
  const T z = select(z_raw < -1.0, T(-1.0), select(1.0 < z_raw, T(1.0), z_raw));  // std::clamp(z, −1, 1)
  const T w = y[W], dw = y[DW], dz = y[DZ];
  const T r = 1.0 / w;
  const T s2_raw = -zeta * (2.0 * pole + zeta);                // sin²θ (PolarOffset::sin2)
  const T s_abs = sqrt(select(0.0 < s2_raw, s2_raw, T(0.0)));  // |sin θ|
  const T sigma = r * r + c.a2 * z * z, isig = 1.0 / sigma;
  // dθ/dσ = −s·z'/|sin θ|. For L = 0, Z = (1 − z²)(Q + Az²), so |z'|/|sin θ| = √(Q + Az²): used
  // instead, since near the axis, which such a ray passes, 1 − z² has lost its leading digits.
  const T q_axis = c.Q + c.A * z * z;
  const T dth_axis = -sign * copysign(sqrt(select(0.0 < q_axis, q_axis, T(0.0))), dz);
  const T dth = select(axis, dth_axis, -sign * dz / s_abs);
  const T dr = -dw * r * r;  // dr/dσ
  x[0] = y[TT];
  x[1] = r;
  x[2] = offset + sign * kerr_mino_acos_z(pole, zeta);
  x[3] = y[PHI];
  k[0] = dy[TT] * isig;
  k[1] = dr * isig;
  k[2] = dth * isig;
  k[3] = dy[PHI] * isig;
  if (dk) {
    // dk^μ/dλ = (x^μ'' Σ − x^μ' Σ')/Σ³ with ' = d/dσ, from the Mino derivatives (kerr_mino.h):
    //   r'' = −w''r² + 2w'²r³,  θ'' = −(z'' + z θ'²)/sin θ  (L = 0: −A z sin θ),
    //   t'' = ∂_w T w' + ∂_z T z',  φ'' = ∂_w Φ w' + ∂_z Φ z',  Σ' = 2 r r' + 2a² z z'.
    const T sin_th = sign * s_abs;
    const T ddr = -dy[DW] * r * r + 2.0 * dw * dw * r * r * r;
    const T ddth = select(axis, -c.A * z * sin_th, -(dy[DZ] + z * dth * dth) / sin_th);
    const T w2 = w * w, D = 1.0 - 2.0 * c.M * w + c.a2 * w2, dD = -2.0 * c.M + 2.0 * c.a2 * w;
    const T P = c.E + c.c * w2, dP = 2.0 * c.c * w;
    const T Nt = (1.0 + c.a2 * w2) * P, dNt = 2.0 * c.a2 * w * P + (1.0 + c.a2 * w2) * dP;
    const T den = w2 * D, dden = 2.0 * w * D + w2 * dD;
    const T iD = 1.0 / D;
    const T dT_dw = (dNt - Nt * dden / den) / den, dT_dz = 2.0 * c.a2 * c.E * z;
    const T s2 = select(s2_raw < 1e-300, T(1e-300), s2_raw);  // std::max(s2_raw, 1e-300)
    const T dPhi_dw = c.a * (dP - P * dD * iD) * iD, dPhi_dz = select(axis, T(0.0), 2.0 * c.L * z / (s2 * s2));
    const T ddt = dT_dw * dw + dT_dz * dz, ddph = dPhi_dw * dw + dPhi_dz * dz;
    const T dsig = 2.0 * r * dr + 2.0 * c.a2 * z * dz;
    const T i3 = isig * isig * isig;
    dk[0] = (ddt * sigma - dy[TT] * dsig) * i3;
    dk[1] = (ddr * sigma - dr * dsig) * i3;
    dk[2] = (ddth * sigma - dth * dsig) * i3;
    dk[3] = (ddph * sigma - dy[PHI] * dsig) * i3;
  }
  if (p) kerr_mino_position(pole, sign, y, p);  // r, z and |sin θ| as above
}
