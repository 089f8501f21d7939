// Integrator templates: the ODE systems along a geodesic and the explicit steppers. Everything
// here is a template instantiated per concrete metric (metric_crtp.h), so a Runge-Kutta stage is
// straight-line code with the metric's Christoffel symbols inlined.
//
// Stepper concept:
//   static constexpr int kOrder;                 // order of the propagated solution
//   static constexpr int kErrOrder;              // order of the embedded estimate (0: none)
//   template <int N, class F> bool attempt(F& f, const double* y, const double* dy, double h,
//                                          double* yout, double* yerr, double* dyout, long& evals);
//     one trial step of size h from (y, dy = f(y)); writes the new state and an error estimate
//     (componentwise, zero when kErrOrder == 0); returns true when it also wrote dyout = f(yout)
//     (first-same-as-last methods).
#pragma once

#include <algorithm>
#include <cmath>

#include "spacetime/geodesic.h"
#include "spacetime/vec.h"

namespace geovis {

// ---- ODE systems -------------------------------------------------------------------------------

/// Geodesic equation d²x^μ/dλ² = −Γ^μ_{ab} k^a k^b (y = x, k). Uses the metric's hand-written
/// acceleration when it has one, else contracts the closed-form Christoffel symbols.
template <class M>
struct GeodesicRHS {
  static constexpr int N = 8;
  const M& m;
  void operator()(const double* y, double* dy) const {
    const Vec4 x{{y[0], y[1], y[2], y[3]}};
    const Vec4 k{{y[4], y[5], y[6], y[7]}};
    Vec4 a;
    m.geodesic_acceleration(x, k, a);
    for (int i = 0; i < 4; ++i) {
      dy[i] = k[i];
      dy[4 + i] = a[i];
    }
  }
};

/// Geodesic plus parallel transport of four vectors (paper §2.3): de^μ/dλ = −Γ^μ_{ab} k^a e^b.
template <class M>
struct TransportRHS {
  static constexpr int N = 24;
  const M& m;
  void operator()(const double* y, double* dy) const {
    const Vec4 x{{y[0], y[1], y[2], y[3]}};
    Christoffel G;
    m.christoffel_inline(x, G);
    const double* k = y + 4;
    for (int i = 0; i < 4; ++i) dy[i] = k[i];
    for (int v = 0; v < 5; ++v) {  // v = 0: k itself; 1..4: transported vectors
      const double* e = y + 4 + 4 * v;
      for (int mu = 0; mu < 4; ++mu) {
        double s = 0;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) s += G.G[mu][a][b] * k[a] * e[b];
        dy[4 + 4 * v + mu] = -s;
      }
    }
  }
};

// The Jacobi system (Sachs basis + Jacobi matrix) lives in spacetime/jacobi.h.

// ---- Butcher tableaux ---------------------------------------------------------------------------

/// Generic explicit embedded Runge-Kutta step from a tableau type with static members
/// S (stages), c[S], a[S][S], b[S] (propagated), e[S] = b - b_hat (error weights), kOrder,
/// kErrOrder, kFsal.
template <class Tab>
struct ExplicitRK {
  static constexpr int kOrder = Tab::kOrder;
  static constexpr int kErrOrder = Tab::kErrOrder;
  template <int N, class F>
  static bool attempt(F& f, const double* y, const double* dy, double h, double* yout, double* yerr,
                      double* dyout, long& evals) {
    constexpr int S = Tab::S;
    double k[S][N];
    double tmp[N];
    for (int i = 0; i < N; ++i) k[0][i] = dy[i];
    for (int s = 1; s < S; ++s) {
      for (int i = 0; i < N; ++i) {
        double acc = 0;
        for (int j = 0; j < s; ++j) acc += Tab::a[s][j] * k[j][i];
        tmp[i] = y[i] + h * acc;
      }
      f(tmp, k[s]);
      ++evals;
    }
    for (int i = 0; i < N; ++i) {
      double acc = 0, err = 0;
      for (int s = 0; s < S; ++s) {
        acc += Tab::b[s] * k[s][i];
        err += Tab::e[s] * k[s][i];
      }
      yout[i] = y[i] + h * acc;
      yerr[i] = h * err;
    }
    if constexpr (Tab::kFsal) {
      for (int i = 0; i < N; ++i) dyout[i] = k[S - 1][i];
      return true;
    }
    return false;
  }
};

