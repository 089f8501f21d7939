// Geodesic integration throughput: a fixed bundle of null geodesics — a 64×64 pinhole fan (fov 40°)
// from an observer at r = 30, θ = π/2 looking at the hole, traced backwards in time at eps_abs =
// 1e-8 until capture (r < 1.05 r_+, inside the innermost photon orbit, so the ray cannot return) or
// escape (r > 50) — in Schwarzschild (M = 1) and Kerr (Boyer-Lindquist, M = 1, a = 0.9), for each
// adaptive integrator; and the same bundle through GSL's gsl_odeiv2 Cash-Karp driver
// (gsl_odeiv2_step_rkck + gsl_odeiv2_control_y_new, one evolve_apply per accepted step, the RHS
// through the virtual Metric::christoffel and the full Γ^μ_{ab} k^a k^b contraction, as
// GeoViS/Motion4D does), with the same constraint test after every step, as the reference.
//
//   cmake --build build --target geovis_bench && ./build/bench/geovis_bench
//
// Counters: geodesics/s (rate), steps/geodesic (accepted), evals/geodesic (RHS evaluations) and
// captured (fraction of the bundle that fell in — the same for every integrator if they agree).
#include <benchmark/benchmark.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "spacetime/integrators.h"
#include "spacetime/metric_registry.h"

namespace {

using namespace geovis;

constexpr int kRes = 64;
constexpr double kFovDeg = 40.0;
constexpr double kObserverR = 30.0;
constexpr double kEscapeR = 50.0;
constexpr double kEpsAbs = 1e-8;
constexpr double kPi = 3.141592653589793238462643383280;

struct Scene {
  std::unique_ptr<Metric> metric;
  double capture_r = 0;
  std::vector<std::array<double, 8>> rays;  ///< initial states
};

/// Outer horizon r_+ = M + sqrt(M² − a²) (M = 1).
Scene make_scene(const std::string& name, double a) {
  Scene s;
  s.metric = a != 0 ? make_metric(name, {{"angmom", a}}) : make_metric(name);
  s.capture_r = 1.05 * (1.0 + std::sqrt(1.0 - a * a));
  const Vec4 x{{0, kObserverR, kPi / 2, 0}};
  const Tetrad e = s.metric->natural_tetrad(x, TetradKind::Default);
  // Local frame: e(1) = ∂_r, e(2) = ∂_θ (towards −z), e(3) = ∂_φ. Look along −e(1), up = −e(2).
  const double t = std::tan(0.5 * kFovDeg * kPi / 180.0);
  for (int j = 0; j < kRes; ++j)
    for (int i = 0; i < kRes; ++i) {
      const double u = (2.0 * (i + 0.5) / kRes - 1.0) * t, v = (1.0 - 2.0 * (j + 0.5) / kRes) * t;
      const Vec3 d{-1.0, -v, u};
      const Vec4 k = local_null_direction(e, d, /*past_directed=*/true);
      s.rays.push_back({x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]});
    }
  return s;
}

const Scene& scene(int which) {
  static const Scene schw = make_scene("Schwarzschild", 0.0);
  static const Scene kerr = make_scene("KerrBL", 0.9);
  return which == 0 ? schw : kerr;
}

SolverConfig bundle_config(const Scene& s, SolverKind kind) {
  SolverConfig cfg;
  cfg.kind = kind;
  cfg.eps_abs = kEpsAbs;
  cfg.eps_rel = 0;
  cfg.step_size = 0.01;  // GeoViS default initial step
  cfg.max_steps = 1000000;
  cfg.box_ll = Vec4{{-1e300, s.capture_r, -1e300, -1e300}};
  cfg.box_ur = Vec4{{1e300, kEscapeR, 1e300, 1e300}};
  return cfg;
}

void report(benchmark::State& state, long rays, long steps, long evals, long captured, long rejected = -1) {
  state.counters["geodesics/s"] = benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
  state.counters["steps/geodesic"] = static_cast<double>(steps) / rays;
  state.counters["evals/geodesic"] = static_cast<double>(evals) / rays;
  state.counters["captured"] = static_cast<double>(captured) / rays;
  if (rejected >= 0) state.counters["rejected/geodesic"] = static_cast<double>(rejected) / rays;
}

/// Our configuration from the benchmark arguments (metric, SolverKind, separable, n): eps_abs =
/// 10^−n for n > 0, else the bundle's 1e-8.
SolverConfig ours_config(const Scene& s, const benchmark::State& state) {
  SolverConfig cfg = bundle_config(s, static_cast<SolverKind>(state.range(1)));
  cfg.separable = state.range(2) != 0;
  if (state.range(3) > 0) cfg.eps_abs = std::pow(10.0, -static_cast<double>(state.range(3)));
  return cfg;
}

