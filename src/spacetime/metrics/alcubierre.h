// The Alcubierre warp drive (AlcubierreWarpSimple; the line element, Christoffel symbols and
// tetrads are those of every Alcubierre metric, whatever its shape function f):
//   ds² = −dt² + (dx − v_s f(r_s) dt)² + dy² + dz²,  r_s = √((x − v_s t)² + y² + z²)
// (Alcubierre, Class. Quantum Grav. 11 (1994) L73, eq. (8); Müller & Grave, Catalogue of
// Spacetimes, arXiv:0904.4184, "Alcubierre warp drive"), i.e. g_tt = −1 + v_s² f², g_tx = −v_s f.
//
// Christoffel symbols (derived from the line element; j ∈ {y, z}, f_μ = ∂_μ f, f_t = −v_s f_x):
//   Γ^t_tt = v³f²f_x,  Γ^t_tx = −v²f f_x,  Γ^t_tj = −½v²f f_j,  Γ^t_xx = v f_x,  Γ^t_xj = ½v f_j,
//   Γ^x_tt = −v f_t − v²f f_x + v⁴f³f_x,  Γ^x_tx = −v³f²f_x,  Γ^x_tj = −½v f_j (1 + v²f²),
//   Γ^x_xx = v²f f_x,  Γ^x_xj = ½v²f f_j,  Γ^j_tt = −v²f f_j,  Γ^j_tx = ½v f_j
// (v = v_s; these agree with the Catalogue and with Motion4D's calculateChristoffels).
// Natural tetrads (Motion4D localToCoord):
//   comoving (Eulerian observer): e_(0) = ∂_t + v_s f ∂_x, e_(1) = ∂_x, e_(2) = ∂_y, e_(3) = ∂_z;
//   default = static: e_(0) = ∂_t/w, e_(1) = −(v_s f/w) ∂_t + w ∂_x, w = √(1 − v_s² f²)
//   (only where v_s |f| < 1).
// After every accepted step of a light ray Motion4D's AlcubierreWarpSimple rescales k to |k^t| = 1
// (its Metric::resize); rescale_direction reproduces it (the ray is the same curve, only its
// affine parameter changes, so k^t stays of order one through the bubble wall). Motion4D's
// AlcubierreWarp instead projects k onto the null cone, which geovis does not reproduce
// (alcubierre_warp.cpp).
#pragma once

#include <cmath>

#include "spacetime/vec.h"

namespace geovis::alcubierre {

/// Γ from v = v_s, f and the spatial gradient (f_x, f_y, f_z) of f (file comment).
inline void christoffel(double v, double f, double fx, double fy, double fz, Christoffel& G) {
  G = Christoffel{};
  if (fx == 0.0 && fy == 0.0 && fz == 0.0) return;  // f constant here: all Γ vanish
  const double ft = -v * fx;
  const double v2 = v * v, f2 = f * f;
  auto set = [&G](int mu, int a, int b, double val) { G.G[mu][a][b] = G.G[mu][b][a] = val; };
  set(0, 0, 0, v2 * v * f2 * fx);
  set(0, 0, 1, -v2 * f * fx);
  set(0, 0, 2, -0.5 * v2 * f * fy);
  set(0, 0, 3, -0.5 * v2 * f * fz);
  set(0, 1, 1, v * fx);
  set(0, 1, 2, 0.5 * v * fy);
  set(0, 1, 3, 0.5 * v * fz);
  set(1, 0, 0, -v * ft - v2 * f * fx + v2 * v2 * f2 * f * fx);
  set(1, 0, 1, -v2 * v * f2 * fx);
  set(1, 0, 2, -0.5 * v * fy * (1.0 + v2 * f2));
  set(1, 0, 3, -0.5 * v * fz * (1.0 + v2 * f2));
  set(1, 1, 1, v2 * f * fx);
  set(1, 1, 2, 0.5 * v2 * f * fy);
  set(1, 1, 3, 0.5 * v2 * f * fz);
  set(2, 0, 0, -v2 * f * fy);
  set(2, 0, 1, 0.5 * v * fy);
  set(3, 0, 0, -v2 * f * fz);
  set(3, 0, 1, 0.5 * v * fz);
}

/// g_μν for v_s f = vf, generic in the scalar.
template <class T>
void metric(const T& vf, Mat4T<T>& g) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  g[0][0] = -1.0 + vf * vf;
  g[0][1] = g[1][0] = -vf;
  g[1][1] = T(1.0);
  g[2][2] = T(1.0);
  g[3][3] = T(1.0);
}

/// The comoving tetrad (comoving = true) or the static one (false; only where |v_s f| < 1: returns
/// false elsewhere).
inline bool tetrad(double vf, bool comoving, Tetrad& e) {
  e = Tetrad{};
  e[2][2] = 1.0;
  e[3][3] = 1.0;
  if (comoving) {
    e[0][0] = 1.0;
    e[0][1] = vf;
    e[1][1] = 1.0;
    return true;
  }
  const double w2 = 1.0 - vf * vf;
  if (!(w2 > 0.0)) return false;
  const double w = std::sqrt(w2);
  e[0][0] = 1.0 / w;
  e[1][0] = -vf / w;
  e[1][1] = w;
  return true;
}

/// k -> k / |k^t| (Motion4D's resize).
inline void rescale_direction(double* k) {
  const double a = 1.0 / std::fabs(k[0]);
  for (int i = 0; i < 4; ++i) k[i] *= a;
}

}  // namespace geovis::alcubierre
