// Straight rays without integrator (spacetime/straight_ray.h): the one step is the exact line
// x0 + λ k, and it ends where, and for the reason, the integrated ray in Minkowski ends.
#include "spacetime/straight_ray.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "spacetime/jacobi.h"
#include "spacetime/metric.h"
#include "spacetime/metric_registry.h"
#include "support/uniform.h"

using namespace geovis;

namespace {

using geovis::testing_support::uni;

/// A past-directed null ray from a random event inside the box: k = (−1, n̂).
void random_ray(std::mt19937& rng, double* y) {
  const double z = uni(rng, -1, 1), ph = uni(rng, -M_PI, M_PI), s = std::sqrt(1 - z * z);
  const double x[4] = {uni(rng, -5, 5), uni(rng, -8, 8), uni(rng, -8, 8), uni(rng, -8, 8)};
  const double k[4] = {-1.0, s * std::cos(ph), s * std::sin(ph), z};
  for (int i = 0; i < 4; ++i) y[i] = x[i], y[4 + i] = k[i];
}

SolverConfig scene_config() {
  SolverConfig cfg;
  cfg.step_ctrl = false;
  cfg.step_size = 0.1;
  cfg.max_steps = 3000;
  cfg.box_ll = Vec4{{-DBL_MAX, -20, -20, -20}};
  cfg.box_ur = Vec4{{DBL_MAX, 20, 20, 20}};
  return cfg;
}

/// Both ways from the same start; the ends must agree in reason, λ and state.
void expect_same_end(const Metric& mink, const SolverConfig& cfg, const double* start, const char* what) {
  double ys[8], yi[8];
  for (int i = 0; i < 8; ++i) ys[i] = yi[i] = start[i];
  int calls = 0;
  const GeodesicResult s =
      integrate_straight(cfg, GeodesicSystem::Geodesic, ys, 0.0, mink.asymptotically_flat(), [&](const StepView&) {
        ++calls;
        return StepAction::Continue;
      });
  const GeodesicResult r = mink.integrate(cfg, GeodesicSystem::Geodesic, yi, 0.0, {});
  EXPECT_EQ(stop_reason_name(s.reason), std::string(stop_reason_name(r.reason))) << what;
  EXPECT_EQ(calls, 1) << what;
  // The integrator sums its steps in floating point (3000 additions of 0.1: ~1e-13 relative).
  EXPECT_NEAR(s.lambda, r.lambda, 1e-10 * (1 + std::fabs(r.lambda))) << what;
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(ys[i], yi[i], 1e-10 * (1 + std::fabs(yi[i]))) << what << " " << i;
}

}  // namespace

TEST(StraightRay, OneStepOnTheExactLine) {
  std::mt19937 rng(5);
  const SolverConfig cfg = scene_config();
  for (int n = 0; n < 50; ++n) {
    double y[8], y0[8];
    random_ray(rng, y);
    for (int i = 0; i < 8; ++i) y0[i] = y[i];
    std::vector<double> checked;
    const GeodesicResult r = integrate_straight(cfg, GeodesicSystem::Geodesic, y, 0.0, true, [&](const StepView& st) {
      EXPECT_EQ(st.lambda0, 0.0);
      for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(st.y0[i], y0[i]);
        EXPECT_NEAR(st.y1[i], y0[i] + st.lambda1 * y0[4 + i], 1e-13 * (1 + std::fabs(st.y1[i])));
        EXPECT_EQ(st.y1[4 + i], y0[4 + i]);  // k constant
        EXPECT_EQ(st.dy0[i], y0[4 + i]);     // dx/dλ = k
        EXPECT_EQ(st.dy1[4 + i], 0.0);       // dk/dλ = −Γkk = 0
      }
      // Dense output of the step (hermite_interpolate) is the line itself.
      for (double f : {0.1, 0.5, 0.9}) {
        Vec4 x, k;
        hermite_interpolate(st, f, x, k);
        for (int i = 0; i < 4; ++i) {
          EXPECT_NEAR(x[i], y0[i] + f * st.lambda1 * y0[4 + i], 1e-12 * (1 + std::fabs(x[i])));
          EXPECT_NEAR(k[i], y0[4 + i], 1e-12);
        }
      }
      checked.push_back(st.lambda1);
      return StepAction::Continue;
    });
    ASSERT_EQ(checked.size(), 1u);
    EXPECT_EQ(r.reason, StopReason::BoundingBox);
    EXPECT_EQ(r.steps, 1);
    EXPECT_EQ(r.rhs_evals, 0);
    // The integrator's fixed steps end at j·h; the ray stops at the first end outside the box.
    double s_box = INFINITY;
    for (int i = 1; i < 4; ++i) s_box = std::min(s_box, ((y0[4 + i] > 0 ? 20.0 : -20.0) - y0[i]) / y0[4 + i]);
    EXPECT_NEAR(r.lambda, (std::floor(s_box / 0.1) + 1) * 0.1, 1e-12);
  }
}

