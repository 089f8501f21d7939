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
                     const ThetaBranch& b, Vec4& x, Vec4& k, Vec4* dk, double* p) {
  kerr_mino_bl_view<double>(c, c.axis, polar.pole, b.sign, b.offset, y, dy, x.c, k.c, dk ? dk->c : nullptr, p);
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

void KerrMinoRay::to_bl(const PolarOffset& polar, const ThetaBranch& b, const double* ym, const double* dym,
                        EndView& v, double* p) const {
  Vec4 x, kk, acc;
  kerr_mino_to_bl(c, polar, ym, dym, b, x, kk, &acc, p);
  for (int i = 0; i < 4; ++i) {
    v.xk[i] = x[i];
    v.xk[4 + i] = kk[i];
    v.xk[8 + i] = acc[i];
  }
  v.has_xk = true;
}

void KerrMinoRay::fill_views(const void* ray) {
  // The views belong to the ray (end_); the StepView that asks is const.
  KerrMinoRay& r = *const_cast<KerrMinoRay*>(static_cast<const KerrMinoRay*>(ray));
  // After report: the step's start is end_[start_ ^ 1], its end end_[start_].
  for (int e = 0; e < 2; ++e) {
    EndView& v = r.end_[r.start_ ^ (e == 0 ? 1 : 0)];
    if (v.has_xk) continue;
    double ym[KerrMinoRHS::N];
    std::copy_n(r.mino_states_[2 * e], KerrMinoRHS::N, ym);
    ym[KerrMinoRHS::Z] = v.zeta;
    r.to_bl(PolarOffset{v.pole}, v.branch, ym, r.mino_states_[2 * e + 1], v, nullptr);  // v.p is given
  }
}

StepAction KerrMinoRay::step(const StepView& s, StepCallback cb) {
  if (!cb) {
    track_axis(s);
    return StepAction::Continue;
  }
  return cb(bl_step(s));
}

StepView KerrMinoRay::bl_step(const StepView& s) {
  // The end is viewed on the branch after the step (the start: on the one before it).
  if (!have0_) to_bl(s.y0, s.dy0, end_[start_]);
  track_axis(s);
  to_bl(s.y1, s.dy1, next_end());
  return report(s);
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
