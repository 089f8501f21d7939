// Small fixed-size vectors and matrices for the hot path: no heap, trivially copyable, templated
// on the scalar so the same metric code runs on doubles and on dual numbers (spacetime/dual.h).
#pragma once

#include <array>
#include <cmath>

/// Forces inlining of the per-stage right-hand side into the Runge–Kutta stages (integrators.h) and
/// of the metric functions it calls (GCC/Clang).
#if defined(__GNUC__)
#define GEOVIS_HOT_INLINE [[gnu::always_inline]] inline
#else
#define GEOVIS_HOT_INLINE inline
#endif

namespace geovis {

template <class T>
struct Vec4T {
  T c[4];
  constexpr T& operator[](int i) { return c[i]; }
  constexpr const T& operator[](int i) const { return c[i]; }
};
using Vec4 = Vec4T<double>;

template <class T>
struct Mat4T {
  T m[4][4];
  constexpr T* operator[](int i) { return m[i]; }
  constexpr const T* operator[](int i) const { return m[i]; }
};
using Mat4 = Mat4T<double>;

/// Christoffel symbols of the second kind, G[mu][a][b] = Γ^μ_{ab} (symmetric in a, b); with dual
/// numbers (spacetime/dual.h) they carry their partial derivatives as well.
template <class T>
struct ChristoffelT {
  T G[4][4][4];
};
using Christoffel = ChristoffelT<double>;

/// A local tetrad: e[a] holds the coordinate components e_(a)^μ of base vector a
/// (a = 0 timelike). Paper §2.1, eq. (2).
struct Tetrad {
  Vec4 e[4];
  Vec4& operator[](int a) { return e[a]; }
  const Vec4& operator[](int a) const { return e[a]; }
};

struct Vec3 {
  double x = 0, y = 0, z = 0;
  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

// ---- conditions on one value or on SIMD lanes ---------------------------------------------------
// A formula written once for one ray (a bool condition) and for a packet of rays on SIMD lanes (a
// lane mask: simd.h's select, all_of, none_of) takes these for its bool.

/// cond ? x : y.
template <class T>
inline T select(bool cond, const T& x, const T& y) {
  return cond ? x : y;
}
inline bool all_of(bool cond) { return cond; }
inline bool none_of(bool cond) { return !cond; }

// ---- Vec4 arithmetic ----------------------------------------------------------------------------
template <class T>
constexpr Vec4T<T> operator+(const Vec4T<T>& a, const Vec4T<T>& b) {
  return {{a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]}};
}
template <class T>
constexpr Vec4T<T> operator-(const Vec4T<T>& a, const Vec4T<T>& b) {
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]}};
}
template <class T>
constexpr Vec4T<T> operator-(const Vec4T<T>& a) {
  return {{-a[0], -a[1], -a[2], -a[3]}};
}
template <class T>
constexpr Vec4T<T> operator*(double s, const Vec4T<T>& a) {
  return {{s * a[0], s * a[1], s * a[2], s * a[3]}};
}
template <class T>
constexpr Vec4T<T> operator*(const Vec4T<T>& a, double s) {
  return s * a;
}

/// g(a, b) = g_{μν} a^μ b^ν
inline double dot(const Mat4& g, const Vec4& a, const Vec4& b) {
  double s = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s += g[i][j] * a[i] * b[j];
  return s;
}

/// dot(g, a, b) without the terms of the components g_μν that are zero: the same bits for finite a
/// and b (such a term is ±0, and the running sum, which starts at +0, is never −0, so adding ±0
/// leaves it unchanged; IEEE 754 §6.3), but a chain of as many dependent additions as g has
/// non-zero components (four for a diagonal metric) instead of sixteen. For the frame algebra
/// of moving local objects (LocalFrame, gram_schmidt_after_e0), where that chain is the latency.
inline double dot_skipping_zeros(const Mat4& g, const Vec4& a, const Vec4& b) {
  double s = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (g[i][j] != 0.0) s += g[i][j] * a[i] * b[j];
  return s;
}

/// Whether every off-diagonal component of g is zero (a diagonal metric tensor, such as
/// Schwarzschild's or Minkowski's in their natural coordinates): the frame algebra of moving local
/// objects then takes dot_diagonal, four terms without a test of each of the sixteen components.
inline bool is_diagonal(const Mat4& g) {
  return g[0][1] == 0.0 && g[0][2] == 0.0 && g[0][3] == 0.0 && g[1][0] == 0.0 && g[1][2] == 0.0 && g[1][3] == 0.0 &&
         g[2][0] == 0.0 && g[2][1] == 0.0 && g[2][3] == 0.0 && g[3][0] == 0.0 && g[3][1] == 0.0 && g[3][2] == 0.0;
}

/// dot_skipping_zeros for a diagonal g (is_diagonal): the terms g_ii a^i b^i in its order, so the
/// same bits for finite a and b (a zero g_ii's term is ±0, which leaves a sum started at +0 as it
/// is, as in dot_skipping_zeros).
inline double dot_diagonal(const Mat4& g, const Vec4& a, const Vec4& b) {
  double s = 0;
  for (int i = 0; i < 4; ++i) s += g[i][i] * a[i] * b[i];
  return s;
}

/// dot_skipping_zeros, through dot_diagonal where the caller found g diagonal (is_diagonal, tested
/// once for several products with one g): the same bits either way.
inline double dot_skipping_zeros(const Mat4& g, bool diagonal, const Vec4& a, const Vec4& b) {
  return diagonal ? dot_diagonal(g, a, b) : dot_skipping_zeros(g, a, b);
}

// ---- Vec3 arithmetic ----------------------------------------------------------------------------
constexpr Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
constexpr Vec3 operator*(const Vec3& a, double s) { return s * a; }
constexpr Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(const Vec3& a) { return a / norm(a); }

/// Two unit vectors spanning the plane orthogonal to the unit vector n, (s1, s2, n) right-handed:
/// s1 is the projection of ẑ (of x̂ when n is within 26° of ẑ) into that plane, s2 = n × s1. The
/// screen of a light ray seen in a local frame (Perlick, Living Rev. Relativ. 7 (2004) 9, §4:
/// s_a ⟂ k and ⟂ the observer).
inline void screen_basis(const Vec3& n, Vec3& s1, Vec3& s2) {
  const Vec3 a = std::fabs(n.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  s1 = normalize(a - dot(a, n) * n);
  s2 = cross(n, s1);
}

}  // namespace geovis
