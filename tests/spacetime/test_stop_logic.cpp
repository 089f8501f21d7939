// Stop logic of the geodesic integration (integrators.h, integrate_with and MetricSystem):
//  * rays falling towards a horizon where the chart is singular stop promptly with the horizon
//    reason at the metric's break margin (Metric::horizon_eps, Motion4D's breakCondition eps),
//    instead of creeping towards r_s while k^t diverges and burning the step budget;
//  * the constraint test measures g(k,k) relative to a positive-definite size of k, so that rays
//    in charts with large/cancelling off-diagonal terms (ingoing Eddington–Finkelstein across the
//    horizon) are not stopped, while a genuinely non-null k is.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "spacetime/metric_registry.h"

using namespace geovis;

namespace {

constexpr double kPi = 3.141592653589793238462643383280;

const SolverKind kAdaptive[] = {SolverKind::CashKarp45, SolverKind::Fehlberg45, SolverKind::DormandPrince54,
                                SolverKind::DormandPrince853, SolverKind::BulirschStoer};

/// Backward-traced (past-directed) light ray from x in local direction d of the default tetrad,
/// as the renderer starts its rays.
GeodesicResult trace_back(const Metric& m, const Vec4& x, const Vec3& d, SolverKind kind, double eps,
                          double* y_out = nullptr) {
  const Vec4 k = local_null_direction(m.natural_tetrad(x), d, /*past_directed=*/true);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg;
  cfg.kind = kind;
  cfg.eps_abs = eps;
  cfg.max_steps = 100000;
  const GeodesicResult r = m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
  if (y_out)
    for (int i = 0; i < 8; ++i) y_out[i] = y[i];
  return r;
}

}  // namespace

TEST(StopLogic, HorizonStopsCapturedRayPromptly) {
  // Impact parameter 0.9·3√3 M from r = 30: captured. Local direction from the static observer:
  // sin α = (b/r) sqrt(1 − r_s/r) off the inward radial direction.
  auto m = make_metric("Schwarzschild");
  const double r0 = 30, b = 0.9 * 3 * std::sqrt(3.0);
  const double sa = b / r0 * std::sqrt(1 - 2 / r0);
  const Vec4 x{{0, r0, kPi / 2, 0}};
  const double r_break = 2.0 * (1.0 + m->horizon_eps());
  for (SolverKind kind : kAdaptive)
    for (double eps : {1e-4, 1e-8}) {
      double y[8];
      const GeodesicResult r = trace_back(*m, x, Vec3{-std::sqrt(1 - sa * sa), 0, sa}, kind, eps, y);
      const std::string what = std::string(solver_kind_name(kind)) + " eps " + std::to_string(eps);
      EXPECT_EQ(r.reason, StopReason::Invalid) << what << ": " << stop_reason_name(r.reason);
      EXPECT_LT(r.steps, 500) << what;  // was 100000 (max-steps) at eps 1e-8
      EXPECT_GT(y[1], r_break) << what;
      EXPECT_LT(y[1], r_break * (1 + 1e-4)) << what;
      EXPECT_LT(y[0], -50.0) << what;  // t → −∞ backwards in time
    }
}

TEST(StopLogic, EveryHorizonMetricStopsAFallingRayPromptly) {
  struct Case {
    const char* name;
    std::vector<std::pair<std::string, double>> params;
    Vec4 x;
    Vec3 d;  ///< local direction of the default tetrad
  };
  const Case cases[] = {
      {"Schwarzschild", {}, Vec4{{0, 10, 1.1, 0.3}}, Vec3{-1, 0, 0}},
      {"SchwarzschildCart", {}, Vec4{{0, 6, 5, 3}}, Vec3{-6, -5, -3}},
      {"SchwarzschildIsotropic", {}, Vec4{{0, 6, 5, 3}}, Vec3{-6, -5, -3}},
      {"KerrBL", {{"angmom", 0.9}}, Vec4{{0, 10, 1.1, 0.3}}, Vec3{-1, 0, 0.2}},
      {"ReissnerNordstrom", {{"charge", 0.6}}, Vec4{{0, 10, 1.1, 0.3}}, Vec3{-1, 0.1, 0}},
      {"Kottler", {}, Vec4{{0, 4, 1.1, 0.3}}, Vec3{-1, 0, 0.1}},
      {"TaubNUT", {}, Vec4{{0, 10, 1.1, 0.3}}, Vec3{-1, 0, 0}},
      {"Ernst", {}, Vec4{{0, 6, 1.1, 0.3}}, Vec3{-1, 0, 0}},
  };
  for (const Case& c : cases) {
    auto m = make_metric(c.name, c.params);
    for (SolverKind kind : {SolverKind::CashKarp45, SolverKind::DormandPrince853})
      for (double eps : {1e-4, 1e-8}) {
        const GeodesicResult r = trace_back(*m, c.x, c.d, kind, eps);
        const std::string what = std::string(c.name) + " " + solver_kind_name(kind) + " eps " + std::to_string(eps);
        EXPECT_EQ(r.reason, StopReason::Invalid) << what << ": " << stop_reason_name(r.reason);
        EXPECT_LT(r.steps, 500) << what;
      }
  }
}

