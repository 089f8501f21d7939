// Inline sine/cosine for the geodesic hot path. Every right-hand-side evaluation of a metric in
// spherical-type coordinates needs sin θ and cos θ; glibc's sincos is an out-of-line call of
// ~110 instructions with its own range reduction for huge arguments, which was a third of the
// integration time (docs/PERFORMANCE.md). θ is a polar angle of moderate size, so a short
// Cody–Waite reduction and two polynomials, inlined, do the job to about 1 ulp.
//
// Method: x = n·π/2 + r, |r| <= π/4 (+ rounding), with π/2 split into three parts whose first two
// have 33 significant bits (so n·P1 and n·P2 are exact for |n| < 2^20; fdlibm's pio2_1, pio2_2,
// pio2_2t, computed here from 80 digits of π); then the Taylor series of sin r to r^17 and of
// cos r to r^18, whose truncation errors are below 1e-19 relative on |r| <= π/4, evaluated by
// Estrin's scheme in r². Maximal observed error against the correctly rounded glibc results is
// tested in tests/spacetime/test_fast_math.cpp. |x| >= 1e5, ±∞ and NaN go to std::sin/std::cos.
#pragma once

#include <cmath>
#include <type_traits>

namespace geovis {

#if defined(__GNUC__)
[[gnu::always_inline]]
#endif
inline void
fast_sincos(double x, double& s, double& c) {
  if (!(std::fabs(x) < 1e5)) {
    s = std::sin(x);
    c = std::cos(x);
    return;
  }
  constexpr double kTwoOverPi = 0.63661977236758134308;
  constexpr double kP1 = 0x1.921fb544p+0, kP2 = 0x1.0b4611a6p-34, kP3 = 0x1.3198a2e037073p-69;
  constexpr double kRound = 6755399441055744.0;  // 1.5·2^52: adding it rounds to an integer
  const double n = (x * kTwoOverPi + kRound) - kRound;
  const double r = ((x - n * kP1) - n * kP2) - n * kP3;
  const double z = r * r;
  // (−1)^k / (2k+1)!  and  (−1)^k / (2k)!
  constexpr double s3 = -1.0 / 6, s5 = 1.0 / 120, s7 = -1.0 / 5040, s9 = 1.0 / 362880, s11 = -1.0 / 39916800,
                   s13 = 1.0 / 6227020800.0, s15 = -1.0 / 1307674368000.0, s17 = 1.0 / 355687428096000.0;
  constexpr double c4 = 1.0 / 24, c6 = -1.0 / 720, c8 = 1.0 / 40320, c10 = -1.0 / 3628800, c12 = 1.0 / 479001600,
                   c14 = -1.0 / 87178291200.0, c16 = 1.0 / 20922789888000.0, c18 = -1.0 / 6402373705728000.0;
  // Estrin's scheme: the right-hand side of a geodesic is one long dependency chain from θ to
  // the next stage, so the latency of the polynomials matters more than their operation count
  // (depth 4 multiply-adds instead of Horner's 8).
  const double z2 = z * z, z4 = z2 * z2;
  const double ps = ((s3 + z * s5) + z2 * (s7 + z * s9)) + z4 * ((s11 + z * s13) + z2 * (s15 + z * s17));
  const double pc = ((c4 + z * c6) + z2 * (c8 + z * c10)) + z4 * ((c12 + z * c14) + z2 * (c16 + z * c18));
  const double sr = r + r * z * ps;
  const double cr = (1.0 - 0.5 * z) + z * z * pc;
  switch (static_cast<long>(n) & 3) {
    case 0: s = sr, c = cr; break;
    case 1: s = cr, c = -sr; break;
    case 2: s = -sr, c = -cr; break;
    default: s = -cr, c = sr; break;
  }
}

/// sin and cos for the metric templates: fast_sincos for doubles, the (dual-number) overloads
/// found by argument-dependent lookup otherwise.
template <class T>
inline void sincos_t(const T& x, T& s, T& c) {
  if constexpr (std::is_same_v<T, double>) {
    fast_sincos(x, s, c);
  } else {
    using std::cos;
    using std::sin;
    s = sin(x);
    c = cos(x);
  }
}

/// sin x for the metric templates (fast_sincos for doubles).
template <class T>
inline T sin_t(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    double s, c;
    fast_sincos(x, s, c);
    return s;
  } else {
    using std::sin;
    return sin(x);
  }
}

}  // namespace geovis
