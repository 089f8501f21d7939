// The core of fast_exp (fast_math.h: range and error there) as one template over the number type:
// the Cody–Waite reduction x = n·ln 2 + r and the polynomial of e^r, which the caller scales by
// 2^n. Included (no include guard) by fast_math.h into namespace geovis, for doubles, and by
// simd.h into each SIMD target's namespace (geovis::HWY_NAMESPACE), as sincos_reduced.h. The same
// operations in the same order on both: a lane of SimdD's exp_t equals fast_exp of that lane to
// the bit (test Simd.ExpIsFastExpLaneByLane).
//
// Method (Tang, ACM TOMS 15 (1989) 144, without the table; fdlibm e_exp.c's reduction):
// n = round(x/ln 2), r = (x − n·L1) − n·L2 with L1 + L2 = ln 2 and L1 = fdlibm's ln2_hi, whose
// low 21 bits are zero, so n·L1 and x − n·L1 are exact for |n| < 2^21; |r| <= ln2/2 (+ rounding).
// e^r = 1 + (r + r²·P(r)) with P the Taylor series Σ_{k=2}^{13} r^{k−2}/k!, whose truncation error
// r^14/14! < 5e-18 is far below half an ulp of e^r >= 0.7; Estrin's scheme in r, r², r⁴, r⁸ (the
// geodesic right-hand side is one dependency chain, as for sincos_reduced).

template <class T>
#if defined(__GNUC__)
[[gnu::always_inline]]
#endif
inline void
exp_reduced(const T& x, T& n, T& er) {
  constexpr double kInvLn2 = 1.44269504088896338700;                            // 1/ln 2
  constexpr double kL1 = 6.93147180369123816490e-01, kL2 = 1.90821492927058770002e-10;  // fdlibm ln2_hi, ln2_lo
  constexpr double kRound = 6755399441055744.0;  // 1.5·2^52: adding it rounds to an integer
  n = (x * kInvLn2 + kRound) - kRound;
  const T r = (x - n * kL1) - n * kL2;
  constexpr double c2 = 1.0 / 2, c3 = 1.0 / 6, c4 = 1.0 / 24, c5 = 1.0 / 120, c6 = 1.0 / 720, c7 = 1.0 / 5040,
                   c8 = 1.0 / 40320, c9 = 1.0 / 362880, c10 = 1.0 / 3628800, c11 = 1.0 / 39916800,
                   c12 = 1.0 / 479001600, c13 = 1.0 / 6227020800.0;
  const T z = r * r, z2 = z * z, z4 = z2 * z2;
  const T p = ((c2 + r * c3) + z * (c4 + r * c5)) + z2 * ((c6 + r * c7) + z * (c8 + r * c9)) +
              z4 * ((c10 + r * c11) + z * (c12 + r * c13));
  er = 1.0 + (r + z * p);
}