/// Cash & Karp, ACM TOMS 16 (1990) 201: embedded 4(5), the 5th-order solution is propagated
/// (as GSL's rkck and Numerical Recipes).
struct CashKarpTableau {
  static constexpr int S = 6, kOrder = 5, kErrOrder = 4;
  static constexpr bool kFsal = false;
  static constexpr double a[6][6] = {
      {0, 0, 0, 0, 0, 0},
      {1.0 / 5, 0, 0, 0, 0, 0},
      {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
      {3.0 / 10, -9.0 / 10, 6.0 / 5, 0, 0, 0},
      {-11.0 / 54, 5.0 / 2, -70.0 / 27, 35.0 / 27, 0, 0},
      {1631.0 / 55296, 175.0 / 512, 575.0 / 13824, 44275.0 / 110592, 253.0 / 4096, 0}};
  static constexpr double b[6] = {37.0 / 378, 0, 250.0 / 621, 125.0 / 594, 0, 512.0 / 1771};
  static constexpr double e[6] = {37.0 / 378 - 2825.0 / 27648, 0, 250.0 / 621 - 18575.0 / 48384,
                                  125.0 / 594 - 13525.0 / 55296, -277.0 / 14336, 512.0 / 1771 - 0.25};
};

/// Classical fourth-order Runge-Kutta (fixed step; no error estimate).
struct RK4Tableau {
  static constexpr int S = 4, kOrder = 4, kErrOrder = 0;
  static constexpr bool kFsal = false;
  static constexpr double a[4][4] = {{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1, 0}};
  static constexpr double b[4] = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
  static constexpr double e[4] = {0, 0, 0, 0};
};

// ---- driver --------------------------------------------------------------------------------------

/// Target of the normalization constraint and helpers shared by the driver.
template <class M>
inline double constraint_value(const M& m, const double* y, GeodesicType type) {
  const Vec4 x{{y[0], y[1], y[2], y[3]}};
  const Vec4 k{{y[4], y[5], y[6], y[7]}};
  Mat4 g;
  m.metric_tensor_inline(x, g);
  return dot(g, k, k) - constraint_target(type);
}

/// Re-projects k onto g(k,k) = target by solving the quadratic for k^0 (root closest to the
/// current k^0); leaves k unchanged when no real root exists.
template <class M>
inline void reproject_constraint(const M& m, double* y, GeodesicType type) {
  const Vec4 x{{y[0], y[1], y[2], y[3]}};
  Mat4 g;
  m.metric_tensor_inline(x, g);
  const double* k = y + 4;
  const double A = g[0][0];
  double B = 0, C = -constraint_target(type);
  for (int i = 1; i < 4; ++i) {
    B += 2 * g[0][i] * k[i];
    for (int j = 1; j < 4; ++j) C += g[i][j] * k[i] * k[j];
  }
  if (std::fabs(A) < 1e-300) {
    if (std::fabs(B) > 1e-300) y[4] = -C / B;
    return;
  }
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return;
  const double s = std::sqrt(disc);
  const double r1 = (-B + s) / (2 * A), r2 = (-B - s) / (2 * A);
  y[4] = std::fabs(r1 - k[0]) < std::fabs(r2 - k[0]) ? r1 : r2;
}

inline bool inside_box(const SolverConfig& c, const double* y) {
  for (int i = 0; i < 4; ++i)
    if (y[i] < c.box_ll[i] || y[i] > c.box_ur[i]) return false;
  return true;
}

/// Integrates y' = f(y) with stepper St, stopping at the first of: callback stop, invalid
/// coordinates, leaving the bounding box, |λ| ≥ lambda_max, max_steps accepted steps,
/// constraint violation, step underflow, non-finite state.
template <class St, class M, class F>
GeodesicResult integrate_with(const M& m, F& f, const SolverConfig& cfg, double* y_io, double lambda0,
                              StepCallback cb) {
  constexpr int N = F::N;
  GeodesicResult res;
  double y[N], dy[N], y1[N], dy1[N], yerr[N];
  for (int i = 0; i < N; ++i) y[i] = y_io[i];
  double lambda = lambda0;
  const double dir = cfg.direction >= 0 ? 1.0 : -1.0;
  const bool adaptive = cfg.step_ctrl && St::kErrOrder > 0;
  double h = std::clamp(std::fabs(cfg.step_size), cfg.step_min, cfg.step_max);
  const bool check_constraint = N >= 8;

  auto finish = [&](StopReason r) {
    for (int i = 0; i < N; ++i) y_io[i] = y[i];
    res.reason = r;
    res.lambda = lambda;
    if (check_constraint) res.constraint_drift = constraint_value(m, y, cfg.type);
    return res;
  };

  if (!m.is_valid(Vec4{{y[0], y[1], y[2], y[3]}})) return finish(StopReason::Invalid);
  if (!inside_box(cfg, y)) return finish(StopReason::BoundingBox);
  f(y, dy);
  ++res.rhs_evals;
  const double kscale0 = std::max(1.0, std::fabs(y[4]));

  while (true) {
    if (res.steps >= cfg.max_steps) return finish(StopReason::MaxSteps);
    double hstep = h;
    const double remaining = cfg.lambda_max - std::fabs(lambda - lambda0);
    bool clipped = false;
    if (remaining <= 0) return finish(StopReason::LambdaMax);
    if (hstep >= remaining) {
      hstep = remaining;
      clipped = true;
    }
    const bool have_dy1 = St::template attempt<N>(f, y, dy, dir * hstep, y1, yerr, dy1, res.rhs_evals);
    bool finite = true;
    for (int i = 0; i < N; ++i) finite = finite && std::isfinite(y1[i]);
    if (adaptive) {
      double err = 0;
      for (int i = 0; i < N; ++i) {
        const double sc = cfg.eps_abs + cfg.eps_rel * std::max(std::fabs(y[i]), std::fabs(y1[i]));
        err = std::max(err, std::fabs(yerr[i]) / sc);
      }
      if (!finite || !(err <= 1.0)) {
        ++res.rejected;
        const double fac = finite && std::isfinite(err)
                               ? std::max(0.2, 0.9 * std::pow(err, -1.0 / St::kErrOrder))
                               : 0.25;
        h = hstep * fac;
        if (h < cfg.step_min) return finish(StopReason::StepUnderflow);
        continue;
      }
      // Grow the step for the next attempt (never more than 5x), as GSL's standard control.
      const double fac = err > 0 ? std::min(5.0, 0.9 * std::pow(err, -1.0 / (St::kErrOrder + 1))) : 5.0;
      if (!clipped) h = std::min(cfg.step_max, std::max(hstep * fac, cfg.step_min));
    } else if (!finite) {
      return finish(StopReason::NotFinite);
    }
    if (!m.is_valid(Vec4{{y1[0], y1[1], y1[2], y1[3]}})) return finish(StopReason::Invalid);
    if (cfg.reproject && N >= 8) reproject_constraint(m, y1, cfg.type);
    if (!have_dy1 || cfg.reproject) {
      f(y1, dy1);
      ++res.rhs_evals;
    }
    ++res.steps;
    const double lambda1 = lambda + dir * hstep;
    StepAction act = StepAction::Continue;
    if (cb) act = cb(StepView{lambda, lambda1, y, y1, dy, dy1, N, res.steps});
    for (int i = 0; i < N; ++i) {
      y[i] = y1[i];
      dy[i] = dy1[i];
    }
    lambda = lambda1;
    if (act == StepAction::Stop) return finish(StopReason::Callback);
    if (!inside_box(cfg, y)) return finish(StopReason::BoundingBox);
    if (clipped) return finish(StopReason::LambdaMax);
    if (check_constraint) {
      const double c = constraint_value(m, y, cfg.type);
      const double scale = std::max(kscale0, y[4] * y[4]);
      if (!(std::fabs(c) <= cfg.constraint_tol * scale)) return finish(StopReason::Constraint);
    }
  }
}

/// Chooses the stepper for cfg.kind (dispatch once per geodesic).
template <class M, class F>
GeodesicResult integrate_system(const M& m, F& f, const SolverConfig& cfg, double* y, double lambda0,
                                StepCallback cb) {
  switch (cfg.kind) {
    case SolverKind::RK4:
      return integrate_with<ExplicitRK<RK4Tableau>>(m, f, cfg, y, lambda0, cb);
    case SolverKind::CashKarp45:
    default:
      return integrate_with<ExplicitRK<CashKarpTableau>>(m, f, cfg, y, lambda0, cb);
  }
}

}  // namespace geovis