std::string ours_label(const benchmark::State& state, const SolverConfig& cfg) {
  return std::string(state.range(0) == 0 ? "Schwarzschild " : "KerrBL a=0.9 ") + solver_kind_name(cfg.kind) +
         (cfg.separable ? " Mino" : " coordinates") +
         (state.range(3) > 0 ? " eps 1e-" + std::to_string(state.range(3)) : "");
}

void BM_Ours(benchmark::State& state) {
  const Scene& s = scene(static_cast<int>(state.range(0)));
  const SolverConfig cfg = ours_config(s, state);
  long rays = 0, steps = 0, evals = 0, captured = 0, rejected = 0;
  for (auto _ : state) {
    for (const auto& r0 : s.rays) {
      double y[8];
      for (int i = 0; i < 8; ++i) y[i] = r0[i];
      const GeodesicResult r = s.metric->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
      ++rays;
      steps += r.steps;
      rejected += r.rejected;
      evals += r.rhs_evals;
      captured += y[1] < s.capture_r;
      benchmark::DoNotOptimize(y);
    }
  }
  report(state, rays, steps, evals, captured, rejected);
  state.SetLabel(ours_label(state, cfg));
}

// ---- GSL reference (GeoViS/Motion4D style) --------------------------------------------------------

struct GslContext {
  const Metric* metric;
  long evals = 0;
};

/// Motion4D's calcDerivs: Christoffel symbols through the virtual interface, then the full
/// contraction over all index pairs.
int gsl_rhs(double /*t*/, const double y[], double dydt[], void* params) {
  auto* ctx = static_cast<GslContext*>(params);
  ++ctx->evals;
  const Vec4 x{{y[0], y[1], y[2], y[3]}};
  Christoffel G;
  ctx->metric->christoffel(x, G);
  for (int mu = 0; mu < 4; ++mu) {
    dydt[mu] = y[4 + mu];
    double s = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) s += G.G[mu][a][b] * y[4 + a] * y[4 + b];
    dydt[4 + mu] = -s;
  }
  return GSL_SUCCESS;
}

/// GSL's Cash–Karp driver as GeoViS uses it, for one scene.
struct GslTracer {
  const Scene& s;
  GslContext ctx;
  gsl_odeiv2_system sys;
  gsl_odeiv2_step* step;
  gsl_odeiv2_control* control;
  gsl_odeiv2_evolve* evolve;
  explicit GslTracer(const Scene& sc)
      : s(sc),
        ctx{sc.metric.get()},
        sys{gsl_rhs, nullptr, 8, &ctx},
        step(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rkck, 8)),
        control(gsl_odeiv2_control_y_new(kEpsAbs, 0.0)),
        evolve(gsl_odeiv2_evolve_alloc(8)) {}
  ~GslTracer() {
    gsl_odeiv2_evolve_free(evolve);
    gsl_odeiv2_control_free(control);
    gsl_odeiv2_step_free(step);
  }
  /// Integrates y until the validity test, the box, the constraint or λ = lambda_end (GSL clips
  /// its last step there); returns the accepted steps.
  long trace(const SolverConfig& cfg, double* y, double lambda_end) {
    gsl_odeiv2_step_reset(step);
    gsl_odeiv2_evolve_reset(evolve);
    double lambda = 0, h = cfg.step_size;
    long steps = 0;
    for (int n = 0; n < cfg.max_steps && lambda < lambda_end; ++n) {
      const Vec4 x{{y[0], y[1], y[2], y[3]}};
      if (!s.metric->is_valid(x)) break;  // Motion4D breakCondition before each step
      if (gsl_odeiv2_evolve_apply(evolve, control, step, &sys, &lambda, lambda_end, &h, y) != GSL_SUCCESS) break;
      ++steps;
      if (y[1] < cfg.box_ll[1] || y[1] > cfg.box_ur[1]) break;  // bounding box
      // Constraint test after every step (Motion4D testConstraint), relative as ours.
      Mat4 g;
      s.metric->metric_tensor(Vec4{{y[0], y[1], y[2], y[3]}}, g);
      double c = 0, sc = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const double t = g[a][b] * y[4 + a] * y[4 + b];
          c += t;
          sc += std::fabs(t);
        }
      if (std::fabs(c) > cfg.constraint_tol * sc) break;
    }
    return steps;
  }
};