TEST(StopLogic, HorizonEpsIsAMetricSetting) {
  auto m = make_metric("Schwarzschild");
  EXPECT_EQ(m->horizon_eps(), Metric::kDefaultHorizonEps);
  EXPECT_FALSE(m->is_valid(Vec4{{0, 2.0 * (1 + 0.5 * Metric::kDefaultHorizonEps), 1, 0}}));
  EXPECT_TRUE(m->is_valid(Vec4{{0, 2.0 * (1 + 2.0 * Metric::kDefaultHorizonEps), 1, 0}}));
  m->set_horizon_eps(1e-2);
  EXPECT_FALSE(m->is_valid(Vec4{{0, 2.019, 1, 0}}));
  EXPECT_TRUE(m->is_valid(Vec4{{0, 2.021, 1, 0}}));
  EXPECT_FALSE(m->clone()->is_valid(Vec4{{0, 2.019, 1, 0}}));  // copies keep it
  m->set_param("mass", 2.0);                                    // and parameter changes too
  EXPECT_FALSE(m->is_valid(Vec4{{0, 4.039, 1, 0}}));
  EXPECT_TRUE(m->is_valid(Vec4{{0, 4.041, 1, 0}}));
  EXPECT_THROW(m->set_horizon_eps(0.0), Error);
  EXPECT_THROW(m->set_horizon_eps(0.5), Error);
  EXPECT_EQ(m->horizon_eps(), 1e-2);
  // Isotropic chart: the same margin in 1 − r_s/r = ((ρ − ρ_s)/(ρ + ρ_s))², ρ_s = M/2.
  auto iso = make_metric("SchwarzschildIsotropic");
  iso->set_horizon_eps(1e-2);  // √eps = 0.1: ρ_break = 0.5·1.1/0.9
  const double rho_b = 0.5 * 1.1 / 0.9;
  EXPECT_FALSE(iso->is_valid(Vec4{{0, rho_b * (1 - 1e-9), 0, 0}}));
  EXPECT_TRUE(iso->is_valid(Vec4{{0, rho_b * (1 + 1e-9), 0, 0}}));
}

TEST(StopLogic, EddFinkInRayCrossesTheHorizonWithoutConstraintStop) {
  // Nearly radial ingoing light ray (future-directed): k^v is tiny and g_rr = 0, so every term
  // g_μν k^μ k^ν is tiny compared with k itself; a constraint test relative to those terms
  // stopped it at the first round-off.
  auto m = make_metric("EddFinkIn");
  const Vec4 x{{0, 10, 1.1, 0.3}};
  for (double ang : {1e-6, 1e-4, 1e-2})
    for (SolverKind kind : kAdaptive)
      for (double eps : {1e-4, 1e-8}) {
        const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Static), Vec3{-1, 0, ang}, false);
        double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
        SolverConfig cfg;
        cfg.kind = kind;
        cfg.eps_abs = eps;
        cfg.max_steps = 100000;
        double rmin = 1e300;
        auto cb = [&](const StepView& s) {
          rmin = std::min(rmin, s.y1[1]);
          return s.y1[1] < 0.1 ? StepAction::Stop : StepAction::Continue;
        };
        const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
        const std::string what =
            std::string(solver_kind_name(kind)) + " eps " + std::to_string(eps) + " angle " + std::to_string(ang);
        EXPECT_EQ(r.reason, StopReason::Callback) << what << ": " << stop_reason_name(r.reason);
        EXPECT_LT(rmin, 0.1) << what;  // crossed r_s = 2
      }
}

TEST(StopLogic, NonNullDirectionIsStoppedForConstraint) {
  // k = E (e_(0) + 0.9 n) in the free-fall frame: g(k,k) = −0.19 E², i.e. non-null by about 10 %
  // of its Euclidean size 1.81 E² in that frame; outside and inside the horizon.
  auto m = make_metric("EddFinkIn");
  for (double r0 : {10.0, 1.0}) {
    const Vec4 x{{0, r0, 1.1, 0.3}};
    const Tetrad e = m->natural_tetrad(x, TetradKind::Freefall);
    for (const Vec3 n : {Vec3{-1, 0, 0}, Vec3{0.6, 0, 0.8}, Vec3{0, -1, 0}}) {
      Vec4 k;
      for (int mu = 0; mu < 4; ++mu) k[mu] = e[0][mu] + 0.9 * (n.x * e[1][mu] + n.y * e[2][mu] + n.z * e[3][mu]);
      for (SolverKind kind : kAdaptive) {
        double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
        SolverConfig cfg;
        cfg.kind = kind;
        const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
        EXPECT_EQ(r.reason, StopReason::Constraint) << solver_kind_name(kind) << " r0 " << r0;
        EXPECT_EQ(r.steps, 0) << solver_kind_name(kind);
      }
      // The same k made null again (|n| = 1) runs on.
      for (int mu = 0; mu < 4; ++mu) k[mu] = e[0][mu] + n.x * e[1][mu] + n.y * e[2][mu] + n.z * e[3][mu];
      double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
      SolverConfig cfg;
      cfg.max_steps = 20;
      const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
      EXPECT_NE(r.reason, StopReason::Constraint) << "r0 " << r0;
    }
  }
}
