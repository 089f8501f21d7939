// Kerr geodesics in Mino time: constants of motion and the conversions between Boyer–Lindquist
// (x, k) and the Mino state (formulas in kerr_mino.h).
#include "spacetime/kerr_mino.h"

#include <algorithm>
#include <cmath>

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

GeodesicResult integrate_kerr_mino(double M, double a, double r_break, const SolverConfig& cfg_in, double* y_io,
                                   double lambda0, StepCallback cb) {
  SolverConfig cfg = cfg_in;
  if (!cfg_in.step_max_separable) cfg.step_max = SolverConfig{}.step_max;
  const Vec4 x0{{y_io[0], y_io[1], y_io[2], y_io[3]}};
  const Vec4 k0{{y_io[4], y_io[5], y_io[6], y_io[7]}};
  const double mu2 = -constraint_target(cfg.type);
  const KerrMinoConstants c = kerr_mino_constants(M, a, x0, k0, mu2);
  double y[KerrMinoRHS::N];
  const PolarOffset polar0 = kerr_mino_from_bl(c, x0, k0, lambda0, y);
  KerrMinoSystem sys{c, KerrMinoRHS{c, polar0}, 1.0 / r_break};
  ThetaBranch branch = ThetaBranch::through(x0[2]);
  sys.set_box(cfg, branch);
  // A turning point of z at the axis (L = 0) inside step s: the ray went through the pole.
  auto track_axis = [&](const StepView& s) {
    using I = KerrMinoRHS;
    const double z1 = sys.f.polar.z(s.y1[I::Z]);
    if (c.axis && s.y0[I::DZ] * s.y1[I::DZ] < 0.0 && z1 * s.y1[I::DZ] < 0.0) branch.cross_axis(z1);
  };

  // BL view of the previous step end (the start of the next step).
  double bl0[8], bl1[8], dbl0[8], dbl1[8];
  bool have0 = false;
  auto to_bl = [&](const double* ym, const double* dym, double* bl, double* dbl) {
    Vec4 x, kk, acc;
    kerr_mino_to_bl(c, sys.f.polar, ym, dym, branch, x, kk, &acc);
    for (int i = 0; i < 4; ++i) {
      bl[i] = x[i];
      bl[4 + i] = kk[i];
      dbl[i] = kk[i];
      dbl[4 + i] = acc[i];
    }
  };
  auto on_step = [&](const StepView& s) -> StepAction {
    if (!have0) to_bl(s.y0, s.dy0, bl0, dbl0);
    track_axis(s);
    to_bl(s.y1, s.dy1, bl1, dbl1);
    StepAction act = StepAction::Continue;
    if (cb) act = cb(StepView{s.lambda0, s.lambda1, bl0, bl1, dbl0, dbl1, 8, s.step_index});
    for (int i = 0; i < 8; ++i) {
      bl0[i] = bl1[i];
      dbl0[i] = dbl1[i];
    }
    have0 = true;
    return act;
  };
  auto axis_only = [&](const StepView& s) {
    track_axis(s);
    return StepAction::Continue;
  };
  // Without a caller's callback only the axis passages need watching (the BL view is not built).
  const GeodesicResult res = cb       ? integrate_dispatch(sys, cfg, y, lambda0, on_step)
                             : c.axis ? integrate_dispatch(sys, cfg, y, lambda0, axis_only)
                                      : integrate_dispatch(sys, cfg, y, lambda0, StepCallback{});
  double dy[KerrMinoRHS::N];
  sys(y, dy);
  Vec4 x, kk;
  kerr_mino_to_bl(c, sys.f.polar, y, dy, branch, x, kk);
  for (int i = 0; i < 4; ++i) {
    y_io[i] = x[i];
    y_io[4 + i] = kk[i];
  }
  return res;
}

}  // namespace geovis
