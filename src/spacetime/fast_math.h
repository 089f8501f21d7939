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

}  // namespace geovis
