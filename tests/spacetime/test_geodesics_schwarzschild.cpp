// Geodesics of the Schwarzschild spacetime (M = 1, r_s = 2) against analytic results, for every
// adaptive integrator: the circular photon orbit at r = 3M, capture/escape around the critical
// impact parameter 3√3 M, the radial light travel time (paper eq. 9), the period of the circular
// timelike orbit at r = 6M (Kepler's third law holds exactly in Schwarzschild time), and the
// weak-field deflection 4M/b. Also the constraint monitor and the re-projection.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "metric_checks.h"
#include "spacetime/metric_registry.h"

using namespace geovis;

namespace {

struct AdaptiveCase {
  SolverKind kind;
  double eps;             ///< eps_abs used for the precision tests (RK2 is 2nd order: looser to stay fast)
  bool separable = true;  ///< Carter's equations in Mino time (kerr_mino.h), else the coordinate form
};
/// Every adaptive integrator, each through both forms of the geodesic equation.
const std::vector<AdaptiveCase>& adaptive_cases() {
  static const std::vector<AdaptiveCase> c = [] {
    std::vector<AdaptiveCase> v;
    for (bool separable : {false, true})
      for (auto [kind, eps] : std::vector<std::pair<SolverKind, double>>{{SolverKind::RK2, 1e-10},
                                                                         {SolverKind::CashKarp45, 1e-12},
                                                                         {SolverKind::Fehlberg45, 1e-12},
                                                                         {SolverKind::DormandPrince54, 1e-12},
                                                                         {SolverKind::DormandPrince853, 1e-12},
                                                                         {SolverKind::BulirschStoer, 1e-12}})
        v.push_back({kind, eps, separable});
    return v;
  }();
  return c;
}

std::string name(const AdaptiveCase& c) {
  return std::string(solver_kind_name(c.kind)) + (c.separable ? " (Mino)" : " (coordinates)");
}

SolverConfig config(SolverKind kind, double eps, bool separable = true) {
  SolverConfig cfg;
  cfg.kind = kind;
  cfg.eps_abs = eps;
  cfg.max_steps = 50000000;
  cfg.separable = separable;
  return cfg;
}

/// Equatorial null ray at radius r0 with energy E = 1 and angular momentum L = b (impact
/// parameter b = L/E), moving inward: k^t = E/(1−2M/r), k^φ = L/r², k^r from g(k,k) = 0
/// (Müller & Grave, Catalogue of Spacetimes §2.2.1).
void equatorial_null_ray(double r0, double b, double* y) {
  const double f = 1.0 - 2.0 / r0;
  y[0] = 0;
  y[1] = r0;
  y[2] = std::numbers::pi / 2;
  y[3] = 0;
  y[4] = 1.0 / f;
  y[5] = -std::sqrt(1.0 - f * b * b / (r0 * r0));
  y[6] = 0;
  y[7] = b / (r0 * r0);
}

}  // namespace

TEST(SchwarzschildGeodesics, ClosedFormChristoffelMatchesAD) {
  auto m = make_metric("Schwarzschild", {{"mass", 1.3}});
  metric_checks::expect_christoffel_matches_ad(*m, Vec4{{0.3, 7.1, 1.1, 0.4}}, metric_checks::kRuleRel,
                                               metric_checks::kRuleFloorFrac);
}

TEST(SchwarzschildGeodesics, CircularPhotonOrbitStaysAtThreeM) {
  // r = 3M is the (unstable) circular photon orbit; started tangentially there, the ray must stay
  // within 1e-8 of it for one revolution.
  auto m = make_metric("Schwarzschild");
  const Vec4 x{{0, 3.0, std::numbers::pi / 2, 0}};
  const Tetrad e = m->natural_tetrad(x);
  const Vec4 k = local_null_direction(e, Vec3{0, 0, 1}, false);
  for (const auto& c : adaptive_cases()) {
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    double rdev = 0;
    auto cb = [&](const StepView& s) {
      rdev = std::max(rdev, std::fabs(s.y1[1] - 3.0));
      return s.y1[3] > 2 * std::numbers::pi ? StepAction::Stop : StepAction::Continue;
    };
    const GeodesicResult r = m->integrate(config(c.kind, c.eps, c.separable), GeodesicSystem::Geodesic, y, 0.0, cb);
    EXPECT_EQ(r.reason, StopReason::Callback) << name(c);
    EXPECT_LT(rdev, 1e-8) << name(c);
  }
}

