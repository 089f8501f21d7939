// Kerr geodesics in Mino time: constants of motion and the conversions between Boyer–Lindquist
// (x, k) and the Mino state (formulas in kerr_mino.h).
#include "spacetime/kerr_mino.h"

#include <algorithm>
#include <cmath>

#include "spacetime/fast_math.h"

namespace geovis {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

KerrMinoConstants kerr_mino_constants(double M, double a, const Vec4& x, const Vec4& k, double mu2) {
  const double r = x[1], st = std::sin(x[2]), ct = std::cos(x[2]);
  const double a2 = a * a, st2 = st * st, ct2 = ct * ct;
  const double sigma = r * r + a2 * ct2;
  const double u = 2.0 * M * r / sigma;
  const double gtt = u - 1.0, gtp = -a * st2 * u, gpp = (r * r + a2 + a2 * st2 * u) * st2;
  KerrMinoConstants c;
  c.M = M;
  c.a = a;
  c.mu2 = mu2;
  c.E = -(gtt * k[0] + gtp * k[3]);
  c.L = gtp * k[0] + gpp * k[3];
  const double ptheta = sigma * k[2];
  // Carter constant (Carter 1968): Q = p_θ² + cos²θ (a²(μ² − E²) + L²/sin²θ).
  auto carter = [&] { return ptheta * ptheta + ct2 * (a2 * (mu2 - c.E * c.E) + c.L * c.L / st2); };
  c.Q = carter();
  // Closest approach to the axis below 1e-12 rad: through the axis (kerr_mino.h).
  if (std::fabs(c.L) <= 1e-12 * std::sqrt(std::fabs(c.Q) + a2 * c.E * c.E + c.L * c.L)) {
    c.L = 0.0;
    c.Q = carter();
  }
  c.derive();
  return c;
}

PolarOffset kerr_mino_from_bl(const KerrMinoConstants& c, const Vec4& x, const Vec4& k, double lambda, double* y) {
  using I = KerrMinoRHS;
  const double r = x[1], st = std::sin(x[2]), ct = std::cos(x[2]);
  const double sigma = r * r + c.a2 * ct * ct;
  y[I::T] = x[0];
  y[I::W] = 1.0 / r;
  const PolarOffset polar = PolarOffset::through(x[2], y[I::Z]);
  y[I::PHI] = x[3];
  y[I::LAM] = lambda;
  y[I::DW] = -sigma * k[1] / (r * r);  // dw/dσ = −(dr/dσ)/r², dr/dσ = Σ k^r
  y[I::DZ] = -st * sigma * k[2];       // dz/dσ = −sin θ Σ k^θ
  return polar;
}

ThetaBranch ThetaBranch::through(double theta) {
  const double tw = std::remainder(theta, 2.0 * kPi);  // in [−π, π]
  ThetaBranch b;
  b.sign = tw < 0.0 ? -1.0 : 1.0;
  b.offset = theta - tw;
  return b;
}

void ThetaBranch::cross_axis(double z) {
  // North pole (acos z → 0): θ = offset + s·acos z passes through offset. South pole
  // (acos z → π): it passes offset + sπ, which the new branch must keep.
  if (z < 0.0) offset += 2.0 * sign * kPi;
  sign = -sign;
}

void kerr_mino_to_bl(const KerrMinoConstants& c, const PolarOffset& polar, const double* y, const double* dy,
                     const ThetaBranch& b, Vec4& x, Vec4& k, Vec4* dk) {
  using I = KerrMinoRHS;
  const double w = y[I::W], z = std::clamp(polar.z(y[I::Z]), -1.0, 1.0), dw = y[I::DW], dz = y[I::DZ];
  const double r = 1.0 / w;
  const double s2_raw = polar.sin2(y[I::Z]);
  const double s_abs = std::sqrt(std::max(0.0, s2_raw));  // |sin θ|
  const double sigma = r * r + c.a2 * z * z, isig = 1.0 / sigma;
  // dθ/dσ = −s·z'/|sin θ|. For L = 0, Z = (1 − z²)(Q + Az²), so |z'|/|sin θ| = √(Q + Az²): used
  // instead, since near the axis, which such a ray passes, 1 − z² has lost its leading digits.
  const double dth =
      c.axis ? -b.sign * std::copysign(std::sqrt(std::max(0.0, c.Q + c.A * z * z)), dz) : -b.sign * dz / s_abs;
  const double dr = -dw * r * r;  // dr/dσ
  x = Vec4{{y[I::T], r, b.offset + b.sign * polar.acos_z(y[I::Z]), y[I::PHI]}};
  k = Vec4{{dy[I::T] * isig, dr * isig, dth * isig, dy[I::PHI] * isig}};
  if (!dk) return;
  // dk^μ/dλ = (x^μ'' Σ − x^μ' Σ')/Σ³ with ' = d/dσ, from the Mino derivatives (file comment):
  //   r'' = −w''r² + 2w'²r³,  θ'' = −(z'' + z θ'²)/sin θ  (L = 0: −A z sin θ),
  //   t'' = ∂_w T w' + ∂_z T z',  φ'' = ∂_w Φ w' + ∂_z Φ z',  Σ' = 2 r r' + 2a² z z'.
  const double sin_th = b.sign * s_abs;
  const double ddr = -dy[I::DW] * r * r + 2.0 * dw * dw * r * r * r;
  const double ddth = c.axis ? -c.A * z * sin_th : -(dy[I::DZ] + z * dth * dth) / sin_th;
  const double w2 = w * w, D = 1.0 - 2.0 * c.M * w + c.a2 * w2, dD = -2.0 * c.M + 2.0 * c.a2 * w;
  const double P = c.E + c.c * w2, dP = 2.0 * c.c * w;
  const double Nt = (1.0 + c.a2 * w2) * P, dNt = 2.0 * c.a2 * w * P + (1.0 + c.a2 * w2) * dP;
  const double den = w2 * D, dden = 2.0 * w * D + w2 * dD;
  const double iD = 1.0 / D;
  const double dT_dw = (dNt - Nt * dden / den) / den, dT_dz = 2.0 * c.a2 * c.E * z;
  const double s2 = std::max(s2_raw, 1e-300);
  const double dPhi_dw = c.a * (dP - P * dD * iD) * iD, dPhi_dz = c.axis ? 0.0 : 2.0 * c.L * z / (s2 * s2);
  const double ddt = dT_dw * dw + dT_dz * dz, ddph = dPhi_dw * dw + dPhi_dz * dz;
  const double dsig = 2.0 * r * dr + 2.0 * c.a2 * z * dz;
  const double i3 = isig * isig * isig;
  *dk = Vec4{{(ddt * sigma - dy[I::T] * dsig) * i3, (ddr * sigma - dr * dsig) * i3, (ddth * sigma - dth * dsig) * i3,
              (ddph * sigma - dy[I::PHI] * dsig) * i3}};
}

SolverConfig KerrMinoRay::config(const SolverConfig& cfg_in) {
  SolverConfig cfg = cfg_in;
  if (!cfg_in.step_max_separable) cfg.step_max = SolverConfig{}.step_max;
  return cfg;
}

namespace {
KerrMinoConstants ray_constants(double M, double a, const double* y_bl, double mu2) {
  return kerr_mino_constants(M, a, Vec4{{y_bl[0], y_bl[1], y_bl[2], y_bl[3]}},
                             Vec4{{y_bl[4], y_bl[5], y_bl[6], y_bl[7]}}, mu2);
}
}  // namespace

KerrMinoRay::KerrMinoRay(double M, double a, double r_break, const SolverConfig& cfg, const double* y_bl,
                         double lambda0, double* y)
    : c(ray_constants(M, a, y_bl, -constraint_target(cfg.type))),
      branch(ThetaBranch::through(y_bl[2])),
      sys{c,
          KerrMinoRHS{c, kerr_mino_from_bl(c, Vec4{{y_bl[0], y_bl[1], y_bl[2], y_bl[3]}},
                                           Vec4{{y_bl[4], y_bl[5], y_bl[6], y_bl[7]}}, lambda0, y)},
          1.0 / r_break} {
  sys.set_box(cfg, branch);
}

void KerrMinoRay::track_axis(const StepView& s) {
  // A turning point of z at the axis (L = 0) inside step s: the ray went through the pole.
  using I = KerrMinoRHS;
  const double z1 = sys.f.polar.z(s.y1[I::Z]);
  if (c.axis && s.y0[I::DZ] * s.y1[I::DZ] < 0.0 && z1 * s.y1[I::DZ] < 0.0) branch.cross_axis(z1);
}

void KerrMinoRay::to_bl(const double* ym, const double* dym, double* bl, double* dbl, double* p) const {
  using I = KerrMinoRHS;
  Vec4 x, kk, acc;
  kerr_mino_to_bl(c, sys.f.polar, ym, dym, branch, x, kk, &acc);
  for (int i = 0; i < 4; ++i) {
    bl[i] = x[i];
    bl[4 + i] = kk[i];
    dbl[i] = kk[i];
    dbl[4 + i] = acc[i];
  }
  kerr_mino_pseudo_cartesian(sys.f.polar, branch, ym, x[1], x[3], p);
}

void kerr_mino_pseudo_cartesian(const PolarOffset& polar, const ThetaBranch& b, const double* y, double r, double phi,
                                double* p) {
  using I = KerrMinoRHS;
  // r (sin θ cos φ, sin θ sin φ, cos θ) (Metric::to_pseudo_cartesian) without θ: cos θ = z,
  // sin θ = s·√(1 − z²) on the branch θ = offset + s·acos z (offset a multiple of 2π).
  const double z = std::clamp(polar.z(y[I::Z]), -1.0, 1.0);
  const double st = b.sign * std::sqrt(std::max(0.0, polar.sin2(y[I::Z])));
  double sp, cp;
  fast_sincos(phi, sp, cp);
  p[0] = r * st * cp;
  p[1] = r * st * sp;
  p[2] = r * z;
}

StepAction KerrMinoRay::step(const StepView& s, StepCallback cb) {
  if (!cb) {
    track_axis(s);
    return StepAction::Continue;
  }
  // The BL view of the previous step end is the start of this step.
  if (!have0_) to_bl(s.y0, s.dy0, bl0_, dbl0_, p0_);
  track_axis(s);
  to_bl(s.y1, s.dy1, bl1_, dbl1_, p1_);
  const StepAction act = cb(StepView{s.lambda0, s.lambda1, bl0_, bl1_, dbl0_, dbl1_, 8, s.step_index, p0_, p1_});
  for (int i = 0; i < 8; ++i) {
    bl0_[i] = bl1_[i];
    dbl0_[i] = dbl1_[i];
  }
  for (int i = 0; i < 3; ++i) p0_[i] = p1_[i];
  have0_ = true;
  return act;
}

void KerrMinoRay::to_bl_state(const double* y, double* y_bl) const {
  double dy[KerrMinoRHS::N];
  sys(y, dy);
  Vec4 x, kk;
  kerr_mino_to_bl(c, sys.f.polar, y, dy, branch, x, kk);
  for (int i = 0; i < 4; ++i) {
    y_bl[i] = x[i];
    y_bl[4 + i] = kk[i];
  }
}

GeodesicResult integrate_kerr_mino(double M, double a, double r_break, const SolverConfig& cfg_in, double* y_io,
                                   double lambda0, StepCallback cb) {
  const SolverConfig cfg = KerrMinoRay::config(cfg_in);
  double y[KerrMinoRHS::N];
  KerrMinoRay ray(M, a, r_break, cfg, y_io, lambda0, y);
  auto on_step = [&](const StepView& s) { return ray.step(s, cb); };
  // Without a caller's callback only the axis passages need watching (the BL view is not built).
  const GeodesicResult res = cb || ray.c.axis ? integrate_dispatch(ray.sys, cfg, y, lambda0, on_step)
                                              : integrate_dispatch(ray.sys, cfg, y, lambda0, StepCallback{});
  ray.to_bl_state(y, y_io);
  return res;
}

}  // namespace geovis
