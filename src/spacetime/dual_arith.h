// The dual number type of dual.h (struct Dual, its arithmetic, the chain rule and the first-order
// sqrt, sincos_t, sin_t and exp_t of the metric templates) as a template over the number type.
// Included (no include guard) by dual.h into namespace geovis, and by simd.h into each SIMD
// target's namespace (geovis::HWY_NAMESPACE), where its instantiation on SimdD (the Jacobi fields of
// a packet's rays: kerr_jacobi.h, jacobi_terms_from_accel) must be compiled with that target's
// instruction set: operators defined outside the target's region are compiled for the baseline and
// cannot inline Highway's operations (as kerr_mino_rhs.h). One definition, so a lane's arithmetic is
// operation for operation that of Dual<double, K>. Needs <cmath> and <type_traits>, and the value
// type's sqrt, sincos_t and exp_t declared or found by argument-dependent lookup.
// GEOVIS_DUAL_ATTR (defined by the includer: empty, or the target's attributes) marks every
// function: GCC's target pragma of the per-target region does not reach the friends and members
// of a class template instantiated there.

template <class T, int K = 4>
struct Dual {
  T v{};     ///< value
  T d[K]{};  ///< ∂_0..∂_3 (K = 4, seed), or K directional derivatives (seed_directions)

  constexpr Dual() = default;
  GEOVIS_DUAL_ATTR constexpr Dual(double x) : v(x) {}  // NOLINT: implicit from constants, as for double
  template <class U = T, class = std::enable_if_t<!std::is_same_v<U, double>>>
  GEOVIS_DUAL_ATTR constexpr Dual(const T& x) : v(x) {}  // NOLINT

  GEOVIS_DUAL_ATTR Dual& operator+=(const Dual& o) { return *this = *this + o; }
  GEOVIS_DUAL_ATTR Dual& operator-=(const Dual& o) { return *this = *this - o; }
  GEOVIS_DUAL_ATTR Dual& operator*=(const Dual& o) { return *this = *this * o; }
  GEOVIS_DUAL_ATTR Dual& operator/=(const Dual& o) { return *this = *this / o; }

