// The dual number type of dual.h (struct Dual and its arithmetic) as a template over the number
// type. Included (no include guard) by dual.h into namespace geovis, and by the packet integrator
// (geodesic_packet.cpp) into each SIMD target's namespace (geovis::HWY_NAMESPACE), where its
// instantiation on SimdD (the Jacobi fields of a packet's rays, kerr_jacobi.h) must be compiled
// with that target's instruction set: operators defined outside the target's region are compiled
// for the baseline and cannot inline Highway's operations (as kerr_mino_rhs.h). One definition,
// so a lane's arithmetic is operation for operation that of Dual<double, K>. Needs <type_traits>.
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
