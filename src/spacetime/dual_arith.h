// The dual number type of dual.h (struct Dual and its arithmetic) as a template over the number
// type. Included (no include guard) by dual.h into namespace geovis, and by the packet integrator
// (geodesic_packet.cpp) into each SIMD target's namespace (geovis::HWY_NAMESPACE), where its
// instantiation on SimdD (the Jacobi fields of a packet's rays, kerr_jacobi.h) must be compiled
// with that target's instruction set: operators defined outside the target's region are compiled
// for the baseline and cannot inline Highway's operations (as kerr_mino_rhs.h). One definition,
// so a lane's arithmetic is operation for operation that of Dual<double, K>. Needs <type_traits>.

template <class T, int K = 4>
struct Dual {
  T v{};     ///< value
  T d[K]{};  ///< ∂_0..∂_3 (K = 4, seed), or K directional derivatives (seed_directions)

  constexpr Dual() = default;
  constexpr Dual(double x) : v(x) {}  // NOLINT: implicit from constants, as for double
  template <class U = T, class = std::enable_if_t<!std::is_same_v<U, double>>>
  constexpr Dual(const T& x) : v(x) {}  // NOLINT

  Dual& operator+=(const Dual& o) { return *this = *this + o; }
  Dual& operator-=(const Dual& o) { return *this = *this - o; }
  Dual& operator*=(const Dual& o) { return *this = *this * o; }
  Dual& operator/=(const Dual& o) { return *this = *this / o; }

  friend Dual operator+(const Dual& a, const Dual& b) {
    Dual r;
    r.v = a.v + b.v;
    for (int i = 0; i < K; ++i) r.d[i] = a.d[i] + b.d[i];
    return r;
  }
  friend Dual operator-(const Dual& a, const Dual& b) {
    Dual r;
    r.v = a.v - b.v;
    for (int i = 0; i < K; ++i) r.d[i] = a.d[i] - b.d[i];
    return r;
  }
  friend Dual operator-(const Dual& a) {
    Dual r;
    r.v = -a.v;
    for (int i = 0; i < K; ++i) r.d[i] = -a.d[i];
    return r;
  }
  friend Dual operator*(const Dual& a, const Dual& b) {
    Dual r;
    r.v = a.v * b.v;
    for (int i = 0; i < K; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
    return r;
  }
  friend Dual operator/(const Dual& a, const Dual& b) {
    Dual r;
    const T inv = T(1.0) / b.v;
    r.v = a.v * inv;
    for (int i = 0; i < K; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) * inv;
    return r;
  }
  friend Dual operator+(const Dual& a, double b) { return a + Dual(b); }
  friend Dual operator+(double a, const Dual& b) { return Dual(a) + b; }
  friend Dual operator-(const Dual& a, double b) { return a - Dual(b); }
  friend Dual operator-(double a, const Dual& b) { return Dual(a) - b; }
  friend Dual operator*(const Dual& a, double b) {
    Dual r;
    r.v = a.v * b;
    for (int i = 0; i < K; ++i) r.d[i] = a.d[i] * b;
    return r;
  }
  friend Dual operator*(double a, const Dual& b) { return b * a; }
  friend Dual operator/(const Dual& a, double b) { return a * (1.0 / b); }
  friend Dual operator/(double a, const Dual& b) { return Dual(a) / b; }

  friend bool operator<(const Dual& a, const Dual& b) { return a.v < b.v; }
  friend bool operator>(const Dual& a, const Dual& b) { return a.v > b.v; }
  friend bool operator<=(const Dual& a, const Dual& b) { return a.v <= b.v; }
  friend bool operator>=(const Dual& a, const Dual& b) { return a.v >= b.v; }
  friend bool operator<(const Dual& a, double b) { return a.v < b; }
  friend bool operator>(const Dual& a, double b) { return a.v > b; }
  friend bool operator<=(const Dual& a, double b) { return a.v <= b; }
  friend bool operator>=(const Dual& a, double b) { return a.v >= b; }
};
