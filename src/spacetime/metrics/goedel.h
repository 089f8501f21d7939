// The Gödel universe shared by the metrics Goedel, GoedelCart, GoedelScaled and GoedelScaledCart
// (one file each in spacetime/metrics/). In cylindrical coordinates (t, r, φ, z), G = c = 1
// (Gödel, Rev. Mod. Phys. 21 (1949) 447; Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184, "Gödel universe"; Motion4D m4dMetricGoedel):
//   ds² = −dt² − (√2 r²/a) dt dφ + dr²/(1 + r²/(4a²)) + r² (1 − r²/(4a²)) dφ² + dz²,
// i.e. g_tφ = w(r) = −r²/(√2 a), g_rr = h(r) = 1/(1 + r²/(4a²)), g_φφ = p(r) = r² − r⁴/(4a²).
// r_G = 2a is the Gödel radius (g_φφ = 0; beyond it the circles r = const are closed timelike
// curves). The (t, φ) block has determinant D = −p − w² = −r² (1 + r²/(4a²)) < 0 for r > 0, so the
// signature is (−,+,+,+) everywhere off the axis.
//
// Christoffel symbols (g depends on r only; Γ_{rAB} = −½ ∂_r g_AB, Γ_{ArB} = ½ ∂_r g_AB for A, B
// in {t, φ}, raised with the inverse block g^tt = p/D, g^tφ = −w/D, g^φφ = −1/D):
//   Γ^r_tφ = −w'/(2h), Γ^r_φφ = −p'/(2h), Γ^r_rr = h'/(2h),
//   Γ^t_rt = −w w'/(2D), Γ^t_rφ = (p w' − w p')/(2D), Γ^φ_rt = −w'/(2D), Γ^φ_rφ = −(w w' + p')/(2D),
// with w' = −√2 r/a, p' = 2r − r³/a², h' = −(r/(2a²)) h².
//
// Natural tetrad (Motion4D localToCoord): observers rotating with dφ/dt = ζ,
//   e_(0) = Γ (∂_t + ζ ∂_φ),  Γ = 1/√(1 + √2 ζ r²/a − ζ² p),   e_(1) = ∂_r/√h,   e_(3) = ∂_z,
//   e_(2) = the unit vector in span(∂_t, ∂_φ) orthogonal to e_(0) with positive ∂_φ component;
// ζ = 0 is the dust at rest (Gödel's comoving observers).
//
// Scaled coordinates (Motion4D GoedelScaled): t = r_G T, r = r_G R, z = r_G Z with a = r_G/2 give
//   ds² = r_G² [−dT² − 2√2 R² dT dφ + dR²/(1 + R²) + R² (1 − R²) dφ² + dZ²],
// which is r_G² times the metric above with a = 1/2 in (T, R, φ, Z): same Christoffel symbols,
// tetrad vectors divided by r_G.
//
// Cartesian coordinates (GoedelCart): x = r cos φ, y = r sin φ; with r² dφ = x dy − y dx,
// r dr = x dx + y dy, s = 1/(4a²), q = 1 + s r²:
//   g_tx = y/(√2 a), g_ty = −x/(√2 a), g_xx = 1 − s x²/q − s y², g_yy = 1 − s y²/q − s x²,
//   g_xy = s x y (1 − 1/q), g_tt = −1, g_zz = 1,
// regular on the axis (where it is Minkowski).
#pragma once

#include <cmath>

#include "spacetime/metrics/metric_derivs.h"
#include "spacetime/vec.h"

