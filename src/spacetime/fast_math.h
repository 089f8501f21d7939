// Inline sine/cosine (and, below, the exponential and the arcsine) for the geodesic hot path. Every
// right-hand-side evaluation of a metric in spherical-type coordinates needs sin θ and cos θ;
// glibc's sincos is an out-of-line call of ~110 instructions with its own range reduction for
// huge arguments, which was a third of the integration time (docs/PERFORMANCE.md). θ is a polar
// angle of moderate size, so a short Cody–Waite reduction and two polynomials, inlined, do the
// job to about 1 ulp.
//
// Method: x = n·π/2 + r, |r| <= π/4 (+ rounding), with π/2 split into three parts whose first two
// have 33 significant bits (so n·P1 and n·P2 are exact for |n| < 2^20; fdlibm's pio2_1, pio2_2,
// pio2_2t, computed here from 80 digits of π); then the Taylor series of sin r to r^17 and of
// cos r to r^18, whose truncation errors are below 1e-19 relative on |r| <= π/4, evaluated by
// Estrin's scheme in r². Maximal observed error against the correctly rounded glibc results is
// tested in tests/spacetime/test_fast_math.cpp. |x| >= 1e5, ±∞ and NaN go to std::sin/std::cos.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "spacetime/vec.h"  // select: the templates written for doubles and SIMD lanes choose with it

namespace geovis {

/// x with the low 32 bits of its significand cleared (asin_core.h: a part whose square is exact).
inline double clear_low_word(double x) {
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) & 0xffffffff00000000ull);
}

#include "spacetime/asin_core.h"       // asin_core: in namespace geovis
#include "spacetime/exp_reduced.h"     // exp_reduced: in namespace geovis
#include "spacetime/sincos_reduced.h"  // sincos_reduced: in namespace geovis

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
  double n, sr, cr;
  sincos_reduced(x, n, sr, cr);
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

/// 2^n for an integer-valued double n in [−1022, 1023], exactly (the bits of the power of two).
inline double exp2_integer(double n) {
  return std::bit_cast<double>(static_cast<std::uint64_t>(static_cast<std::int64_t>(n) + 1023) << 52);
}

/// e^x, inlined, for metrics whose right-hand side has an exponential (KastorTraschen's scale
/// factor e^{Ht}): the same function on doubles and on SIMD lanes (simd.h), so the scalar and
/// packet integrators give the same bits, where glibc's exp has no SIMD twin. exp_reduced (method
/// there) and an exact scaling by 2^n: within 1 ulp of the correctly rounded e^x (worst observed
/// in tests/spacetime/test_fast_math.cpp). |x| >= 708 (where e^x or its 2^n leaves the normal
/// range), ±∞ and NaN go to std::exp.
#if defined(__GNUC__)
[[gnu::always_inline]]
#endif
inline double
fast_exp(double x) {
  if (!(std::fabs(x) < 708.0)) return std::exp(x);
  double n, er;
  exp_reduced(x, n, er);
  return er * exp2_integer(n);
}

/// e^x for the metric templates: fast_exp for doubles, the (dual-number) overloads found by
/// argument-dependent lookup otherwise.
template <class T>
inline T exp_t(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return fast_exp(x);
  } else {
    using std::exp;
    return exp(x);
  }
}

/// asin x, inlined, for the Boyer–Lindquist view of Mino-time states (θ = 2 asin √((1 ∓ cos θ)/2),
/// kerr_mino_bl.h): the same function on doubles and on SIMD lanes (simd.h), so the scalar and
/// packet integrators report the same bits, where glibc's asin has no SIMD twin. fdlibm's method
/// (asin_core.h), within 1 ulp of glibc's asin on [−1, 1] (test FastMath.AsinWithinOneUlpOfLibm).
#if defined(__GNUC__)
[[gnu::always_inline]]
#endif
inline double
fast_asin(double x) {
  return asin_core(x);
}

/// asin x for the templates written once for doubles and SIMD lanes (SimdD: simd.h's asin_t).
inline double asin_t(double x) { return fast_asin(x); }

}  // namespace geovis