TEST(SchwarzschildGeodesics, CriticalImpactParameterSeparatesCaptureFromEscape) {
  // Photons with b < 3√3 M fall in, with b > 3√3 M they return to infinity.
  auto m = make_metric("Schwarzschild");
  const double bc = 3.0 * std::sqrt(3.0);
  const double r0 = 30;
  for (const auto& c : adaptive_cases()) {
    for (const double sign : {-1.0, 1.0}) {
      double y[8];
      equatorial_null_ray(r0, bc * (1.0 + sign * 1e-4), y);
      SolverConfig cfg = config(c.kind, c.kind == SolverKind::RK2 ? 1e-9 : 1e-10, c.separable);
      // Stop inside the photon sphere (an ingoing photon there is captured) or beyond r0.
      cfg.box_ll = Vec4{{-1e300, 2.5, -1e300, -1e300}};
      cfg.box_ur = Vec4{{1e300, r0 + 1e-9, 1e300, 1e300}};
      const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
      EXPECT_EQ(r.reason, StopReason::BoundingBox) << name(c);
      if (sign < 0)
        EXPECT_LT(y[1], 2.5) << name(c) << " should be captured";
      else
        EXPECT_GT(y[1], r0) << name(c) << " should escape";
    }
  }
}

TEST(SchwarzschildGeodesics, RadialLightTravelTime) {
  // Paper eq. (9): along a radial null ray dt/dr = 1/(1 − r_s/r), so t(r) = r + r_s ln(r − r_s).
  // For an affinely parametrized radial null geodesic dr/dλ = E is constant, so the ray from
  // r = 6 reaches r = 30 exactly at λ = 24/k^r.
  auto m = make_metric("Schwarzschild");
  const double rs = 2.0;
  const double expected = (30.0 + rs * std::log(30.0 - rs)) - (6.0 + rs * std::log(6.0 - rs));
  EXPECT_NEAR(expected, 27.8918, 1e-4);
  const Vec4 x{{0, 6.0, std::numbers::pi / 2, 0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{1, 0, 0}, false);
  for (const auto& c : adaptive_cases()) {
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    SolverConfig cfg = config(c.kind, c.eps, c.separable);
    cfg.lambda_max = 24.0 / k[1];
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
    EXPECT_EQ(r.reason, StopReason::LambdaMax) << name(c);
    EXPECT_NEAR(y[1], 30.0, 1e-9) << name(c);
    EXPECT_NEAR(y[0], expected, 1e-8) << name(c);
  }
}

TEST(SchwarzschildGeodesics, CircularTimelikeOrbitPeriod) {
  // A circular geodesic at r has dφ/dt = sqrt(M/r³), so its coordinate period is 2π sqrt(r³/M)
  // (= 92.3436 at r = 6M). The static observer sees it move with β = sqrt(M/(r − 2M)) = 1/2.
  auto m = make_metric("Schwarzschild");
  const double r0 = 6.0;
  const double period = 2 * std::numbers::pi * std::sqrt(r0 * r0 * r0);
  EXPECT_NEAR(period, 92.3436, 1e-4);
  const Vec4 x{{0, r0, std::numbers::pi / 2, 0}};
  const Vec4 u = local_four_velocity(m->natural_tetrad(x), Vec3{0, 0, std::sqrt(1.0 / (r0 - 2.0))});
  for (const auto& c : adaptive_cases()) {
    double y[8] = {x[0], x[1], x[2], x[3], u[0], u[1], u[2], u[3]};
    SolverConfig cfg = config(c.kind, c.eps, c.separable);
    cfg.type = GeodesicType::Timelike;
    // u^φ is constant on the circular orbit: one revolution takes proper time 2π/u^φ.
    cfg.lambda_max = 2 * std::numbers::pi / u[3];
    double rdev = 0;
    auto cb = [&](const StepView& s) {
      rdev = std::max(rdev, std::fabs(s.y1[1] - r0));
      return StepAction::Continue;
    };
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
    EXPECT_EQ(r.reason, StopReason::LambdaMax) << name(c);
    EXPECT_NEAR(y[3], 2 * std::numbers::pi, 1e-8) << name(c);
    EXPECT_NEAR(y[0], period, 1e-6) << name(c);
    EXPECT_LT(rdev, 1e-6) << name(c);
    EXPECT_LT(std::fabs(r.constraint_drift), 1e-9) << name(c);
  }
}

TEST(SchwarzschildGeodesics, WeakFieldDeflection) {
  // Einstein's deflection 4M/b (MTW eq. 25.49b) at b = 1000 M. The ray starts and ends at r = R;
  // a straight line between those points sweeps π − asin(b/R) − asin(b/r_end) in φ, the rest is
  // the deflection.
  auto m = make_metric("Schwarzschild");
  const double b = 1000, R = 1e6;
  for (const auto& c : adaptive_cases()) {
    double y[8];
    equatorial_null_ray(R, b, y);
    // RK2 needs ~tol^(-1/2) steps: 1e-7 keeps it well inside the 1% at a few 1e5 steps.
    SolverConfig cfg = config(c.kind, c.kind == SolverKind::RK2 ? 1e-7 : 1e-10, c.separable);
    cfg.box_ur = Vec4{{1e300, R, 1e300, 1e300}};
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
    EXPECT_EQ(r.reason, StopReason::BoundingBox) << name(c);
    const double alpha = y[3] - (std::numbers::pi - std::asin(b / R) - std::asin(b / y[1]));
    EXPECT_NEAR(alpha, 4.0 / b, 0.01 * 4.0 / b) << name(c) << " steps " << r.steps;
  }
}

TEST(SchwarzschildGeodesics, ConstraintMonitorAndReprojection) {
  // A sloppy tolerance lets g(k,k) drift; the monitor stops the ray once the relative drift
  // exceeds constraint_tol, and re-projection keeps it at round-off.
  auto m = make_metric("Schwarzschild");
  double y[8];
  equatorial_null_ray(30, 5.3, y);
  // The coordinate form: Carter's equations in Mino time keep E, L, Q exactly and drift far less.
  SolverConfig cfg = config(SolverKind::RK4, 0, false);
  cfg.step_ctrl = false;
  cfg.step_size = 0.5;
  cfg.constraint_tol = 1e-6;
  cfg.box_ll = Vec4{{-1e300, 2.5, -1e300, -1e300}};
  cfg.box_ur = Vec4{{1e300, 30.5, 1e300, 1e300}};
  GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
  EXPECT_EQ(r.reason, StopReason::Constraint);
  EXPECT_GT(std::fabs(r.constraint_drift), 0.0);

  equatorial_null_ray(30, 5.3, y);
  cfg.reproject = true;
  r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
  EXPECT_NE(r.reason, StopReason::Constraint);
  const double scale = (1 - 2 / y[1]) * y[4] * y[4];  // |g_tt| (k^t)², the size of the terms
  EXPECT_LT(std::fabs(r.constraint_drift), 1e-13 * scale);
}

TEST(SchwarzschildGeodesics, HorizonStopsTheRay) {
  // A radial ingoing ray reaches the horizon at finite affine parameter; the integration ends
  // there (validity domain or step underflow at the coordinate singularity) without leaving r > r_s.
  auto m = make_metric("Schwarzschild");
  const Vec4 x{{0, 10.0, std::numbers::pi / 2, 0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{-1, 0, 0}, false);
  for (const auto& c : adaptive_cases()) {
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    const double eps = c.kind == SolverKind::RK2 ? 1e-6 : 1e-8;
    SolverConfig cfg = config(c.kind, eps, c.separable);
    cfg.eps_rel = eps;  // k^t diverges at the horizon: a relative tolerance lets the steps follow
    cfg.max_steps = 100000;
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
    EXPECT_TRUE(r.reason == StopReason::Invalid || r.reason == StopReason::StepUnderflow)
        << name(c) << ": " << stop_reason_name(r.reason);
    EXPECT_GT(y[1], 2.0);
    EXPECT_LT(y[1], 2.0 + 1e-3) << name(c);
  }
}
