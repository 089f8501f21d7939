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

KerrMinoJacobiRay::KerrMinoJacobiRay(double M, double a, double r_break, const SolverConfig& cfg, const double* y_bl,
                                     double lambda0, double* y)
    : x0{{y_bl[0], y_bl[1], y_bl[2], y_bl[3]}},
      k0{{y_bl[4], y_bl[5], y_bl[6], y_bl[7]}},
      s0{Vec4{{y_bl[kJacobiS1], y_bl[kJacobiS1 + 1], y_bl[kJacobiS1 + 2], y_bl[kJacobiS1 + 3]}},
         Vec4{{y_bl[kJacobiS2], y_bl[kJacobiS2 + 1], y_bl[kJacobiS2 + 2], y_bl[kJacobiS2 + 3]}}},
      sys{KerrMinoSystem{c, KerrMinoRHS{c, PolarOffset{}}, 1.0 / r_break}, {}} {
  using L = MinoJacobiLayout;
  using I = KerrMinoRHS;
  // The Walker–Penrose constant is that of null geodesics; the fields must start at zero.
  if (cfg.type != GeodesicType::Lightlike) return;
  for (int i = 0; i < 4; ++i)
    if (y_bl[kJacobiY1 + i] != 0.0 || y_bl[kJacobiY2 + i] != 0.0) return;
  const double mu2 = -constraint_target(cfg.type);
  c = kerr_mino_constants(M, a, x0, k0, mu2);
  if (c.axis) return;
  integrable = true;

  // Value: the ray's own Mino state and constants, bit for bit those of integrate_kerr_mino.
  double v[I::N];
  sys.ray.f.polar = kerr_mino_from_bl(c, x0, k0, lambda0, v);
  for (int i = 0; i < I::N; ++i) y[L::at(i, -1)] = v[i];
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
    const Vec4 dk{{y_bl[kJacobiDY1 + 8 * f], y_bl[kJacobiDY1 + 8 * f + 1], y_bl[kJacobiDY1 + 8 * f + 2],
                   y_bl[kJacobiDY1 + 8 * f + 3]}};
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
  branch = ThetaBranch::through(x0[2]);
  sys.ray.set_box(cfg, branch);
}

StepView KerrMinoJacobiRay::bl_step(const StepView& s) {
  const int end = start_ ^ 1;
  if (!have0_) to_bl_jacobi(c, sys.ray.f.polar, branch, s.y0, s.dy0, bl_[start_], dbl_[start_], p_[start_]);
  to_bl_jacobi(c, sys.ray.f.polar, branch, s.y1, s.dy1, bl_[end], dbl_[end], p_[end]);
  converted_[start_] = converted_[end] = true;
  const StepView bl{s.lambda0, s.lambda1,  bl_[start_],  bl_[end],   dbl_[start_],
                    dbl_[end], kJacobiDim, s.step_index, p_[start_], p_[end]};
  start_ = end;
  have0_ = true;
  return bl;
}

StepView KerrMinoJacobiRay::bl_step_with_position(const StepView& s) {
  using L = MinoJacobiLayout;
  using I = KerrMinoRHS;
  const int end = start_ ^ 1;
  double v[I::N];
  if (!have0_) {
    L::value(s.y0, v);
    pole_[start_] = sys.ray.f.polar.pole;
    zeta_[start_] = v[I::Z];
    converted_[start_] = false;
    kerr_mino_position<double>(pole_[start_], branch.sign, v, p_[start_]);
  }
  L::value(s.y1, v);
  pole_[end] = sys.ray.f.polar.pole;
  zeta_[end] = v[I::Z];
  converted_[end] = false;
  kerr_mino_position<double>(pole_[end], branch.sign, v, p_[end]);
  mino_states_[0] = s.y0;
  mino_states_[1] = s.dy0;
  mino_states_[2] = s.y1;
  mino_states_[3] = s.dy1;
  StepView bl{s.lambda0, s.lambda1,  bl_[start_],  bl_[end],   dbl_[start_],
              dbl_[end], kJacobiDim, s.step_index, p_[start_], p_[end]};
  bl.fill_states = &fill_views;
  bl.fill_context = this;
  start_ = end;
  have0_ = true;
  return bl;
}

void KerrMinoJacobiRay::fill_views(const void* context) {
  using L = MinoJacobiLayout;
  using I = KerrMinoRHS;
  // Called during the step's callback: start_ is already the step's end.
  KerrMinoJacobiRay& r = *const_cast<KerrMinoJacobiRay*>(static_cast<const KerrMinoJacobiRay*>(context));
  for (const int end : {0, 1}) {
    const int slot = end ? r.start_ : r.start_ ^ 1;
    if (r.converted_[slot]) continue;
    double y[L::N];
    std::copy(r.mino_states_[2 * end], r.mino_states_[2 * end] + L::N, y);
    y[L::at(I::Z, -1)] = r.zeta_[slot];  // the start: before the re-basing after the previous step
    PolarOffset polar;
    polar.pole = r.pole_[slot];
    to_bl_jacobi(r.c, polar, r.branch, y, r.mino_states_[2 * end + 1], r.bl_[slot], r.dbl_[slot]);
    r.converted_[slot] = true;
  }
}

void KerrMinoJacobiRay::to_bl_state(const double* y, double* y_bl) const {
  double dy[MinoJacobiLayout::N], bl[kJacobiDim], dbl[kJacobiDim];
  sys(y, dy);
  to_bl_jacobi(c, sys.ray.f.polar, branch, y, dy, bl, dbl);
  Vec4 s[2];
  if (!kerr_transported_screen(c.M, c.a, x0, k0, s0, Vec4{{bl[0], bl[1], bl[2], bl[3]}},
                               Vec4{{bl[4], bl[5], bl[6], bl[7]}}, s))
    s[0] = s[1] = Vec4{{kNaN, kNaN, kNaN, kNaN}};
  for (int i = 0; i < 4; ++i) {
    bl[kJacobiS1 + i] = s[0][i];
    bl[kJacobiS2 + i] = s[1][i];
  }
  std::copy(bl, bl + kJacobiDim, y_bl);
}

bool integrate_kerr_mino_jacobi(double M, double a, double r_break, const SolverConfig& cfg_in, double* y_io,
                                double lambda0, StepCallback cb, GeodesicResult& res) {
  const SolverConfig cfg = KerrMinoRay::config(cfg_in);
  double y[MinoJacobiLayout::N];
  KerrMinoJacobiRay ray(M, a, r_break, cfg, y_io, lambda0, y);
  if (!ray.integrable) return false;
  auto on_step = [&](const StepView& s) { return cb(ray.bl_step(s)); };
  res = cb ? integrate_dispatch(ray.sys, cfg, y, lambda0, on_step) : integrate_dispatch(ray.sys, cfg, y, lambda0, {});
  ray.to_bl_state(y, y_io);
  return true;
}

}  // namespace geovis
