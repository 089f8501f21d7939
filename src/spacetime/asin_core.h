// asin x on [−1, 1] (fast_asin, fast_math.h) as one template over the number type, without
// branches: both of fdlibm's argument ranges are evaluated and the result chosen per lane with
// select(cond, a, b), which is the ternary for doubles (fast_math.h) and a lane mask for SimdD
// (simd.h). Included (no include guard) by fast_math.h into namespace geovis, for doubles, and by
// simd.h into each SIMD target's namespace (geovis::HWY_NAMESPACE), as sincos_reduced.h. The same
// operations in the same order on both: a lane of SimdD's asin_t equals fast_asin of that lane to
// the bit (test Simd.AsinIsFastAsinLaneByLane). Needs clear_low_word(x) (the low 32 bits of the
// significand set to zero) for the number type.
//
// Method: fdlibm's e_asin.c (Sun Microsystems 1993; the algorithm and its rational approximation,
// coefficients pS0..pS5, qS1..qS4 and the split of π/2 and π/4, as published there):
//   |x| < 1/2:  asin x = x + x·R(x²),  R(t) = t·P(t)/Q(t) ≈ (asin √t − √t)/√t  (P, Q of degree 5, 4)
//   |x| ≥ 1/2:  asin x = π/2 − 2 asin √t,  t = (1 − |x|)/2 ≤ 1/4, with asin √t = s + s·R(t), s = √t;
//               for |x| ≤ 0.975, where the subtraction from π/2 would cancel digits of 2s, s is
//               split into w = s with its low 32 significand bits cleared (w² exact) and the
//               correction c = (t − w²)/(s + w) = s − w, so that π/4 − 2w is exact and carries
//               the large part.
// Both ranges evaluate the same R, at t = x² or t = (1 − |x|)/2, so one rational evaluation serves
// both. Within 1 ulp of glibc's (correctly rounded) asin over all of [−1, 1] (worst observed in
// tests/spacetime/test_fast_math.cpp); |x| > 1 and NaN give NaN (the square root of t < 0).

template <class T>
#if defined(__GNUC__)
[[gnu::always_inline]]
#endif
inline T
asin_core(const T& x) {
  using std::fabs;
  using std::sqrt;
  constexpr double kPio2Hi = 0x1.921fb54442d18p+0, kPio2Lo = 0x1.1a62633145c07p-54;  // π/2 = hi + lo
  constexpr double kPio4Hi = 0x1.921fb54442d18p-1;
  constexpr double pS0 = 0x1.5555555555555p-3, pS1 = -0x1.4d61203eb6f7dp-2, pS2 = 0x1.9c1550e884455p-3,
                   pS3 = -0x1.48228b5688f3bp-5, pS4 = 0x1.9efe07501b288p-11, pS5 = 0x1.23de10dfdf709p-15;
  constexpr double qS1 = -0x1.33a271c8a2d4bp+1, qS2 = 0x1.02ae59c598ac8p+1, qS3 = -0x1.6066c1b8d0159p-1,
                   qS4 = 0x1.3b8c5b12e9282p-4;
  const T ax = fabs(x);
  const auto small = ax < 0.5;
  const T t = select(small, x * x, (1.0 - ax) * 0.5);
  const T p = t * (pS0 + t * (pS1 + t * (pS2 + t * (pS3 + t * (pS4 + t * pS5)))));
  const T q = 1.0 + t * (qS1 + t * (qS2 + t * (qS3 + t * qS4)));
  const T r = p / q;
  const T s = sqrt(t);
  const T near_one = kPio2Hi - (2.0 * (s + s * r) - kPio2Lo);
  const T w = clear_low_word(s);
  const T c = (t - w * w) / (s + w);
  const T middle = kPio4Hi - ((2.0 * s * r - (kPio2Lo - 2.0 * c)) - (kPio4Hi - 2.0 * w));
  const T large = select(ax > 0.975, near_one, middle);
  return select(small, x + x * r, select(x < 0.0, -large, large));
}
