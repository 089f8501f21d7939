// Jacobi fields of Kerr light rays from the Mino-time flow and the Walker–Penrose screen
// (formulas in kerr_jacobi.h).
#include "spacetime/kerr_jacobi.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spacetime/dual.h"
#include "spacetime/integrators.h"
#include "spacetime/jacobi.h"
#include "spacetime/kerr_mino.h"

namespace geovis {

std::complex<double> walker_penrose(double a, const Vec4& x, const Vec4& k, const Vec4& f) {
  const double r = x[1], st = std::sin(x[2]), ct = std::cos(x[2]);
  const double A = (k[0] * f[1] - k[1] * f[0]) + a * st * st * (k[1] * f[3] - k[3] * f[1]);
  const double B = ((r * r + a * a) * (k[3] * f[2] - k[2] * f[3]) - a * (k[0] * f[2] - k[2] * f[0])) * st;
  return std::complex<double>(A, -B) * std::complex<double>(r, -a * ct);
}

bool kerr_transported_screen(double M, double a, const Vec4& x0, const Vec4& k0, const Vec4 (&s0)[2], const Vec4& x,
                             const Vec4& k, Vec4 (&s)[2]) {
  // A screen basis at (x, k): two unit vectors orthogonal to k in the rest frame of the
  // zero-angular-momentum observer (Bardeen, Press & Teukolsky, ApJ 178 (1972) 347, eq. 3.2),
  // whose spatial triad is e_r = √(Δ/Σ) ∂_r, e_θ = ∂_θ/√Σ, e_φ = √(Σ/𝒜) ∂_φ / sin θ
  // (𝒜 = (r² + a²)² − a²Δ sin²θ, ω = 2Mar/𝒜): vectors orthogonal to that observer and to k's
  // spatial direction n there are orthogonal to k.
  const double r = x[1], st = std::sin(x[2]), ct = std::cos(x[2]);
  const double sigma = r * r + a * a * ct * ct, delta = r * r - 2.0 * M * r + a * a;
  const double calA = (r * r + a * a) * (r * r + a * a) - a * a * delta * st * st;
  const double omega = 2.0 * M * a * r / calA;
  const double er = std::sqrt(delta / sigma), eth = 1.0 / std::sqrt(sigma), eph = std::sqrt(sigma / calA) / st;
  const Vec3 n = normalize(Vec3{k[1] / er, k[2] / eth, (k[3] - omega * k[0]) / eph});
  Vec3 b1, b2;
  screen_basis(n, b1, b2);
  const Vec4 e1{{0.0, b1.x * er, b1.y * eth, b1.z * eph}}, e2{{0.0, b2.x * er, b2.y * eth, b2.z * eph}};
  const std::complex<double> K1 = walker_penrose(a, x, k, e1), K2 = walker_penrose(a, x, k, e2);
  // s_a = α e1 + β e2 with κ(s_a) = κ(s0_a): [Re K1 Re K2; Im K1 Im K2] (α, β) = (Re κ, Im κ).
  const double det = K1.real() * K2.imag() - K2.real() * K1.imag();
  if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return false;
  for (int f = 0; f < 2; ++f) {
    const std::complex<double> kappa = walker_penrose(a, x0, k0, s0[f]);
    const double al = (kappa.real() * K2.imag() - K2.real() * kappa.imag()) / det;
    const double be = (K1.real() * kappa.imag() - kappa.real() * K1.imag()) / det;
    for (int i = 0; i < 4; ++i) s[f][i] = al * e1[i] + be * e2[i];
  }
  return true;
}

namespace {

using DualJ = Dual<double, 2>;

/// State of the Mino flow with its derivatives along two initial directions: the coupled part
/// (w, ζ, w', z') of the value and of each derivative first, then the quadratures (t, φ, λ) of
/// the value and of each derivative, so the Runge–Kutta stages sum only the first 12 (kCoupled).
struct MinoJacobiLayout {
  static constexpr int N = 21, kCoupled = 12;
  /// Index of Mino component i (KerrMinoRHS order) of the value (f = −1) or of derivative f.
  static constexpr int at(int i, int f) { return i < 4 ? 4 * (f + 1) + i : 12 + 3 * (f + 1) + (i - 4); }
  static void value(const double* y, double* v) {
    for (int i = 0; i < KerrMinoRHS::N; ++i) v[i] = y[at(i, -1)];
  }
};

/// The Mino system with derivatives (kerr_jacobi.h) as the integration driver sees it: the
/// right-hand side on dual numbers (kerr_mino_rhs), everything else on the value through the
/// ray's own KerrMinoSystem, so the ray's validity, box, escape and capture are RGB's.
struct KerrMinoJacobiSystem {
  using L = MinoJacobiLayout;
  using I = KerrMinoRHS;
  static constexpr int N = L::N;
  static constexpr int kCoupled = L::kCoupled;
  static constexpr bool kHasConstraint = true;
  KerrMinoSystem ray;
  KerrMinoCoeffs<DualJ> kd;

