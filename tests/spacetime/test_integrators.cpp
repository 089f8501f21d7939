// The integrators on problems with known solutions (no metric involved): tableau consistency,
// convergence at the nominal order with fixed steps, error proportional to the tolerance with
// step control, driver semantics (λ_max, max_steps, callback, domain, underflow), and no heap
// allocation inside the integration loop.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "spacetime/geodesic_packet.h"
#include "spacetime/integrators.h"
#include "spacetime/metric.h"
#include "spacetime/metric_registry.h"
#include "spacetime/solver_type.h"

using namespace geovis;

// ---- heap allocation counter (global operator new of this test executable) ------------------
namespace {
std::atomic<long> g_allocations{0};
}
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace {

// ---- problems ------------------------------------------------------------------------------------

/// Kepler problem, μ = 1: r'' = −r/|r|³ (y = x, y, vx, vy). Started at pericentre of an orbit with
/// semi-major axis a = 1 and eccentricity e, it returns to the initial state after the period
/// T = 2π a^{3/2} = 2π (Kepler's third law).
/// Every registered integrator that takes a general first-order system y' = f(λ, y): all but the
/// Runge–Kutta–Nyström ones (SolverType::separable_only), which need the form y'' = f(y) and are
/// tested on it below (Kepler, OrderCase). Read from the registry, so a new integrator is tested here
/// without editing this file.
std::vector<SolverKind> general_solver_kinds() {
  std::vector<SolverKind> kinds;
  for (const SolverType* t : SolverRegistry::instance().entries())
    if (!t->separable_only) kinds.push_back(t->kind);
  return kinds;
}

struct Kepler {
  static constexpr int N = 4;
  static constexpr int kNystromPositions = 2;  // (x, y), (vx, vy): y'' = f(y), for RKN86
  void operator()(const double* y, double* dy) const {
    const double r2 = y[0] * y[0] + y[1] * y[1];
    const double ir3 = 1.0 / (r2 * std::sqrt(r2));
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = -y[0] * ir3;
    dy[3] = -y[1] * ir3;
  }
  static void initial(double e, double* y) {
    // Pericentre distance a(1−e), speed from vis-viva: v² = (1+e)/(1−e) for a = 1.
    y[0] = 1.0 - e;
    y[1] = 0;
    y[2] = 0;
    y[3] = std::sqrt((1.0 + e) / (1.0 - e));
  }
};

/// Harmonic oscillator x'' = −x: x(t) = cos t, v(t) = −sin t for x(0) = 1, v(0) = 0.
struct Oscillator {
  static constexpr int N = 2;
  static constexpr int kNystromPositions = 1;
  void operator()(const double* y, double* dy) const {
    dy[0] = y[1];
    dy[1] = -y[0];
  }
};

/// y' = y², y(0) = 1: y = 1/(1 − t) blows up at t = 1.
struct BlowUp {
  static constexpr int N = 1;
  void operator()(const double* y, double* dy) const { dy[0] = y[0] * y[0]; }
};

constexpr double kTwoPi = 6.283185307179586476925286766559;

double kepler_error(SolverKind kind, bool step_ctrl, double h_or_tol, double ecc, int* steps = nullptr) {
  Kepler f;
  double y[4], y0[4];
  Kepler::initial(ecc, y0);
  for (int i = 0; i < 4; ++i) y[i] = y0[i];
  SolverConfig cfg;
  cfg.kind = kind;
  cfg.step_ctrl = step_ctrl;
  if (step_ctrl) {
    cfg.eps_abs = h_or_tol;
    cfg.step_size = 1e-3;
  } else {
    cfg.step_size = h_or_tol;
  }
  cfg.lambda_max = kTwoPi;
  cfg.max_steps = 10000000;
  const GeodesicResult r = integrate_ode(f, cfg, y, 0.0);
  EXPECT_EQ(r.reason, StopReason::LambdaMax) << solver_kind_name(kind);
  EXPECT_DOUBLE_EQ(r.lambda, kTwoPi);
  if (steps) *steps = r.steps;
  // Euclidean norm: the max norm over components fluctuates where one component's error changes
  // sign as h varies.
  double e2 = 0;
  for (int i = 0; i < 4; ++i) e2 += (y[i] - y0[i]) * (y[i] - y0[i]);
  return std::sqrt(e2);
}

/// Least-squares slope of log(err) against log(x).
double loglog_slope(const std::vector<double>& x, const std::vector<double>& err) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(err[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

template <class Tab>
void check_tableau(const char* name, int stages) {
  // Row sums of A equal the nodes c (HNW I eq. II.1.9); Σ b = 1 (consistency); the error weights
  // e = b − b̂ sum to 0 (both solutions are consistent).
  double sb = 0, se = 0;
  for (int s = 0; s < stages; ++s) {
    double row = 0;
    for (int j = 0; j < stages; ++j) row += Tab::a[s][j];
    EXPECT_NEAR(row, Tab::c[s], 1e-14) << name << " stage " << s;
    sb += Tab::b[s];
    se += Tab::e[s];
  }
  EXPECT_NEAR(sb, 1.0, 1e-14) << name;
  EXPECT_NEAR(se, 0.0, 1e-14) << name;
}

}  // namespace

TEST(Integrators, TableauxAreConsistent) {
  check_tableau<HeunEulerTableau>("HeunEuler", 2);
  check_tableau<RK4Tableau>("RK4", 4);
  check_tableau<CashKarpTableau>("CashKarp", 6);
  check_tableau<FehlbergTableau>("Fehlberg", 6);
  check_tableau<DormandPrince54Tableau>("DP54", 7);
  using T = DOP853Tableau;
  double sb = 0, s5 = 0, s3 = 0;
  for (int s = 0; s < T::S; ++s) {
    double row = 0;
    for (int j = 0; j < T::S; ++j) row += T::a[s][j];
    // dop853.f gives the coefficients to ~30 digits; the row sums hold to double precision.
    EXPECT_NEAR(row, T::c[s], 1e-13) << "DOP853 stage " << s;
    sb += T::b[s];
    s5 += T::e5[s];
    s3 += T::e3[s];
  }
  EXPECT_NEAR(sb, 1.0, 1e-13);
  EXPECT_NEAR(s5, 0.0, 1e-13);
  EXPECT_NEAR(s3, 0.0, 1e-13);
  // DP54 is first-same-as-last: its last row of A is b.
  for (int j = 0; j < 7; ++j) EXPECT_EQ(DormandPrince54Tableau::a[6][j], DormandPrince54Tableau::b[j]);
  // RKN86 (HNW I §II.14): rows of ā sum to c²/2, Σ b̄ = 1/2, Σ b = 1, Σ b̄ c... the order
  // conditions of the quadrature Σ b_j c_j^m = 1/(m+1) up to m = 7 (b integrates polynomials of
  // degree 7 exactly: 8th order), Σ b̄_j c_j^m = 1/((m+1)(m+2)) up to m = 6, and the error weights
  // sum to 0.
  using R = RKN86Tableau;
  for (int s = 0; s < R::S; ++s) {
    double row = 0;
    for (int j = 0; j < R::S; ++j) row += R::a[s][j];
    EXPECT_NEAR(row, 0.5 * R::c[s] * R::c[s], 1e-14) << "RKN86 stage " << s;
  }
  for (int m = 0; m <= 7; ++m) {
    double qv = 0, qp = 0;
    for (int j = 0; j < R::S; ++j) {
      qv += R::bv[j] * std::pow(R::c[j], m);
      qp += R::bp[j] * std::pow(R::c[j], m);
    }
    EXPECT_NEAR(qv, 1.0 / (m + 1), 1e-14) << "RKN86 velocity weights, c^" << m;
    if (m <= 6) {
      EXPECT_NEAR(qp, 1.0 / ((m + 1) * (m + 2)), 1e-14) << "RKN86 position weights, c^" << m;
    }
  }
  double ep = 0, ev = 0;
  for (int j = 0; j < R::S; ++j) {
    ep += R::ep[j];
    ev += R::ev[j];
  }
  EXPECT_NEAR(ep, 0.0, 1e-14);
  EXPECT_NEAR(ev, 0.0, 1e-14);
  for (int j = 0; j < R::S; ++j) EXPECT_EQ(R::a[8][j], R::bp[j]);  // first same as last
}

struct OrderCase {
  SolverKind kind;
  int order;
  std::vector<int> steps_per_run;  // all in the asymptotic range, above round-off
};

double oscillator_error(SolverKind kind, int n) {
  // Fixed step h = T/n; exact solution x = cos t, v = −sin t.
  constexpr double T = 10.0;
  Oscillator f;
  double y[2] = {1.0, 0.0};
  SolverConfig cfg;
  cfg.kind = kind;
  cfg.step_ctrl = false;
  cfg.step_size = T / n;
  cfg.lambda_max = T;
  cfg.max_steps = 10000000;
  const GeodesicResult r = integrate_ode(f, cfg, y, 0.0);
  EXPECT_EQ(r.reason, StopReason::LambdaMax);
  EXPECT_NEAR(r.steps, n, 1);  // the last step may be a round-off sliver
  return std::max(std::fabs(y[0] - std::cos(T)), std::fabs(y[1] + std::sin(T)));
}

TEST(Integrators, FixedStepConvergesAtNominalOrder) {
  const std::vector<OrderCase> cases = {
      {SolverKind::RK2, 2, {128, 256, 512, 1024}},           {SolverKind::RK4, 4, {64, 128, 256, 512}},
      {SolverKind::CashKarp45, 5, {32, 64, 128, 256}},       {SolverKind::Fehlberg45, 4, {64, 128, 256, 512}},
      {SolverKind::DormandPrince54, 5, {32, 64, 128, 256}},  {SolverKind::DormandPrince853, 8, {8, 16, 32, 64}},
      {SolverKind::BulirschStoer, 8, {8, 16, 32, 64}},  // 4 extrapolation rows with fixed steps
      {SolverKind::RungeKuttaNystrom86, 8, {8, 16, 32, 64}},
  };
  for (const auto& c : cases) {
    std::vector<double> h, errs;
    for (int n : c.steps_per_run) {
      h.push_back(10.0 / n);
      errs.push_back(oscillator_error(c.kind, n));
    }
    const double slope = loglog_slope(h, errs);
    EXPECT_NEAR(slope, c.order, 0.15) << solver_kind_name(c.kind) << ": errors " << errs.front() << " .. "
                                      << errs.back();
    EXPECT_EQ(c.order, solver_order(c.kind));
  }
}

TEST(Integrators, KeplerOrbitFixedStepOrder) {
  // The same on a nonlinear problem: one period of an e = 0.1 Kepler orbit. The step ranges sit
  // between the pre-asymptotic regime (large h) and round-off (errors below ~1e-12); the 8th-order
  // methods have only about one decade of h there, hence the looser slope tolerance.
  const double T = kTwoPi;
  const std::vector<OrderCase> cases = {
      {SolverKind::RK2, 2, {320, 640, 1280, 2560}},      {SolverKind::RK4, 4, {640, 1280, 2560}},
      {SolverKind::CashKarp45, 5, {80, 160, 320, 640}},  {SolverKind::Fehlberg45, 4, {226, 452, 905}},
      {SolverKind::DormandPrince54, 5, {226, 452, 905}}, {SolverKind::DormandPrince853, 8, {28, 40, 56, 80}},
      {SolverKind::BulirschStoer, 8, {20, 28, 40, 56}},
  };
  for (const auto& c : cases) {
    std::vector<double> h, errs;
    for (int n : c.steps_per_run) {
      h.push_back(T / n);
      errs.push_back(kepler_error(c.kind, false, T / n, 0.1));
    }
    EXPECT_NEAR(loglog_slope(h, errs), c.order, c.order >= 8 ? 0.3 : 0.15) << solver_kind_name(c.kind);
  }
}

TEST(Integrators, RungeKuttaNystromIsEighthOrderOnKepler) {
  // RKN86 on the e = 0.1 Kepler orbit: at the full period its error converges like h⁹ (errors
  // cancel over the closed orbit), so the order is measured at 0.6 periods against DOP853 with
  // 4000 steps (error ~1e-16) — and RKN86 must beat DOP853 at equal step count (it is ~25× more
  // accurate per step on this orbit with 8 instead of 11 new evaluations).
  const double T = 0.6 * kTwoPi;
  auto run = [&](SolverKind kind, int n, double* y) {
    Kepler f;
    Kepler::initial(0.1, y);
    SolverConfig cfg;
    cfg.kind = kind;
    cfg.step_ctrl = false;
    cfg.step_size = T / n;
    cfg.lambda_max = T;
    cfg.max_steps = 1000000;
    EXPECT_EQ(integrate_ode(f, cfg, y, 0.0).reason, StopReason::LambdaMax);
  };
  double ref[4];
  run(SolverKind::DormandPrince853, 4000, ref);
  std::vector<double> h, errs;
  for (int n : {12, 17, 24, 34}) {
    double y[4], yd[4];
    run(SolverKind::RungeKuttaNystrom86, n, y);
    run(SolverKind::DormandPrince853, n, yd);
    double e = 0, ed = 0;
    for (int i = 0; i < 4; ++i) {
      e += (y[i] - ref[i]) * (y[i] - ref[i]);
      ed += (yd[i] - ref[i]) * (yd[i] - ref[i]);
    }
    h.push_back(T / n);
    errs.push_back(std::sqrt(e));
    EXPECT_LT(std::sqrt(e), std::sqrt(ed)) << n << " steps";
  }
  EXPECT_NEAR(loglog_slope(h, errs), 8.0, 0.4) << "errors " << errs.front() << " .. " << errs.back();
}

TEST(Integrators, AdaptiveErrorScalesWithTolerance) {
  // With error-per-step control the estimate ~h^q̂ is held at tol, so h ~ tol^(1/q̂) and the global
  // error ~h^p ~ tol^(p/q̂) (HNW I §II.4): exponent 1 for the pairs that propagate the higher
  // order (RK2 2/2, Cash-Karp 5/5, DP54 5/5, DOP853 8/8), 4/5 for Fehlberg (4th order propagated,
  // 5th-order comparison), (2j+2)/(2j+1) ≈ 1.1 for Bulirsch-Stoer.
  struct Case {
    SolverKind kind;
    double exponent;
    std::vector<double> tols;
  };
  const std::vector<Case> cases = {
      {SolverKind::RK2, 1.0, {1e-5, 1e-6, 1e-7, 1e-8}},
      {SolverKind::CashKarp45, 1.0, {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}},
      {SolverKind::Fehlberg45, 0.8, {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}},
      {SolverKind::DormandPrince54, 1.0, {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}},
      {SolverKind::DormandPrince853, 1.0, {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}},
      {SolverKind::BulirschStoer, 1.1, {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}},
      {SolverKind::RungeKuttaNystrom86, 8.0 / 7.0, {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}},
  };
  for (const auto& c : cases) {
    std::vector<double> errs;
    int steps_loose = 0, steps_tight = 0;
    for (size_t i = 0; i < c.tols.size(); ++i) {
      int steps = 0;
      errs.push_back(kepler_error(c.kind, true, c.tols[i], 0.2, &steps));
      if (i == 0) steps_loose = steps;
      steps_tight = steps;
    }
    EXPECT_NEAR(loglog_slope(c.tols, errs), c.exponent, 0.25) << solver_kind_name(c.kind);
    EXPECT_GT(steps_tight, steps_loose) << solver_kind_name(c.kind);
    if (c.kind != SolverKind::RK2) {
      EXPECT_LT(errs.back(), 1e-8) << solver_kind_name(c.kind);
    }
  }
}

TEST(Integrators, AdaptiveStepsFollowTheOrbit) {
  // On an eccentric orbit the controller must take small steps at pericentre and large ones at
  // apocentre: with Kepler's second law the speed ratio is (1+e)/(1−e) = 3 for e = 0.5.
  Kepler f;
  double y[4];
  Kepler::initial(0.5, y);
  SolverConfig cfg;
  cfg.kind = SolverKind::DormandPrince54;
  cfg.eps_abs = 1e-10;
  cfg.lambda_max = kTwoPi;
  double h_peri = 1e300, h_apo = 0;
  auto cb = [&](const StepView& s) {
    const double r = std::hypot(s.y0[0], s.y0[1]);
    const double h = s.lambda1 - s.lambda0;
    if (r < 0.6) h_peri = std::min(h_peri, h);
    if (r > 1.4) h_apo = std::max(h_apo, h);
    return StepAction::Continue;
  };
  integrate_ode(f, cfg, y, 0.0, cb);
  EXPECT_GT(h_apo, 3 * h_peri);
}

TEST(Integrators, StopsExactlyAtLambdaMaxBackwards) {
  Oscillator f;
  double y[2] = {1.0, 0.0};
  SolverConfig cfg;
  cfg.kind = SolverKind::DormandPrince853;
  cfg.eps_abs = 1e-12;
  cfg.direction = -1;
  cfg.lambda_max = 2.5;
  double last = 0;
  int calls = 0;
  auto cb = [&](const StepView& s) {
    EXPECT_LT(s.lambda1, s.lambda0);  // backwards
    EXPECT_EQ(s.step_index, ++calls);
    last = s.lambda1;
    return StepAction::Continue;
  };
  const GeodesicResult r = integrate_ode(f, cfg, y, 1.0, cb);
  EXPECT_EQ(r.reason, StopReason::LambdaMax);
  EXPECT_EQ(r.lambda, 1.0 - 2.5);
  EXPECT_EQ(last, r.lambda);
  EXPECT_EQ(r.steps, calls);
  // x(t) = cos(t − 1) from x(1) = 1.
  EXPECT_NEAR(y[0], std::cos(-2.5), 1e-10);
  EXPECT_NEAR(y[1], -std::sin(-2.5), 1e-10);
}

TEST(Integrators, StepViewCarriesStatesAndDerivatives) {
  Oscillator f;
  double y[2] = {1.0, 0.0};
  SolverConfig cfg;
  cfg.kind = SolverKind::CashKarp45;
  cfg.eps_abs = 1e-10;
  cfg.lambda_max = 3;
  double prev_end[2] = {1.0, 0.0};
  auto cb = [&](const StepView& s) {
    EXPECT_EQ(s.dim, 2);
    EXPECT_EQ(s.y0[0], prev_end[0]);  // steps are contiguous
    EXPECT_EQ(s.y0[1], prev_end[1]);
    double d[2];
    f(s.y0, d);
    EXPECT_EQ(s.dy0[0], d[0]);
    EXPECT_EQ(s.dy0[1], d[1]);
    f(s.y1, d);
    EXPECT_EQ(s.dy1[0], d[0]);
    EXPECT_EQ(s.dy1[1], d[1]);
    EXPECT_NEAR(s.y1[0], std::cos(s.lambda1), 1e-8);
    prev_end[0] = s.y1[0];
    prev_end[1] = s.y1[1];
    return StepAction::Continue;
  };
  integrate_ode(f, cfg, y, 0.0, cb);
}

TEST(Integrators, MaxStepsCallbackAndCounters) {
  for (const SolverKind kind : general_solver_kinds()) {
    Oscillator f;
    double y[2] = {1.0, 0.0};
    SolverConfig cfg;
    cfg.kind = kind;
    cfg.eps_abs = 1e-9;
    cfg.max_steps = 7;
    GeodesicResult r = integrate_ode(f, cfg, y, 0.0);
    EXPECT_EQ(r.reason, StopReason::MaxSteps) << solver_kind_name(kind);
    EXPECT_EQ(r.steps, 7);
    EXPECT_GT(r.rhs_evals, 7);
    double y2[2] = {1.0, 0.0};
    cfg.max_steps = 100;
    int n = 0;
    auto stop_at_3 = [&](const StepView&) { return ++n == 3 ? StepAction::Stop : StepAction::Continue; };
    r = integrate_ode(f, cfg, y2, 0.0, stop_at_3);
    EXPECT_EQ(r.reason, StopReason::Callback);
    EXPECT_EQ(r.steps, 3);
  }
}

TEST(Integrators, FsalSavesOneEvaluationPerStep) {
  // Dormand-Prince 5(4) needs 6 new evaluations per accepted step (7 stages, the last reused),
  // Cash-Karp 6 + 1 for f at the new point, DOP853 11 + 1 (HNW I §II.5, §II.10).
  Oscillator f;
  SolverConfig cfg;
  cfg.step_ctrl = false;
  cfg.step_size = 0.01;
  cfg.max_steps = 10;
  const std::vector<std::pair<SolverKind, int>> per_step = {{SolverKind::DormandPrince54, 6},
                                                            {SolverKind::CashKarp45, 6},
                                                            {SolverKind::DormandPrince853, 12},
                                                            {SolverKind::RK4, 4},
                                                            {SolverKind::RK2, 2}};
  for (auto [kind, evals] : per_step) {
    double y[2] = {1.0, 0.0};
    cfg.kind = kind;
    const GeodesicResult r = integrate_ode(f, cfg, y, 0.0);
    EXPECT_EQ(r.rhs_evals, 1 + 10L * evals) << solver_kind_name(kind);
  }
}

TEST(Integrators, BlowUpStopsBeforeTheSingularity) {
  // y = 1/(1−t) is finite only for t < 1: the adaptive control must creep up to t = 1 and stop
  // (underflow or non-finite), never jump across the pole onto the other branch.
  for (const SolverKind kind : general_solver_kinds()) {
    if (kind == SolverKind::RK4) continue;  // fixed step
    BlowUp f;
    double y[1] = {1.0};
    SolverConfig cfg;
    cfg.kind = kind;
    cfg.eps_rel = 1e-6;
    cfg.eps_abs = 0;
    cfg.max_steps = 1000000;
    double rel_err_at_09 = -1;
    auto cb = [&](const StepView& s) {
      if (rel_err_at_09 < 0 && s.lambda1 >= 0.9) rel_err_at_09 = std::fabs(s.y1[0] * (1.0 - s.lambda1) - 1.0);
      return StepAction::Continue;
    };
    const GeodesicResult r = integrate_ode(f, cfg, y, 0.0, cb);
    EXPECT_TRUE(r.reason == StopReason::StepUnderflow || r.reason == StopReason::NotFinite)
        << solver_kind_name(kind) << ": " << stop_reason_name(r.reason);
    // The numerical pole sits at 1 + O(tolerance); the state must still be on the positive branch.
    EXPECT_NEAR(r.lambda, 1.0, 1e-4) << solver_kind_name(kind);
    EXPECT_GT(y[0], 1e3) << solver_kind_name(kind);
    EXPECT_LT(rel_err_at_09, 1e-3) << solver_kind_name(kind);
  }
}

TEST(Integrators, BadConfigurationIsAClearError) {
  Oscillator f;
  double y[2] = {1.0, 0.0};
  SolverConfig cfg;
  cfg.eps_abs = 0;
  cfg.eps_rel = 0;
  try {
    integrate_ode(f, cfg, y, 0.0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("eps_abs"), std::string::npos) << e.what();
  }
  cfg.eps_abs = 1e-8;
  cfg.step_size = -1;
  EXPECT_THROW(integrate_ode(f, cfg, y, 0.0), Error);
}

TEST(Integrators, SolverNamesMapOntoKinds) {
  EXPECT_EQ(solver_kind_from_name("GSL_RK_Cash-Karp"), SolverKind::CashKarp45);
  EXPECT_EQ(solver_kind_from_name("GSL: Embedded 4th order Runge-Kutta Cash-Karp"), SolverKind::CashKarp45);
  EXPECT_EQ(solver_kind_from_name("gsl_rk_fehlberg"), SolverKind::Fehlberg45);
  EXPECT_EQ(solver_kind_from_name("RK4"), SolverKind::RK4);
  EXPECT_EQ(solver_kind_from_name("BS"), SolverKind::BulirschStoer);
  EXPECT_EQ(solver_kind_from_name("GSL_RK2"), SolverKind::RK2);
  EXPECT_EQ(solver_kind_from_name("DP54"), SolverKind::DormandPrince54);
  EXPECT_EQ(solver_kind_from_name("DOP853"), SolverKind::DormandPrince853);
  EXPECT_EQ(solver_kind_from_name("GSL_RK_Prince-Dormand"), SolverKind::DormandPrince853);
  // Every kind is reachable by its own name.
  for (const SolverType* t : SolverRegistry::instance().entries()) {
    const SolverKind kind = t->kind;
    EXPECT_EQ(solver_kind_from_name(solver_kind_name(kind)), kind);
  }
  try {
    solver_kind_from_name("GSL_RK_Cash-Krap");
    FAIL();
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("did you mean \"GSL_RK_Cash-Karp\""), std::string::npos) << msg;
    EXPECT_NE(msg.find("DP853"), std::string::npos) << msg;  // lists the valid names
  }
}

TEST(Integrators, NoHeapAllocationWhileIntegrating) {
  // Kepler also has the form y'' = f(y): every registered integrator, Nyström ones included.
  for (const SolverType* t : SolverRegistry::instance().entries()) {
    const SolverKind kind = t->kind;
    Kepler f;
    double y[4];
    Kepler::initial(0.5, y);
    SolverConfig cfg;
    cfg.kind = kind;
    cfg.eps_abs = 1e-9;
    cfg.lambda_max = kTwoPi;
    cfg.max_steps = 1000000;
    double sum = 0;
    auto cb = [&](const StepView& s) {
      sum += s.y1[0];
      return StepAction::Continue;
    };
    const long before = g_allocations.load();
    const GeodesicResult r = integrate_ode(f, cfg, y, 0.0, cb);
    EXPECT_EQ(g_allocations.load(), before) << solver_kind_name(cfg.kind);
    EXPECT_EQ(r.reason, StopReason::LambdaMax);
    EXPECT_TRUE(std::isfinite(sum));
  }
}

// The packet integrator (geodesic_packet.h) allocates nothing either: 20 light rays through
// packets with refills, on Schwarzschild (SIMD right-hand side) and KastorTraschen (lane by lane).
TEST(Integrators, NoHeapAllocationWhileIntegratingPackets) {
  for (const char* name : {"Schwarzschild", "KastorTraschen"}) {
    const auto m = make_metric(name);
    const Vec4 x = m->info().sample_pos;
    const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
    SolverConfig cfg;
    cfg.separable = false;
    cfg.max_steps = 300;
    cfg.escape_radius = 40.0;
    int started = 0, finished = 0;
    long steps = 0;
    auto next = [&](int, double* y) {
      if (started == 20) return false;
      const double a = 0.3 * started++;
      const Vec4 k = local_null_direction(e, Vec3{std::cos(a), std::sin(a), 0.2});
      for (int i = 0; i < 4; ++i) y[i] = x[i], y[4 + i] = k[i];
      return true;
    };
    auto on_step = [&](int, const StepView&) {
      ++steps;
      return StepAction::Continue;
    };
    auto done = [&](int, const double*, const GeodesicResult&) { ++finished; };
    const long before = g_allocations.load();
    m->integrate_packet(cfg, PacketRays{next, on_step, done, {}});
    EXPECT_EQ(g_allocations.load(), before) << name;
    EXPECT_EQ(finished, 20) << name;
    EXPECT_GT(steps, 20) << name;
  }
}

// diagonal_geodesic_constraint (geodesic_constraint.h, the packet's constraint on MorrisThorne and
// KastorTraschen) leaves out the terms of the off-diagonal zeros: value and scale must have the bits
// of geodesic_constraint on the full matrix with abs_quadratic_form, on the diagonals of real metrics
// (where the slicing observer exists) and inside Schwarzschild's horizon (g_tt > 0: the fallback
// Σ|g_ij k^i k^j|), for momenta with zero, −0 and mixed-sign components and for both targets.
TEST(Integrators, DiagonalConstraintHasTheBitsOfTheFullOne) {
  auto bits_equal = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  std::vector<Mat4> gs;
  const std::vector<std::pair<const char*, Vec4>> events = {
      {"MorrisThorne", Vec4{{0, 3.0, 1.1, 0.4}}},  {"MorrisThorne", Vec4{{0, -0.2, 0.05, 2.0}}},
      {"KastorTraschen", Vec4{{-20, 40, 0.5, 0}}}, {"KastorTraschen", Vec4{{3, 0.1, 0.0, 0.9}}},
      {"Schwarzschild", Vec4{{0, 5.0, 1.0, 0}}},   {"Schwarzschild", Vec4{{0, 1.5, 0.3, 0}}}};
  for (const auto& [name, x] : events) {
    Mat4 g;
    make_metric(name)->metric_tensor(x, g);
    gs.push_back(g);
  }
  int compared = 0, fallbacks = 0;
  for (const Mat4& g : gs) {
    const double d[4] = {g[0][0], g[1][1], g[2][2], g[3][3]};
    for (int i = 0; i < 64; ++i) {
      const Vec4 k{
          {i % 4 == 0 ? 0.0 : std::sin(1.3 * i), -std::cos(0.7 * i) * 1e3, 1e-5 * i, i % 3 == 0 ? -0.0 : 0.25 * i}};
      for (double target : {0.0, -1.0}) {
        double v_full, s_full, v_diag, s_diag;
        geodesic_constraint(
            g, k, target, [&] { return abs_quadratic_form(g, k); }, v_full, s_full);
        diagonal_geodesic_constraint(d, k, target, v_diag, s_diag);
        EXPECT_TRUE(bits_equal(v_diag, v_full)) << i << " " << v_diag << " " << v_full;
        EXPECT_TRUE(bits_equal(s_diag, s_full)) << i << " " << s_diag << " " << s_full;
        ++compared;
        if (!(d[0] < 0.0)) ++fallbacks;
      }
    }
  }
  EXPECT_EQ(compared, 6 * 64 * 2);
  EXPECT_GT(fallbacks, 0);  // the horizon's inside reaches the fallback
}