void BM_GslCashKarp(benchmark::State& state) {
  const Scene& s = scene(static_cast<int>(state.range(0)));
  const SolverConfig cfg = bundle_config(s, SolverKind::CashKarp45);
  GslTracer gsl(s);
  long rays = 0, steps = 0, captured = 0;
  for (auto _ : state) {
    for (const auto& r0 : s.rays) {
      double y[8];
      for (int i = 0; i < 8; ++i) y[i] = r0[i];
      steps += gsl.trace(cfg, y, 1e300);
      ++rays;
      captured += y[1] < s.capture_r;
      benchmark::DoNotOptimize(y);
    }
  }
  report(state, rays, steps, gsl.ctx.evals, captured);
  state.SetLabel(std::string(state.range(0) == 0 ? "Schwarzschild " : "KerrBL a=0.9 ") + "GSL rkck (reference)");
}

// ---- speed-up against GSL, measured back to back ------------------------------------------------------

/// CPU time of this thread.
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The shared machine's speed drifts by ±20 % over minutes, so separately timed benchmarks give
/// unreliable ratios. Here every iteration integrates the bundle once with GSL and once with ours,
/// back to back, and the counter x_gsl = Σ t_GSL / Σ t_ours is the speed-up. Args: metric, our
/// SolverKind, separable, n > 0: our eps_abs = 10^−n (GSL stays at 1e-8).
void BM_VersusGsl(benchmark::State& state) {
  const Scene& s = scene(static_cast<int>(state.range(0)));
  const SolverConfig cfg = ours_config(s, state);
  const SolverConfig gcfg = bundle_config(s, SolverKind::CashKarp45);
  GslTracer gsl(s);
  double t_gsl = 0, t_ours = 0;
  for (auto _ : state) {
    double t0 = thread_cpu_seconds();
    for (const auto& r0 : s.rays) {
      double y[8];
      for (int i = 0; i < 8; ++i) y[i] = r0[i];
      gsl.trace(gcfg, y, 1e300);
      benchmark::DoNotOptimize(y);
    }
    double t1 = thread_cpu_seconds();
    t_gsl += t1 - t0;
    for (const auto& r0 : s.rays) {
      double y[8];
      for (int i = 0; i < 8; ++i) y[i] = r0[i];
      s.metric->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
      benchmark::DoNotOptimize(y);
    }
    t_ours += thread_cpu_seconds() - t1;
  }
  const double n = static_cast<double>(state.iterations() * static_cast<long>(s.rays.size()));
  state.counters["x_gsl"] = t_gsl / t_ours;
  state.counters["gsl_geod/s"] = n / t_gsl;
  state.counters["ours_geod/s"] = n / t_ours;
  state.SetLabel(ours_label(state, cfg));
}

// ---- accuracy at equal tolerance -------------------------------------------------------------------

/// Equal tolerance is only a fair comparison if it buys equal accuracy. Every ray of the bundle is
/// integrated to λ = kAccuracyLambda (no escape radius; captured rays are left out) by the method
/// under test at eps_abs = 1e-8, and by DOP853 in the coordinate form at 1e-13 as the reference
/// (its distance to DOP853 in the Mino form at 1e-13, a different set of equations, is reported as
/// "ref_spread"). Counters: the median and the largest distance of the end event from the
/// reference, |Δ(x, y, z)| (pseudo-Cartesian) and |Δt|. Method: 0 GSL rkck, 1 ours coordinates,
/// 2 ours Mino; range(2) = our SolverKind; range(3) = n > 0: our eps_abs = 10^−n instead of 1e-8.
constexpr double kAccuracyLambda = 40.0;

Vec3 cartesian(const double* y) {
  const double r = y[1], st = std::sin(y[2]), ct = std::cos(y[2]);
  return {r * st * std::cos(y[3]), r * st * std::sin(y[3]), r * ct};
}

