// The core of fast_sincos (fast_math.h: method and error there) as one template over the number
// type: the Cody–Waite reduction x = n·π/2 + r and the polynomials of sin r and cos r, which the
// caller turns into sin x and cos x by the quadrant n mod 4. Included (no include guard) by
// fast_math.h into namespace geovis, for doubles, and by simd.h into each SIMD target's namespace
// (geovis::HWY_NAMESPACE), whose instantiation on SimdD must be compiled with that target's
// instruction set (as kerr_mino_rhs.h). The same operations in the same order on both: a lane of
// SimdD's sincos_t equals fast_sincos of that lane to the bit (test Simd.SinCosIsFastSinCosLaneByLane).

template <class T>
#if defined(__GNUC__)
[[gnu::always_inline]]
#endif
inline void
sincos_reduced(const T& x, T& n, T& sr, T& cr) {
  constexpr double kTwoOverPi = 0.63661977236758134308;
  constexpr double kP1 = 0x1.921fb544p+0, kP2 = 0x1.0b4611a6p-34, kP3 = 0x1.3198a2e037073p-69;
  constexpr double kRound = 6755399441055744.0;  // 1.5·2^52: adding it rounds to an integer
  n = (x * kTwoOverPi + kRound) - kRound;
  const T r = ((x - n * kP1) - n * kP2) - n * kP3;
  const T z = r * r;
  // (−1)^k / (2k+1)!  and  (−1)^k / (2k)!
  constexpr double s3 = -1.0 / 6, s5 = 1.0 / 120, s7 = -1.0 / 5040, s9 = 1.0 / 362880, s11 = -1.0 / 39916800,
                   s13 = 1.0 / 6227020800.0, s15 = -1.0 / 1307674368000.0, s17 = 1.0 / 355687428096000.0;
  constexpr double c4 = 1.0 / 24, c6 = -1.0 / 720, c8 = 1.0 / 40320, c10 = -1.0 / 3628800, c12 = 1.0 / 479001600,
                   c14 = -1.0 / 87178291200.0, c16 = 1.0 / 20922789888000.0, c18 = -1.0 / 6402373705728000.0;
  // Estrin's scheme: the right-hand side of a geodesic is one long dependency chain from θ to
  // the next stage, so the latency of the polynomials matters more than their operation count
  // (depth 4 multiply-adds instead of Horner's 8).
  const T z2 = z * z, z4 = z2 * z2;
  const T ps = ((s3 + z * s5) + z2 * (s7 + z * s9)) + z4 * ((s11 + z * s13) + z2 * (s15 + z * s17));
  const T pc = ((c4 + z * c6) + z2 * (c8 + z * c10)) + z4 * ((c12 + z * c14) + z2 * (c16 + z * c18));
  sr = r + r * z * ps;
  cr = (1.0 - 0.5 * z) + z * z * pc;
}