  GEOVIS_HOT_INLINE void operator()(const double* y, double* dy) const {
    DualJ yd[I::N], dyd[I::N];
    for (int i = 0; i < I::N; ++i) {
      yd[i].v = y[L::at(i, -1)];
      yd[i].d[0] = y[L::at(i, 0)];
      yd[i].d[1] = y[L::at(i, 1)];
    }
    kerr_mino_rhs(kd, false, ray.f.polar.pole, yd, dyd);
    for (int i = 0; i < I::N; ++i) {
      dy[L::at(i, -1)] = dyd[i].v;
      dy[L::at(i, 0)] = dyd[i].d[0];
      dy[L::at(i, 1)] = dyd[i].d[1];
    }
  }
  double affine(const double* y) const { return y[L::at(I::LAM, -1)]; }
  double param_per_affine(const double* y) const {
    double v[I::N];
    L::value(y, v);
    return ray.param_per_affine(v);
  }
  /// The ray's components as in KerrMinoSystem (local errors of the BL x and k); each derivative f
  /// in the same BL units relative to its own size max(1, max_i |V_f,i|/s_i), as the coordinate
  /// Jacobi system holds its fields (jacobi.cpp JacobiSystem): what J needs is a relative accuracy.
  void tolerance_inv_scale(const double* y, double* is) const {
    double v[I::N], iv[I::N];
    L::value(y, v);
    ray.tolerance_inv_scale(v, iv);
    for (int i = 0; i < I::N; ++i) is[L::at(i, -1)] = iv[i];
    for (int f = 0; f < 2; ++f) {
      double size = 1.0;
      for (int i = 0; i < I::N; ++i) size = std::max(size, std::fabs(y[L::at(i, f)]) * iv[i]);
      const double inv = 1.0 / size;
      for (int i = 0; i < I::N; ++i) is[L::at(i, f)] = iv[i] * inv;
    }
  }
  /// The ray's projection onto z'² = Z (kerr_mino.h); it moves the value by far less than the
  /// tolerance, the derivatives keep theirs.
  bool project_invariants(double* y) const {
    double v[I::N];
    L::value(y, v);
    if (!ray.project_invariants(v)) return false;
    y[L::at(I::Z, -1)] = v[I::Z];
    y[L::at(I::DZ, -1)] = v[I::DZ];
    return true;
  }
  bool valid(const double* y) const {
    double v[I::N];
    L::value(y, v);
    return ray.valid(v);
  }
  bool escaped(const SolverConfig& c, const double* y, double& radius) const {
    double v[I::N];
    L::value(y, v);
    return ray.escaped(c, v, radius);
  }
  bool captured(const SolverConfig& c, const double* y) const {
    double v[I::N];
    L::value(y, v);
    return ray.captured(c, v);
  }
  /// Crossing the equator re-bases ζ (kerr_mino.h); δζ = δz is unchanged.
  void rebase(double* y) {
    double v[I::N];
    L::value(y, v);
    ray.rebase(v);
    y[L::at(I::Z, -1)] = v[I::Z];
  }
  bool inside(const SolverConfig& c, const double* y) const {
    double v[I::N];
    L::value(y, v);
    return ray.inside(c, v);
  }
  void constraint(const double* y, GeodesicType t, double& value, double& scale) const {
    double v[I::N];
    L::value(y, v);
    ray.constraint(v, t, value, scale);
  }
  void reproject(double* y, GeodesicType t) const {
    double v[I::N];
    L::value(y, v);
    ray.reproject(v, t);
    y[L::at(I::DW, -1)] = v[I::DW];
    y[L::at(I::DZ, -1)] = v[I::DZ];
  }
};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The BL Jacobi state (jacobi.h layout) and its λ-derivative of Mino state y with σ-derivative
/// dy (kerr_jacobi.h): x, k, dk/dλ, Y_f, Y_f', dY_f/dλ; s_a, ds_a/dλ and d²Y_f/dλ² are NaN.
void to_bl_jacobi(const KerrMinoConstants& c, const PolarOffset& polar, const ThetaBranch& b, const double* y,
                  const double* dy, double* out, double* dout, double* p = nullptr) {
  using L = MinoJacobiLayout;
  using I = KerrMinoRHS;
  double v[I::N], dv[I::N];
  L::value(y, v);
  L::value(dy, dv);
  Vec4 x, k, acc;
  kerr_mino_to_bl(c, polar, v, dv, b, x, k, &acc, p);
  for (int i = 0; i < kJacobiDim; ++i) out[i] = dout[i] = kNaN;
  for (int i = 0; i < 4; ++i) {
    out[kJacobiX + i] = x[i];
    out[kJacobiK + i] = k[i];
    dout[kJacobiX + i] = k[i];
    dout[kJacobiK + i] = acc[i];
  }
  const double w = v[I::W], r = 1.0 / w, z = polar.z(v[I::Z]), dw = v[I::DW], dz = v[I::DZ];
  const double st = std::sqrt(std::max(0.0, polar.sin2(v[I::Z]))), ist = 1.0 / st;
  const double isig = 1.0 / (r * r + c.a2 * z * z);
  for (int f = 0; f < 2; ++f) {
    const double dW = y[L::at(I::W, f)], dZ = y[L::at(I::Z, f)], dDW = y[L::at(I::DW, f)], dDZ = y[L::at(I::DZ, f)];
    const double dlam = y[L::at(I::LAM, f)], dsig = dy[L::at(I::LAM, f)];
    const Vec4 V{{y[L::at(I::T, f)], -dW * r * r, -b.sign * dZ * ist, y[L::at(I::PHI, f)]}};
    const Vec4 dV{{dy[L::at(I::T, f)], -dDW * r * r + 2.0 * dW * dw * r * r * r,
                   -b.sign * (dDZ * ist + dZ * z * dz * ist * ist * ist), dy[L::at(I::PHI, f)]}};
    for (int i = 0; i < 4; ++i) {
      const double Y = V[i] - dlam * k[i];
      const double dY = (dV[i] - dsig * k[i]) * isig - dlam * acc[i];
      out[kJacobiY1 + 8 * f + i] = Y;
      out[kJacobiDY1 + 8 * f + i] = dY;
      dout[kJacobiY1 + 8 * f + i] = dY;
    }
  }
}

}  // namespace

bool integrate_kerr_mino_jacobi(double M, double a, double r_break, const SolverConfig& cfg_in, double* y_io,
                                double lambda0, StepCallback cb, GeodesicResult& res) {
  using L = MinoJacobiLayout;
  using I = KerrMinoRHS;
  // The Walker–Penrose constant is that of null geodesics; the fields must start at zero.
  if (cfg_in.type != GeodesicType::Lightlike) return false;
  for (int i = 0; i < 4; ++i)
    if (y_io[kJacobiY1 + i] != 0.0 || y_io[kJacobiY2 + i] != 0.0) return false;
  SolverConfig cfg = cfg_in;
  if (!cfg_in.step_max_separable) cfg.step_max = SolverConfig{}.step_max;
  const Vec4 x0{{y_io[0], y_io[1], y_io[2], y_io[3]}};
  const Vec4 k0{{y_io[4], y_io[5], y_io[6], y_io[7]}};
  const Vec4 s0[2] = {Vec4{{y_io[kJacobiS1], y_io[kJacobiS1 + 1], y_io[kJacobiS1 + 2], y_io[kJacobiS1 + 3]}},
                      Vec4{{y_io[kJacobiS2], y_io[kJacobiS2 + 1], y_io[kJacobiS2 + 2], y_io[kJacobiS2 + 3]}}};
  const double mu2 = -constraint_target(cfg.type);
  const KerrMinoConstants c = kerr_mino_constants(M, a, x0, k0, mu2);
  if (c.axis) return false;

  // Value: the ray's own Mino state and constants, bit for bit those of integrate_kerr_mino.
  double y[L::N], v[I::N];
  const PolarOffset polar0 = kerr_mino_from_bl(c, x0, k0, lambda0, v);
  for (int i = 0; i < I::N; ++i) y[L::at(i, -1)] = v[i];
  KerrMinoJacobiSystem sys{KerrMinoSystem{c, KerrMinoRHS{c, polar0}, 1.0 / r_break}, {}};
  KerrMinoCoeffs<DualJ>& kd = sys.kd;
  kd.M = M;
  kd.a = a;
  kd.mu2 = mu2;
  kd.E = c.E;
  kd.L = c.L;
  kd.Q = c.Q;
  // Derivatives along δk_f = Y_f'(0): E = −k_t and L = k_φ are linear in k (kerr_mino_constants
  // of δk gives their derivatives), Q = p_θ² + cos²θ (a²(μ² − E²) + L²/sin²θ) (Carter 1968) is
  // quadratic; the initial w', z' are linear in k (kerr_mino_from_bl of δk), w, ζ, t, φ, λ are
  // those of the start event.
  const double st = std::sin(x0[2]), ct = std::cos(x0[2]);
  const double sigma0 = x0[1] * x0[1] + a * a * ct * ct;
  for (int f = 0; f < 2; ++f) {
    const Vec4 dk{{y_io[kJacobiDY1 + 8 * f], y_io[kJacobiDY1 + 8 * f + 1], y_io[kJacobiDY1 + 8 * f + 2],
                   y_io[kJacobiDY1 + 8 * f + 3]}};
    const KerrMinoConstants dc = kerr_mino_constants(M, a, x0, dk, mu2);
    kd.E.d[f] = dc.E;
    kd.L.d[f] = dc.L;
    kd.Q.d[f] =
        2.0 * sigma0 * k0[2] * sigma0 * dk[2] + ct * ct * (-2.0 * a * a * c.E * dc.E + 2.0 * c.L * dc.L / (st * st));
    double dv[I::N];
    kerr_mino_from_bl(c, x0, dk, 0.0, dv);
    for (int i = 0; i < I::N; ++i) y[L::at(i, f)] = 0.0;
    y[L::at(I::DW, f)] = dv[I::DW];
    y[L::at(I::DZ, f)] = dv[I::DZ];
  }
  kd.derive_polynomial();

  ThetaBranch branch = ThetaBranch::through(x0[2]);
  sys.ray.set_box(cfg, branch);
  double bl0[kJacobiDim], bl1[kJacobiDim], dbl0[kJacobiDim], dbl1[kJacobiDim], p0[3], p1[3];
  bool have0 = false;
  auto on_step = [&](const StepView& st_) -> StepAction {
    if (!have0) to_bl_jacobi(c, sys.ray.f.polar, branch, st_.y0, st_.dy0, bl0, dbl0, p0);
    to_bl_jacobi(c, sys.ray.f.polar, branch, st_.y1, st_.dy1, bl1, dbl1, p1);
    const StepAction act =
        cb(StepView{st_.lambda0, st_.lambda1, bl0, bl1, dbl0, dbl1, kJacobiDim, st_.step_index, p0, p1});
    std::copy(bl1, bl1 + kJacobiDim, bl0);
    std::copy(dbl1, dbl1 + kJacobiDim, dbl0);
    std::copy(p1, p1 + 3, p0);
    have0 = true;
    return act;
  };
  res = cb ? integrate_dispatch(sys, cfg, y, lambda0, on_step) : integrate_dispatch(sys, cfg, y, lambda0, {});
  double dy[L::N];
  sys(y, dy);
  to_bl_jacobi(c, sys.ray.f.polar, branch, y, dy, bl1, dbl1);
  Vec4 s[2];
  if (!kerr_transported_screen(M, a, x0, k0, s0, Vec4{{bl1[0], bl1[1], bl1[2], bl1[3]}},
                               Vec4{{bl1[4], bl1[5], bl1[6], bl1[7]}}, s))
    s[0] = s[1] = Vec4{{kNaN, kNaN, kNaN, kNaN}};
  for (int i = 0; i < 4; ++i) {
    bl1[kJacobiS1 + i] = s[0][i];
    bl1[kJacobiS2 + i] = s[1][i];
  }
  std::copy(bl1, bl1 + kJacobiDim, y_io);
  return true;
}

}  // namespace geovis
