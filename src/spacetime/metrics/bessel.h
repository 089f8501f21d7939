// Bessel functions J0, J1 of the first kind for doubles (the C++17 special functions) and for the
// dual numbers of automatic differentiation, through J0′ = −J1 and J1′ = J0 − J1/x (Abramowitz &
// Stegun, Handbook of Mathematical Functions (1964), 9.1.27). Used by the cylindrical
// gravitational waves (BesselGravWaveCart, HalilsoyWave).
#pragma once

#include <cmath>

#include "spacetime/dual.h"

namespace geovis::bessel {

inline double j0(double x) { return std::cyl_bessel_j(0.0, x); }
inline double j1(double x) { return std::cyl_bessel_j(1.0, x); }

template <class T>
Dual<T> j1(const Dual<T>& x);
template <class T>
Dual<T> j0(const Dual<T>& x) {
  return chain(x, j0(x.v), T(-1.0) * j1(x.v));
}
template <class T>
Dual<T> j1(const Dual<T>& x) {
  const T v = j1(x.v);
  return chain(x, v, j0(x.v) - v / x.v);
}

}  // namespace geovis::bessel
