// Forward-mode automatic differentiation with four infinitesimal parts, one per coordinate.
// Dual<double> carries ∂_μ f; Dual<Dual<double>> carries ∂_μ∂_ν f (needed for ∂Γ and the
// Riemann tensor). Used as the fallback Christoffel source for any metric and as the oracle in
// tests (every closed-form Christoffel symbol is checked against it). Dual<double, K> carries K
// directional derivatives Y_k^μ ∂_μ f instead (seed_directions): the Jacobi system needs ∂Γ only
// along its two fields.
#pragma once

#include <cmath>
#include <type_traits>

#include "spacetime/fast_math.h"
#include "spacetime/vec.h"

namespace geovis {

#define GEOVIS_DUAL_ATTR
#include "spacetime/dual_arith.h"  // struct Dual: in namespace geovis
#undef GEOVIS_DUAL_ATTR

// Plain-double overloads so generic metric code can call value_of etc. on any scalar.
inline double value_of(double x) { return x; }
template <class T, int K>
inline double value_of(const Dual<T, K>& x) {
  return value_of(x.v);
}

template <class T, int K>
inline Dual<T, K> sin(const Dual<T, K>& a) {
  using std::cos;
  using std::sin;
  return chain(a, sin(a.v), cos(a.v));
}
template <class T, int K>
inline Dual<T, K> cos(const Dual<T, K>& a) {
  using std::cos;
  using std::sin;
  return chain(a, cos(a.v), -sin(a.v));
}
template <class T, int K>
inline Dual<T, K> tan(const Dual<T, K>& a) {
  using std::tan;
  T t = tan(a.v);
  return chain(a, t, T(1.0) + t * t);
}
template <class T, int K>
inline Dual<T, K> exp(const Dual<T, K>& a) {
  using std::exp;
  T e = exp(a.v);
  return chain(a, e, e);
}
template <class T, int K>
inline Dual<T, K> log(const Dual<T, K>& a) {
  using std::log;
  return chain(a, log(a.v), T(1.0) / a.v);
}
template <class T, int K>
inline Dual<T, K> sinh(const Dual<T, K>& a) {
  using std::cosh;
  using std::sinh;
  return chain(a, sinh(a.v), cosh(a.v));
}
template <class T, int K>
inline Dual<T, K> cosh(const Dual<T, K>& a) {
  using std::cosh;
  using std::sinh;
  return chain(a, cosh(a.v), sinh(a.v));
}
template <class T, int K>
inline Dual<T, K> tanh(const Dual<T, K>& a) {
  using std::tanh;
  T t = tanh(a.v);
  return chain(a, t, T(1.0) - t * t);
}
template <class T, int K>
inline Dual<T, K> atan(const Dual<T, K>& a) {
  using std::atan;
  return chain(a, atan(a.v), T(1.0) / (T(1.0) + a.v * a.v));
}
template <class T, int K>
inline Dual<T, K> asin(const Dual<T, K>& a) {
  using std::asin;
  using std::sqrt;
  return chain(a, asin(a.v), T(1.0) / sqrt(T(1.0) - a.v * a.v));
}
template <class T, int K>
inline Dual<T, K> acos(const Dual<T, K>& a) {
  using std::acos;
  using std::sqrt;
  return chain(a, acos(a.v), T(-1.0) / sqrt(T(1.0) - a.v * a.v));
}
template <class T, int K>
inline Dual<T, K> pow(const Dual<T, K>& a, double p) {
  using std::pow;
  return chain(a, pow(a.v, p), T(p) * pow(a.v, p - 1.0));
}
template <class T, int K>
inline Dual<T, K> abs(const Dual<T, K>& a) {
  return a.v < 0 ? -a : a;
}
template <class T, int K>
inline Dual<T, K> fabs(const Dual<T, K>& a) {
  return a.v < 0 ? -a : a;
}
template <class T, int K>
inline Dual<T, K> atan2(const Dual<T, K>& y, const Dual<T, K>& x) {
  using std::atan2;
  Dual<T, K> r;
  r.v = atan2(y.v, x.v);
  const T den = x.v * x.v + y.v * y.v;
  for (int i = 0; i < K; ++i) r.d[i] = (x.v * y.d[i] - y.v * x.d[i]) / den;
  return r;
}

/// Seeds x as the independent variables: x[μ] has ∂_μ = 1.
template <class T>
inline Vec4T<Dual<T>> seed(const Vec4T<T>& x) {
  Vec4T<Dual<T>> r;
  for (int i = 0; i < 4; ++i) {
    r[i] = Dual<T>(x[i]);
    r[i].d[i] = T(1.0);
  }
  return r;
}

/// Seeds x for derivatives along the directions Y[0..K-1]: x^μ carries Y_k^μ in slot k, so f(x)
/// carries the directional derivatives Y_k^μ ∂_μ f (chain rule).
template <int K>
inline Vec4T<Dual<double, K>> seed_directions(const Vec4& x, const Vec4 (&Y)[K]) {
  Vec4T<Dual<double, K>> r;
  for (int i = 0; i < 4; ++i) {
    r[i] = Dual<double, K>(x[i]);
    for (int k = 0; k < K; ++k) r[i].d[k] = Y[k][i];
  }
  return r;
}

}  // namespace geovis
