// Stop logic of the geodesic integration (integrators.h, integrate_with and MetricSystem):
//  * rays falling towards a horizon where the chart is singular stop promptly with the horizon
//    reason at the metric's break margin (Metric::horizon_eps, Motion4D's breakCondition eps),
//    instead of creeping towards r_s while k^t diverges and burning the step budget;
//  * the constraint test measures g(k,k) relative to a positive-definite size of k, so that rays
//    in charts with large/cancelling off-diagonal terms (ingoing Eddington–Finkelstein across the
//    horizon) are not stopped, while a genuinely non-null k is.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "spacetime/metric_registry.h"

using namespace geovis;

namespace {

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
  const Vec4 x{{0, r0, std::numbers::pi / 2, 0}};
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
      // Killing horizons of the Ehlers–Kundt B metrics (g_tt = 0 at sin θ = 0, r = 0, r = 0) and the
      // C-metric's horizon G(y) = 0: without a break margin these rays ended in step underflow.
      {"Petrov_Type_D_BI_ES", {}, Vec4{{0, 6, 1.1, 0}}, Vec3{0, -1, 0}},
      {"Petrov_Type_D_BII_ES", {}, Vec4{{0, 2, 0, 0.9}}, Vec3{-1, 0, 0}},
      {"Petrov_Type_D_BIII_ES", {}, Vec4{{0, 2, 0, 0.9}}, Vec3{-1, 0, 0}},
      {"Petrov_Type_D_C_ES", {}, Vec4{{0, 0, 1, 1.5}}, Vec3{0, 0, -1}},
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

/// Kruskal: a backward-traced ray inside the shadow crosses the past horizon X = −T into the white
/// hole and ends at the past singularity X² − T² = −1 (MTW §31.5). It must stop there as horizon
/// (Invalid): with the margin taken in r (r < r_s·horizon_eps) the rounding noise of r(X² − T²)
/// made it creep (3000 points: max-steps; 66000 steps: step underflow), and the metric gallery's
/// Kruskal view (observer at X = 20, T = 0, eps_abs 1e-6, 3000 points) was almost all max-steps.
/// A ray that first winds near the photon sphere reaches X ≈ −T ≈ 170 before it falls in, where
/// the rounding of X ± T is larger still: at eps_abs 1e-8 it needs more steps (up to ~40000 with
/// DOP853), but still ends at the break, so only the gallery tolerance gets a step bound.
TEST(StopLogic, KruskalShadowRayStopsAtTheSingularity) {
  auto m = make_metric("Kruskal");
  const Vec4 x{{0, 20, std::numbers::pi / 2, 0}};
  const double eps_h = m->horizon_eps();
  for (const Vec3& d : {Vec3{-1, 0, 0}, Vec3{-1, 0.1, 0}, Vec3{-1, 0.3, 0.2}, Vec3{-1, 0, 0.5}})
    for (SolverKind kind : {SolverKind::CashKarp45, SolverKind::DormandPrince853})
      for (double eps : {1e-6, 1e-8}) {
        double y[8];
        const GeodesicResult r = trace_back(*m, x, d, kind, eps, y);
        const std::string what = std::string(solver_kind_name(kind)) + " eps_abs " + std::to_string(eps * 1e8) +
                                 "e-8 d (-1, " + std::to_string(d.y) + ", " + std::to_string(d.z) + ")";
        EXPECT_EQ(r.reason, StopReason::Invalid) << what << ": " << stop_reason_name(r.reason);
        if (eps == 1e-6) {
          EXPECT_LT(r.steps, 1000) << what;
        }
        // The last valid point: in the white hole (T < 0, |T| > |X|), just before the break
        // u + 1 = horizon_eps (the integrator homes in on the edge of the valid region).
        const double u = (y[1] + y[0]) * (y[1] - y[0]);
        EXPECT_LT(y[0], 0.0) << what;
        EXPECT_LT(y[1], -y[0]) << what;
        EXPECT_GE(u + 1.0, eps_h) << what;
        EXPECT_LT(u + 1.0, 1.01 * eps_h) << what;
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
  m->set_param("mass", 2.0);                                   // and parameter changes too
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

TEST(StopLogic, RaysLeavingTheChartStopAtTheHorizonMargin) {
  // A freely falling observer inside the horizon (r = 1.5, r_s = 2) traces rays backwards. E =
  // g_{0μ} k^μ (k past-directed) is the conserved energy of the future-directed photon.
  //  * E < 0: the light cannot have come through the future horizon (E ≥ 0 there); backwards it
  //    creeps towards r_s from inside with k^0 → −∞ and is stopped at r_s (1 − horizon_eps).
  //  * E > 0: it came in from the exterior: backwards it crosses r_s at finite v and either
  //    escapes (box r < 20) or, turned back by the potential barrier, approaches the past horizon
  //    from outside and is stopped at r_s (1 + horizon_eps).
  // Either way the ray stops promptly instead of burning the step budget.
  for (const char* name : {"EddFinkIn", "PainleveGullstrand"}) {
    auto m = make_metric(name);
    const double rs = 2.0, eps_h = m->horizon_eps();
    const Vec4 x{{0, 1.5, std::numbers::pi / 2, 0}};
    int escaped = 0, stopped_inside = 0, stopped_outside = 0;
    for (int i = 0; i < 24; ++i) {
      const double psi = std::numbers::pi * (i + 0.5) / 24;  // angle from the outward radial direction
      const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Freefall),
                                          Vec3{std::cos(psi), 0, std::sin(psi)}, /*past_directed=*/true);
      Mat4 g;
      m->metric_tensor(x, g);
      const double energy = g[0][0] * k[0] + g[0][1] * k[1];
      double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
      SolverConfig cfg;
      cfg.kind = SolverKind::DormandPrince853;
      cfg.eps_abs = 1e-8;
      cfg.max_steps = 100000;
      cfg.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
      cfg.box_ur = Vec4{{1e300, 20, 1e300, 1e300}};
      double rmax = 0;
      auto cb = [&](const StepView& s) {
        rmax = std::max(rmax, s.y1[1]);
        return StepAction::Continue;
      };
      const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
      const std::string what = std::string(name) + " psi " + std::to_string(psi) + " E " + std::to_string(energy) +
                               ": " + stop_reason_name(r.reason) + " at r " + std::to_string(y[1]);
      EXPECT_LT(r.steps, 500) << what;
      if (energy < 0) {
        ++stopped_inside;
        EXPECT_EQ(r.reason, StopReason::Invalid) << what;
        EXPECT_LE(y[1], rs * (1 - eps_h)) << what;
        EXPECT_GT(y[1], rs * (1 - 2 * eps_h)) << what;
        EXPECT_LT(rmax, rs) << what;
      } else if (r.reason == StopReason::BoundingBox) {
        ++escaped;
        EXPECT_GT(y[1], 20.0) << what;
      } else {
        ++stopped_outside;
        EXPECT_EQ(r.reason, StopReason::Invalid) << what;
        EXPECT_GE(y[1], rs * (1 + eps_h)) << what;
        EXPECT_LT(y[1], rs * (1 + 2 * eps_h)) << what;
        EXPECT_GT(rmax, y[1]) << what;  // went out and came back
      }
    }
    EXPECT_GT(escaped, 0) << name;
    EXPECT_GT(stopped_inside, 0) << name;
    EXPECT_GT(stopped_outside, 0) << name;
  }
}