void BM_Accuracy(benchmark::State& state) {
  const Scene& s = scene(static_cast<int>(state.range(0)));
  const int method = static_cast<int>(state.range(1));
  const auto kind = static_cast<SolverKind>(state.range(2));
  SolverConfig cfg = bundle_config(s, method == 0 ? SolverKind::CashKarp45 : kind);
  cfg.eps_abs = state.range(3) > 0 ? std::pow(10.0, -static_cast<double>(state.range(3))) : kEpsAbs;
  cfg.box_ur = Vec4{{1e300, 1e300, 1e300, 1e300}};
  cfg.lambda_max = kAccuracyLambda;
  cfg.separable = method == 2;
  SolverConfig ref = bundle_config(s, SolverKind::DormandPrince853);
  ref.eps_abs = 1e-13;
  ref.box_ur = cfg.box_ur;
  ref.lambda_max = kAccuracyLambda;
  GslTracer gsl(s);
  std::vector<double> dx, dt;
  double spread = 0;
  for (auto _ : state) {
    dx.clear();
    dt.clear();
    for (const auto& r0 : s.rays) {
      double y[8], yr[8], ym[8];
      for (int i = 0; i < 8; ++i) y[i] = yr[i] = ym[i] = r0[i];
      ref.separable = false;
      if (s.metric->integrate(ref, GeodesicSystem::Geodesic, yr, 0.0, {}).reason != StopReason::LambdaMax) continue;
      ref.separable = true;
      s.metric->integrate(ref, GeodesicSystem::Geodesic, ym, 0.0, {});
      spread = std::max(spread, norm(cartesian(ym) - cartesian(yr)));
      if (method == 0) {
        gsl.trace(cfg, y, kAccuracyLambda);
      } else {
        s.metric->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
      }
      dx.push_back(norm(cartesian(y) - cartesian(yr)));
      dt.push_back(std::fabs(y[0] - yr[0]));
    }
  }
  auto quantile = [](std::vector<double> v, double q) {
    const auto i = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + i, v.end());
    return v[static_cast<std::size_t>(i)];
  };
  state.counters["rays"] = static_cast<double>(dx.size());
  state.counters["dx_median"] = quantile(dx, 0.5);
  state.counters["dx_p90"] = quantile(dx, 0.9);
  state.counters["dx_p99"] = quantile(dx, 0.99);
  state.counters["dx_max"] = quantile(dx, 1.0);
  state.counters["dt_median"] = quantile(dt, 0.5);
  state.counters["dt_max"] = quantile(dt, 1.0);
  state.counters["ref_spread"] = spread;
  state.SetLabel(
      std::string(state.range(0) == 0 ? "Schwarzschild " : "KerrBL a=0.9 ") +
      (method == 0 ? "GSL rkck" : std::string(solver_kind_name(kind)) + (method == 2 ? " Mino" : " coordinates")));
}

void ours_args(benchmark::internal::Benchmark* b) {
  for (int separable : {1, 0})
    for (int m = 0; m < 2; ++m) {
      if (separable) b->Args({m, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 0});
      for (SolverKind k : {SolverKind::CashKarp45, SolverKind::Fehlberg45, SolverKind::DormandPrince54,
                           SolverKind::DormandPrince853, SolverKind::BulirschStoer})
        b->Args({m, static_cast<int>(k), separable, 0});
    }
}

void accuracy_args(benchmark::internal::Benchmark* b) {
  for (int m = 0; m < 2; ++m) {
    b->Args({m, 0, 0, 0});
    for (int method : {1, 2})
      for (SolverKind k : {SolverKind::CashKarp45, SolverKind::DormandPrince853})
        b->Args({m, method, static_cast<int>(k), 0});
    for (int n : {0, 6, 7, 9, 10}) b->Args({m, 2, static_cast<int>(SolverKind::RungeKuttaNystrom86), n});
    for (int n : {9, 10}) b->Args({m, 2, static_cast<int>(SolverKind::DormandPrince853), n});
  }
}

BENCHMARK(BM_GslCashKarp)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ours)->Apply(ours_args)->Unit(benchmark::kMillisecond);
// The 2nd-order pair needs ~1000× more steps at 1e-8 (tens of seconds per bundle): one pass only.
BENCHMARK(BM_Ours)
    ->Args({0, static_cast<int>(SolverKind::RK2), 1, 0})
    ->Args({1, static_cast<int>(SolverKind::RK2), 1, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
// Equal accuracy instead of equal tolerance (see BM_Accuracy): RKN86 in Mino time at looser
// tolerances, whose errors stay below GSL's at 1e-8 in every quantile.
BENCHMARK(BM_Ours)
    ->Args({0, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 6})
    ->Args({0, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 7})
    ->Args({1, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 6})
    ->Args({1, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 7})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VersusGsl)
    ->ArgsProduct({{0, 1},
                   {static_cast<int>(SolverKind::CashKarp45), static_cast<int>(SolverKind::DormandPrince853)},
                   {0, 1},
                   {0}})
    ->Args({0, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 0})
    ->Args({1, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 0})
    ->Args({0, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 6})
    ->Args({1, static_cast<int>(SolverKind::RungeKuttaNystrom86), 1, 6})
    ->MinTime(3.0)
    ->Unit(benchmark::kMillisecond);
// Accuracy, not speed: one pass each.
BENCHMARK(BM_Accuracy)->Apply(accuracy_args)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
