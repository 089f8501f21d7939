// The right-hand side and the tolerance scales of the Mino-time system (kerr_mino.h) as templates
// over the number type.
// Included (no include guard) by kerr_mino.h into namespace geovis, for doubles and dual numbers,
// and by the packet integrator (geodesic_packet.cpp) into each SIMD target's namespace
// (geovis::HWY_NAMESPACE), where its instantiation on SimdD must be compiled with that target's
// instruction set: a template defined outside the target's region would be compiled for the
// baseline and could not inline Highway's operations (as metrics/kerr_bl_accel.h).

/// dσ/dλ = 1/Σ = w²/(1 + a²z²w²) (Σ = r² + a² cos²θ, w = 1/r, z = cos θ) of the Mino-time system
/// (KerrMinoSystem::param_per_affine) on any number type T: one formula for one ray and for the
/// lanes of a packet (geodesic_packet.cpp, mino_param_per_affine), so the same bits.
template <class T>
GEOVIS_HOT_INLINE T kerr_mino_param_per_affine(const T& a2, const T& w, const T& z) {
  return w * w / (1.0 + a2 * z * z * w * w);
}

/// The right-hand side of the Mino-time system (kerr_mino.h) for state y = (w, ζ, w', z', t, φ, λ),
/// z = pole + ζ, on any number type T; `axis` (L == 0: a bool, or a lane mask) picks the form
/// without 1/sin²θ. One formula for one ray (KerrMinoRHS), for packets and for dual numbers.
template <class T, class Cond, class Pole>
GEOVIS_HOT_INLINE void kerr_mino_rhs(const KerrMinoCoeffs<T>& k, const Cond& axis, const Pole& pole, const T* y,
                                     T* dy) {
  enum { W = 0, Z = 1, DW = 2, DZ = 3, TT = 4, PHI = 5, LAM = 6 };
  const T w = y[W], z = pole + y[Z];
  const T w2 = w * w, z2 = z * z;
  const T D = 1.0 - 2.0 * k.M * w + k.a2 * w2;  // Δ/r²
  const T P = k.E + k.c * w2;                   // P/r²
  const T muK = k.mu2 + k.K * w2;
  const T s2 = -y[Z] * (2.0 * pole + y[Z]);  // sin²θ = 1 − z² (PolarOffset::sin2)
  // One division: 1/(w² D s²) gives 1/D, 1/w² and 1/sin²θ. On the axis branch sin²θ may vanish and
  // 1/sin²θ multiplies L = 0: it is left out (the factor 1 is exact, so both branches keep their bits).
  const T s2d = select(axis, T(1.0), s2);
  const T inv = 1.0 / (w2 * D * s2d);
  const T iD = inv * w2 * s2d, iw2 = inv * D * s2d;
  const T is2 = select(axis, T(0.0), inv * w2 * D);
  dy[TT] = (1.0 + k.a2 * w2) * P * iD * iw2 + k.a * k.L - k.a2 * k.E * s2;
  dy[W] = y[DW];
  dy[Z] = y[DZ];
  dy[PHI] = k.a * P * iD - k.a * k.E + k.L * is2;
  dy[LAM] = iw2 + k.a2 * z2;
  dy[DW] = 2.0 * k.c * w * P + (k.M - k.a2 * w) * muK - k.K * w * D;
  dy[DZ] = -(k.B + 2.0 * k.A * z2) * z;
}

/// KerrMinoSystem::tolerance_inv_scale (kerr_mino.h, where the scales are explained) on any number
/// type T: the reciprocals 1/s_i of the tolerance scales of state y (ζ relative to `pole`), from a²
/// and the floor of sin²θ of the ray. One formula for one ray and for a packet's lanes
/// (geodesic_packet.cpp), so both give the same bits.
template <class T>
GEOVIS_HOT_INLINE void kerr_mino_tolerance_inv_scale(const T& a2, const T& sin2_floor, const T& pole, const T* y,
                                                     T* is) {
  using std::sqrt;
  enum { W = 0, Z = 1, DW = 2, DZ = 3, TT = 4, PHI = 5, LAM = 6 };
  const T w2 = y[W] * y[W], z = pole + y[Z], z2 = z * z;
  const T w2sigma = 1.0 + a2 * z2 * w2;                        // w² Σ
  const T s2 = -y[Z] * (2.0 * pole + y[Z]);                    // sin²θ (PolarOffset::sin2)
  const T st = sqrt(select(s2 < sin2_floor, sin2_floor, s2));  // std::max(s2, floor)
  const T q = 1.0 / (w2 * st * w2sigma);                       // one division for all four
  is[TT] = is[PHI] = is[LAM] = T(1.0);
  is[W] = q * st * w2sigma;
  is[Z] = q * w2 * w2sigma;
  is[DW] = q * w2 * st;
  is[DZ] = q * w2 * w2;
}

/// KerrMinoSystem::constraint (kerr_mino.h, where the terms are derived) on any number type T: the
/// value g(k,k) + μ² of the Boyer–Lindquist tangent that state y (ζ relative to `pole`) stands for,
///   Σ (g(k,k) + μ²) = (w'² − W)/(w² D) + (z'² − Z)/(1 − z²),
/// and its scale (the absolute values of the terms that cancel), with one division. One formula
/// for one ray and for a packet's lanes (MinoPacket::step_checks, geodesic_packet.cpp): the same
/// operations in the same order, so a lane gives the scalar system's bits and stops where it does.
template <class T>
GEOVIS_HOT_INLINE void kerr_mino_constraint(const KerrMinoCoeffs<T>& k, const T& pole, const T* y, T& value,
                                            T& scale) {
  using std::fabs;
  enum { W = 0, Z = 1, DW = 2, DZ = 3 };
  const T w = y[W], z = pole + y[Z], dw = y[DW], dz = y[DZ];
  const T w2 = w * w, z2 = z * z;
  const T D = 1.0 - 2.0 * k.M * w + k.a2 * w2, P = k.E + k.c * w2;
  const T Wv = P * P - (1.0 - 2.0 * k.M * w + k.a2 * w2) * (k.mu2 + k.K * w2);  // W(w) (KerrMinoConstants::W)
  const T Zv = k.Q - k.B * z2 - k.A * z2 * z2;                                  // Z(z) (KerrMinoConstants::Z)
  const T s2_raw = -y[Z] * (2.0 * pole + y[Z]);                                // sin²θ (PolarOffset::sin2)
  const T s2 = select(s2_raw < 1e-300, T(1e-300), s2_raw);                      // std::max(s2_raw, 1e-300)
  const T aD = fabs(D), wD = w2 * aD;
  // One division: 1/(w²|D| (1 − z²) Σ), w²Σ = 1 + a²z²w².
  const T inv = w2 / (wD * s2 * (1.0 + k.a2 * z2 * w2));
  value = ((dw * dw - Wv) * s2 + (dz * dz - Zv) * wD) * inv;
  scale = ((dw * dw + P * P + aD * (k.mu2 + k.K * w2)) * s2 +
           (dz * dz + fabs(k.Q) + fabs(k.B) * z2 + fabs(k.A) * z2 * z2) * wD) *
              inv +
          k.mu2;
}