TEST(StraightRay, EndsWhereAndWhyTheIntegratedRayEnds) {
  auto mink = make_metric("Minkowski");
  std::mt19937 rng(17);
  for (int n = 0; n < 20; ++n) {
    double y[8];
    random_ray(rng, y);
    SolverConfig cfg = scene_config();
    expect_same_end(*mink, cfg, y, "box");
    cfg.max_steps = 40;  // 4 units of λ: runs out of steps inside the box
    expect_same_end(*mink, cfg, y, "max steps");
    cfg.max_steps = 3000;
    cfg.lambda_max = 3.05;  // the last step shortened to λ_max
    expect_same_end(*mink, cfg, y, "lambda max");
    cfg.lambda_max = INFINITY;
    cfg.escape_radius = 6.0;
    expect_same_end(*mink, cfg, y, "escape");
    cfg.escape_radius = INFINITY;
    cfg.step_ctrl = true;  // steps growing by 5 per step from 0.1, capped at step_max
    cfg.step_max = 0.7;
    expect_same_end(*mink, cfg, y, "adaptive");
    cfg.max_steps = 7;
    expect_same_end(*mink, cfg, y, "adaptive, max steps");
  }
  // A start outside the box: no step.
  double y[8] = {0, 30, 0, 0, -1, 1, 0, 0};
  int calls = 0;
  const GeodesicResult r =
      integrate_straight(scene_config(), GeodesicSystem::Geodesic, y, 0.0, true, [&](const StepView&) {
        ++calls;
        return StepAction::Continue;
      });
  EXPECT_EQ(r.reason, StopReason::BoundingBox);
  EXPECT_EQ(calls, 0);
}

TEST(StraightRay, JacobiFieldsGrowLinearly) {
  // Jacobi system in flat space: Y'' = 0, so Y(λ) = Y(0) + λ Y'(0), Sachs vectors and Y' constant;
  // the integrator agrees.
  auto mink = make_metric("Minkowski");
  double y[kJacobiDim] = {}, yi[kJacobiDim];
  std::mt19937 rng(3);
  random_ray(rng, y);
  for (int i = 8; i < kJacobiDim; ++i) y[i] = uni(rng, -1, 1);
  for (int i = 0; i < kJacobiDim; ++i) yi[i] = y[i];
  double start[kJacobiDim];
  for (int i = 0; i < kJacobiDim; ++i) start[i] = y[i];
  const SolverConfig cfg = scene_config();
  const GeodesicResult r = integrate_straight(cfg, GeodesicSystem::Jacobi, y, 0.0, true, {});
  const GeodesicResult ri = mink->integrate(cfg, GeodesicSystem::Jacobi, yi, 0.0, {});
  EXPECT_EQ(r.reason, ri.reason);
  EXPECT_NEAR(r.lambda, ri.lambda, 1e-10);
  for (int mu = 0; mu < 4; ++mu) {
    EXPECT_NEAR(y[kJacobiY1 + mu], start[kJacobiY1 + mu] + r.lambda * start[kJacobiDY1 + mu], 1e-12);
    EXPECT_NEAR(y[kJacobiY2 + mu], start[kJacobiY2 + mu] + r.lambda * start[kJacobiDY2 + mu], 1e-12);
    EXPECT_EQ(y[kJacobiS1 + mu], start[kJacobiS1 + mu]);
    EXPECT_EQ(y[kJacobiDY2 + mu], start[kJacobiDY2 + mu]);
  }
  for (int i = 0; i < kJacobiDim; ++i) EXPECT_NEAR(y[i], yi[i], 1e-9 * (1 + std::fabs(yi[i]))) << i;
}