  GEOVIS_DUAL_ATTR friend Dual operator+(const Dual& a, const Dual& b) {
    Dual r;
    r.v = a.v + b.v;
    for (int i = 0; i < K; ++i) r.d[i] = a.d[i] + b.d[i];
    return r;
  }
  GEOVIS_DUAL_ATTR friend Dual operator-(const Dual& a, const Dual& b) {
    Dual r;
    r.v = a.v - b.v;
    for (int i = 0; i < K; ++i) r.d[i] = a.d[i] - b.d[i];
    return r;
  }
  GEOVIS_DUAL_ATTR friend Dual operator-(const Dual& a) {
    Dual r;
    r.v = -a.v;
    for (int i = 0; i < K; ++i) r.d[i] = -a.d[i];
    return r;
  }
  GEOVIS_DUAL_ATTR friend Dual operator*(const Dual& a, const Dual& b) {
    Dual r;
    r.v = a.v * b.v;
    for (int i = 0; i < K; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
    return r;
  }
  GEOVIS_DUAL_ATTR friend Dual operator/(const Dual& a, const Dual& b) {
    Dual r;
    const T inv = T(1.0) / b.v;
    r.v = a.v * inv;
    for (int i = 0; i < K; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) * inv;
    return r;
  }
  GEOVIS_DUAL_ATTR friend Dual operator+(const Dual& a, double b) { return a + Dual(b); }
  GEOVIS_DUAL_ATTR friend Dual operator+(double a, const Dual& b) { return Dual(a) + b; }
  GEOVIS_DUAL_ATTR friend Dual operator-(const Dual& a, double b) { return a - Dual(b); }
  GEOVIS_DUAL_ATTR friend Dual operator-(double a, const Dual& b) { return Dual(a) - b; }
  GEOVIS_DUAL_ATTR friend Dual operator*(const Dual& a, double b) {
    Dual r;
    r.v = a.v * b;
    for (int i = 0; i < K; ++i) r.d[i] = a.d[i] * b;
    return r;
  }
  GEOVIS_DUAL_ATTR friend Dual operator*(double a, const Dual& b) { return b * a; }
  GEOVIS_DUAL_ATTR friend Dual operator/(const Dual& a, double b) { return a * (1.0 / b); }
  GEOVIS_DUAL_ATTR friend Dual operator/(double a, const Dual& b) { return Dual(a) / b; }

  GEOVIS_DUAL_ATTR friend bool operator<(const Dual& a, const Dual& b) { return a.v < b.v; }
  GEOVIS_DUAL_ATTR friend bool operator>(const Dual& a, const Dual& b) { return a.v > b.v; }
  GEOVIS_DUAL_ATTR friend bool operator<=(const Dual& a, const Dual& b) { return a.v <= b.v; }
  GEOVIS_DUAL_ATTR friend bool operator>=(const Dual& a, const Dual& b) { return a.v >= b.v; }
  GEOVIS_DUAL_ATTR friend bool operator<(const Dual& a, double b) { return a.v < b; }
  GEOVIS_DUAL_ATTR friend bool operator>(const Dual& a, double b) { return a.v > b; }
  GEOVIS_DUAL_ATTR friend bool operator<=(const Dual& a, double b) { return a.v <= b; }
  GEOVIS_DUAL_ATTR friend bool operator>=(const Dual& a, double b) { return a.v >= b; }
};

/// Whether T is a dual number (the first-order functions below take plain values only).
template <class T>
inline constexpr bool kIsDual = false;
template <class T, int K>
inline constexpr bool kIsDual<Dual<T, K>> = true;

/// Chain rule helper: f(a) with f(a.v) = fv and f'(a.v) = dfv.
template <class T, int K>
GEOVIS_DUAL_ATTR inline Dual<T, K> chain(const Dual<T, K>& a, const T& fv, const T& dfv) {
  Dual<T, K> r;
  r.v = fv;
  for (int i = 0; i < K; ++i) r.d[i] = dfv * a.d[i];
  return r;
}

template <class T, int K>
GEOVIS_DUAL_ATTR inline Dual<T, K> sqrt(const Dual<T, K>& a) {
  using std::sqrt;
  const T s = sqrt(a.v);
  return chain(a, s, T(0.5) / s);
}

/// sin, cos and e^x of a first-order dual for the metric templates (found by argument-dependent
/// lookup before fast_math.h's generic sincos_t, sin_t and exp_t, which would call libm): the
/// value's sincos_t and exp_t — fast_sincos and fast_exp on doubles, their SIMD twins on lanes
/// (simd.h) — so a formula on Dual<SimdD, K> gives each lane the bits of Dual<double, K> (the
/// Jacobi system's terms, jacobi_terms_from_accel), and one inline polynomial instead of libm
/// calls per stage. d sin = cos·dx, d cos = −sin·dx, d e^x = e^x·dx.
template <class T, int K>
  requires(!kIsDual<T>)
GEOVIS_DUAL_ATTR inline void sincos_t(const Dual<T, K>& x, Dual<T, K>& s, Dual<T, K>& c) {
  T sv, cv;
  sincos_t(x.v, sv, cv);
  s = chain(x, sv, cv);
  c = chain(x, cv, -sv);
}
template <class T, int K>
  requires(!kIsDual<T>)
GEOVIS_DUAL_ATTR inline Dual<T, K> sin_t(const Dual<T, K>& x) {
  T sv, cv;
  sincos_t(x.v, sv, cv);
  return chain(x, sv, cv);
}
template <class T, int K>
  requires(!kIsDual<T>)
GEOVIS_DUAL_ATTR inline Dual<T, K> exp_t(const Dual<T, K>& x) {
  const T e = exp_t(x.v);
  return chain(x, e, e);
}