namespace geovis::goedel {

/// g_tφ, g_rr, g_φφ of the cylindrical form (file comment), generic in the scalar.
template <class T>
void cylinder_metric(double a, const T& r, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T r2 = r * r;
  const double s = 1.0 / (4.0 * a * a);
  g[0][0] = T(-1.0);
  g[0][2] = g[2][0] = -r2 / (std::sqrt(2.0) * a);
  g[1][1] = 1.0 / (1.0 + s * r2);
  g[2][2] = r2 - s * r2 * r2;
  g[3][3] = T(1.0);
}

/// Γ of the cylindrical form (file comment).
inline void cylinder_christoffel(double a, double r, Christoffel& G) {
  G = Christoffel{};
  const double s = 1.0 / (4.0 * a * a), r2 = r * r;
  const double w = -r2 / (std::sqrt(2.0) * a), dw = -std::sqrt(2.0) * r / a;
  const double p = r2 - s * r2 * r2, dp = 2.0 * r - 4.0 * s * r2 * r;
  const double h = 1.0 / (1.0 + s * r2), dh = -2.0 * s * r * h * h;
  const double D = -p - w * w;
  auto set = [&G](int mu, int i, int j, double v) { G.G[mu][i][j] = G.G[mu][j][i] = v; };
  set(1, 0, 2, -dw / (2.0 * h));
  set(1, 2, 2, -dp / (2.0 * h));
  set(1, 1, 1, dh / (2.0 * h));
  set(0, 1, 0, -w * dw / (2.0 * D));
  set(0, 1, 2, (p * dw - w * dp) / (2.0 * D));
  set(2, 1, 0, -dw / (2.0 * D));
  set(2, 1, 2, -(w * dw + dp) / (2.0 * D));
}

/// The rotating-observer tetrad of the cylindrical form (file comment) at r > 0; false where the
/// observer with dφ/dt = ζ is not timelike.
inline bool cylinder_tetrad(double a, double zeta, double r, Tetrad& e) {
  Mat4 g;
  cylinder_metric<double>(a, r, g);
  const double w = g[0][2], p = g[2][2];
  const double n0 = -(g[0][0] + 2.0 * zeta * w + zeta * zeta * p);  // −g(∂t + ζ∂φ, ∂t + ζ∂φ)
  if (!(n0 > 0.0) || !(r > 0.0)) return false;
  e = Tetrad{};
  const double gam = 1.0 / std::sqrt(n0);
  e[0][0] = gam;
  e[0][2] = gam * zeta;
  e[1][1] = 1.0 / std::sqrt(g[1][1]);
  // v = c ∂t + ∂φ with g(∂t + ζ∂φ, v) = 0.
  const double c = -(w + zeta * p) / (g[0][0] + zeta * w);
  const double vv = c * c * g[0][0] + 2.0 * c * w + p;
  if (!(vv > 0.0)) return false;
  const double n2 = 1.0 / std::sqrt(vv);
  e[2][0] = c * n2;
  e[2][2] = n2;
  e[3][3] = 1.0;
  return true;
}

/// The Cartesian form (file comment), generic in the scalar.
template <class T>
void cart_metric(double a, const T& x, const T& y, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const double s = 1.0 / (4.0 * a * a), k = 1.0 / (std::sqrt(2.0) * a);
  const T q = 1.0 + s * (x * x + y * y);
  g[0][0] = T(-1.0);
  g[0][1] = g[1][0] = k * y;
  g[0][2] = g[2][0] = -k * x;
  g[1][1] = 1.0 - s * x * x / q - s * y * y;
  g[2][2] = 1.0 - s * y * y / q - s * x * x;
  g[1][2] = g[2][1] = s * x * y * (1.0 - 1.0 / q);
  g[3][3] = T(1.0);
}

/// g and ∂g of the Cartesian form: with u = 1/q, ∂_x u = −2 s x u², ∂_y u = −2 s y u².
inline void cart_derivs(double a, double x, double y, MetricDerivs& d) {
  cart_metric<double>(a, x, y, d.g);
  const double s = 1.0 / (4.0 * a * a), k = 1.0 / (std::sqrt(2.0) * a);
  const double u = 1.0 / (1.0 + s * (x * x + y * y));
  const double ux = -2.0 * s * x * u * u, uy = -2.0 * s * y * u * u;
  for (auto& c : d.dg)
    for (auto& row : c)
      for (double& v : row) v = 0.0;
  auto set = [&d](int c, int i, int j, double v) { d.dg[c][i][j] = d.dg[c][j][i] = v; };
  set(2, 0, 1, k);   // ∂_y g_tx
  set(1, 0, 2, -k);  // ∂_x g_ty
  set(1, 1, 1, -s * (2.0 * x * u + x * x * ux));
  set(2, 1, 1, -s * (x * x * uy + 2.0 * y));
  set(1, 2, 2, -s * (y * y * ux + 2.0 * x));
  set(2, 2, 2, -s * (2.0 * y * u + y * y * uy));
  set(1, 1, 2, s * (y * (1.0 - u) - x * y * ux));
  set(2, 1, 2, s * (x * (1.0 - u) - x * y * uy));
}

/// The cylindrical tetrad written in Cartesian components (∂_r = (x ∂_x + y ∂_y)/r,
/// ∂_φ = −y ∂_x + x ∂_y), as Motion4D's GoedelCart; on the axis, where the metric is Minkowski,
/// the Cartesian frame of the rotating observer.
inline bool cart_tetrad(double a, double zeta, double x, double y, Tetrad& e) {
  const double r = std::hypot(x, y);
  if (r == 0.0) {
    e = Tetrad{};
    // On the axis the observer rotating with ζ is at rest: e_(0) = ∂_t.
    for (int i = 0; i < 4; ++i) e[i][i] = 1.0;
    return true;
  }
  Tetrad c;
  if (!cylinder_tetrad(a, zeta, r, c)) return false;
  e = Tetrad{};
  for (int i = 0; i < 4; ++i) {
    e[i][0] = c[i][0];
    e[i][1] = c[i][1] * x / r - c[i][2] * y;
    e[i][2] = c[i][1] * y / r + c[i][2] * x;
    e[i][3] = c[i][3];
  }
  return true;
}

}  // namespace geovis::goedel
