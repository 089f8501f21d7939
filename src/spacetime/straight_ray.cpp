#include "spacetime/straight_ray.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spacetime/integrators.h"
#include "spacetime/jacobi.h"

namespace geovis {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Path length s >= 0 (λ = λ0 + dir·s) beyond which x0 + s v lies outside the box [ll, ur]
/// (integrators.h MetricSystem::inside: outside means strictly beyond a face).
double box_exit(const double* x0, const double* v, const SolverConfig& cfg) {
  double s = kInf;
  for (int i = 0; i < 4; ++i) {
    if (v[i] > 0) s = std::min(s, (cfg.box_ur[i] - x0[i]) / v[i]);
    if (v[i] < 0) s = std::min(s, (cfg.box_ll[i] - x0[i]) / v[i]);
  }
  return s;
}

/// Path length beyond which a light ray p0 + s u (spatial) has escaped by the test of
/// escape.h for a metric without a photon sphere (Minkowski::escapes): |p| > R and p·u > 0. Both
/// hold, for good, beyond the closest approach s_c = −p0·u/|u|² and beyond the larger root of
/// |p0 + s u|² = R².
double escape_start(const double* p0, const double* u, double R) {
  const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  if (!(uu > 0)) return kInf;
  const double pu = p0[0] * u[0] + p0[1] * u[1] + p0[2] * u[2];
  const double pp = p0[0] * p0[0] + p0[1] * p0[1] + p0[2] * p0[2];
  const double s_c = -pu / uu;
  const double disc = pu * pu - uu * (pp - R * R);
  const double s_r = disc >= 0 ? (-pu + std::sqrt(disc)) / uu : -kInf;
  return std::max({s_c, s_r, 0.0});
}

}  // namespace

GeodesicResult integrate_straight(const SolverConfig& cfg, GeodesicSystem sys, double* y, double lambda0, bool escapes,
                                  StepCallback cb) {
  validate_solver_config(cfg);
  GeodesicResult res;
  res.lambda = lambda0;
  const int n = system_dim(sys);
  const double dir = cfg.direction >= 0 ? 1.0 : -1.0;
  // dy/dλ of the exact solution (file comment of straight_ray.h): constant along the line.
  double dy[kMaxSystemDim] = {};
  for (int mu = 0; mu < 4; ++mu) dy[mu] = y[4 + mu];
  if (sys == GeodesicSystem::Jacobi) {
    for (int mu = 0; mu < 4; ++mu) {
      dy[kJacobiY1 + mu] = y[kJacobiDY1 + mu];
      dy[kJacobiY2 + mu] = y[kJacobiDY2 + mu];
    }
  }
  const double v[4] = {dir * dy[0], dir * dy[1], dir * dy[2], dir * dy[3]};  // dx/ds

  for (int i = 0; i < 4; ++i)
    if (!(y[i] >= cfg.box_ll[i] && y[i] <= cfg.box_ur[i])) {
      res.reason = StopReason::BoundingBox;
      return res;
    }
  const double s_box = box_exit(y, v, cfg);
  const double s_esc = escapes && cfg.type == GeodesicType::Lightlike && cfg.escape_radius < kInf
                           ? escape_start(y + 1, v + 1, cfg.escape_radius)
                           : kInf;
  const double s_max = cfg.lambda_max;

  // The steps the integrator would take (integrate_with): the end of the first one past a stop
  // condition, or of the last one the budget allows.
  const double hmax = std::max(cfg.step_max, cfg.step_min);
  const double h0 = std::max(std::min(std::fabs(cfg.step_size), hmax), cfg.step_min);
  const bool adaptive = cfg.step_ctrl && cfg.kind != SolverKind::RK4;
  double s_end = 0;
  StopReason reason = StopReason::MaxSteps;
  if (!adaptive) {
    // Step j ends at j·h0 (the last one shortened to λ_max): closed form.
    const double j_exceed = std::floor(std::min(s_box, s_esc) / h0) + 1;  // first end beyond box or escape
    const double j_lmax = std::max(1.0, std::ceil(s_max / h0));           // the step clipped to λ_max
    const double j = std::min(j_exceed, j_lmax);
    if (j > cfg.max_steps) {
      s_end = cfg.max_steps * h0;
    } else {
      s_end = j == j_lmax ? s_max : j * h0;
      reason = s_end > s_box ? StopReason::BoundingBox : (j == j_lmax ? StopReason::LambdaMax : StopReason::Escaped);
    }
  } else {
    // StepController (integrators.h) grows an accepted step by its maximal factor 5 when the error
    // estimate vanishes, as it does on a straight line; step_max caps it.
    double h = h0;
    for (int j = 0;; ++j) {
      if (j >= cfg.max_steps) break;
      const double remaining = s_max - s_end;
      if (!(remaining > 0)) {
        reason = StopReason::LambdaMax;
        break;
      }
      const bool clipped = h >= remaining;
      const double hs = clipped ? remaining : h;
      s_end = clipped ? s_max : s_end + hs;
      if (s_end > s_box) {
        reason = StopReason::BoundingBox;
        break;
      }
      if (clipped) {
        reason = StopReason::LambdaMax;
        break;
      }
      if (s_end > s_esc) {
        reason = StopReason::Escaped;
        break;
      }
      h = std::min(hmax, std::max(StepController<1>::kMaxGrow * hs, cfg.step_min));
    }
  }
  if (!(s_end > 0)) {
    res.reason = reason;
    return res;
  }

  double y0[kMaxSystemDim];
  for (int i = 0; i < n; ++i) y0[i] = y[i];
  const double dl = dir * s_end;
  for (int i = 0; i < n; ++i) y[i] = y0[i] + dl * dy[i];
  res.steps = 1;
  res.lambda = lambda0 + dl;
  if (cb && cb(StepView{lambda0, lambda0 + dl, y0, y, dy, dy, n, 1}) == StepAction::Stop) {
    res.reason = StopReason::Callback;
    return res;
  }
  res.reason = reason;
  if (reason == StopReason::Escaped) {
    res.escape_radius = std::sqrt(y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
  }
  return res;
}

}  // namespace geovis
