// Kerr and Schwarzschild geodesics through Carter's separated equations in Mino time
// (spacetime/kerr_mino.h) against the independent second-order geodesic equation in
// Boyer–Lindquist coordinates (the closed-form Christoffel symbols, themselves checked against
// automatic differentiation), plus the driver features the Mino form has to re-implement: λ_max
// reached exactly, step sizes in λ, the constraint monitor, passages through the polar axis.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "spacetime/kerr_mino.h"
#include "spacetime/metric_registry.h"

using namespace geovis;

namespace {

Vec3 cartesian(const double* y) {
  const double r = y[1], st = std::sin(y[2]), ct = std::cos(y[2]);
  return {r * st * std::cos(y[3]), r * st * std::sin(y[3]), r * ct};
}

SolverConfig tight(bool separable, double lambda_max) {
  SolverConfig cfg;
  cfg.kind = SolverKind::DormandPrince853;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 1000000;
  cfg.lambda_max = lambda_max;
  cfg.separable = separable;
  return cfg;
}

}  // namespace

TEST(KerrMino, AgreesWithTheCoordinateFormOnRandomGeodesics) {
  // Random holes (M, |a| < M), places outside 1.5 r_+ and directions; null and timelike geodesics
  // are integrated to λ = 15 both ways. Both must stop for the same reason and, where both reach
  // λ_max, agree in x and k to the integration accuracy.
  std::mt19937 rng(20261129);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int compared = 0, captured = 0;
  double worst_x = 0, worst_k = 0;
  for (int n = 0; n < 120; ++n) {
    const double M = 0.5 + U(rng), a = (2 * U(rng) - 1) * 0.99 * M;
    const bool schwarzschild = n % 4 == 0;
    auto m = schwarzschild ? make_metric("Schwarzschild", {{"mass", M}})
                           : make_metric("KerrBL", {{"mass", M}, {"angmom", a}});
    const double rp = schwarzschild ? 2 * M : M + std::sqrt(M * M - a * a);
    const Vec4 x{
        {5 * U(rng), rp * (1.5 + 8 * U(rng)), 0.2 + (std::numbers::pi - 0.4) * U(rng), 2 * std::numbers::pi * U(rng)}};
    const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
    const Vec3 d = normalize(Vec3{2 * U(rng) - 1, 2 * U(rng) - 1, 2 * U(rng) - 1});
    const bool timelike = n % 3 == 0;
    const Vec4 k = timelike ? local_four_velocity(e, 0.7 * d) : local_null_direction(e, d, n % 2 == 0);
    double y[2][8];
    GeodesicResult r[2];
    for (int f = 0; f < 2; ++f) {
      for (int i = 0; i < 4; ++i) {
        y[f][i] = x[i];
        y[f][4 + i] = k[i];
      }
      SolverConfig cfg = tight(f == 1, 15.0);
      if (timelike) cfg.type = GeodesicType::Timelike;
      r[f] = m->integrate(cfg, GeodesicSystem::Geodesic, y[f], 0.0, {});
    }
    ASSERT_EQ(r[0].reason, r[1].reason) << "geodesic " << n << ": " << stop_reason_name(r[0].reason) << " vs "
                                        << stop_reason_name(r[1].reason);
    if (r[0].reason != StopReason::LambdaMax) {
      EXPECT_EQ(r[0].reason, StopReason::Invalid);  // both fell into the hole
      EXPECT_NEAR(y[1][1], y[0][1], 2e-3 * rp);
      ++captured;
      continue;
    }
    ++compared;
    EXPECT_NEAR(r[1].lambda, 15.0, 1e-11);
    const double dx = norm(cartesian(y[1]) - cartesian(y[0])), dt = std::fabs(y[1][0] - y[0][0]);
    double dk = 0, kn = 0;
    for (int i = 4; i < 8; ++i) {
      dk = std::max(dk, std::fabs(y[1][i] - y[0][i]));
      kn = std::max(kn, std::fabs(y[0][i]));
    }
    worst_x = std::max({worst_x, dx / y[0][1], dt / (1 + std::fabs(y[0][0]))});
    worst_k = std::max(worst_k, dk / kn);
    EXPECT_LT(dx, 1e-8 * y[0][1]) << "geodesic " << n;
    EXPECT_LT(dt, 1e-8 * (1 + std::fabs(y[0][0]))) << "geodesic " << n;
    EXPECT_LT(dk, 1e-8 * kn) << "geodesic " << n;
  }
  std::printf(
      "Mino vs coordinate form: %d geodesics compared at lambda = 15 (%d captured by both): "
      "worst relative difference x %.2g, k %.2g\n",
      compared, captured, worst_x, worst_k);
  EXPECT_GT(compared, 60);
}

TEST(KerrMino, ConstantsExactNullConstraintKeptAndStepsInAffineUnits) {
  // Along a Kerr (a = 0.9) ray that comes close to the hole, the BL view of every step reproduces
  // E and L to rounding (they are parameters of the integration: this checks the conversion back),
  // and Q and g(k,k) = 0 to the integration accuracy (they also depend on the integrated
  // d(1/r)/dσ and d(cos θ)/dσ); step_max is honoured in λ.
  const double a = 0.9;
  auto m = make_metric("KerrBL", {{"angmom", a}});
  const Vec4 x{{0, 20, 1.2, 0}};
  const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
  const Vec4 k = local_null_direction(e, normalize(Vec3{-1, 0.12, 0.16}), false);
  const KerrMinoConstants c0 = kerr_mino_constants(1.0, a, x, k, 0.0);
  SolverConfig cfg;
  cfg.kind = SolverKind::CashKarp45;
  cfg.eps_abs = 1e-10;
  cfg.step_max = 0.3;
  cfg.box_ur = Vec4{{1e300, 30, 1e300, 1e300}};
  double rmin = 1e300, dE = 0, dL = 0, dQ = 0, dC = 0, hmax = 0;
  auto cb = [&](const StepView& s) {
    const Vec4 xs{{s.y1[0], s.y1[1], s.y1[2], s.y1[3]}}, ks{{s.y1[4], s.y1[5], s.y1[6], s.y1[7]}};
    const KerrMinoConstants c = kerr_mino_constants(1.0, a, xs, ks, 0.0);
    dE = std::max(dE, std::fabs(c.E / c0.E - 1));
    dL = std::max(dL, std::fabs(c.L / c0.L - 1));
    dQ = std::max(dQ, std::fabs(c.Q / c0.Q - 1));
    Mat4 g;
    m->metric_tensor(xs, g);
    dC = std::max(dC, std::fabs(dot(g, ks, ks)) / (c0.E * c0.E));
    rmin = std::min(rmin, xs[1]);
    hmax = std::max(hmax, s.lambda1 - s.lambda0);
    // dx/dλ handed to the caller is k, and dk/dλ the geodesic acceleration at the step end: from
    // the Mino derivatives it equals −Γ k k up to the constraint violation of the integrated state
    // (~1e-10 here), not to rounding.
    for (int i = 0; i < 4; ++i) EXPECT_EQ(s.dy1[i], s.y1[4 + i]);
    Vec4 acc;
    Christoffel G;
    m->christoffel(xs, G);
    for (int mu = 0; mu < 4; ++mu) {
      acc[mu] = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) acc[mu] -= G.G[mu][i][j] * ks[i] * ks[j];
    }
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(s.dy1[4 + i], acc[i], 1e-9 * (1 + std::fabs(acc[i])));
    return StepAction::Continue;
  };
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  std::printf("KerrBL a=0.9, Mino: r_min %.3f, %d steps, rel. E %.2g L %.2g Q %.2g, |g(k,k)|/E^2 %.2g\n", rmin, r.steps,
              dE, dL, dQ, dC);
  EXPECT_EQ(r.reason, StopReason::BoundingBox);
  EXPECT_LT(rmin, 5.0);
  EXPECT_GT(std::fabs(c0.Q), 1.0);
  EXPECT_LT(dE, 1e-13);
  EXPECT_LT(dL, 1e-13);
  EXPECT_LT(dQ, 1e-9);
  EXPECT_LT(dC, 1e-9);
  EXPECT_LE(hmax, 0.3 * (1 + 1e-9));
  EXPECT_GT(hmax, 0.29);
}

TEST(KerrMino, RayThroughThePolarAxisContinuesAcrossIt) {
  // Rays with L = 0 pass through the axis. Schwarzschild: the polar circular photon orbit r = 3M
  // (started at θ = 1 towards the north pole) crosses the north pole at λ = 3, the south pole at
  // λ = 3(1 + π); the coordinate form follows it with θ < 0 (k^φ = 0: nothing singular in its
  // equations) and both forms must give the same event at λ = 17. Kerr a = 0.9 (ω ≠ 0 on the axis,
  // where the coordinate form's Γ^φ_θφ k^θ k^φ diverges): a ray passing the pole must cross it
  // with a continuous path and g(k,k) = 0.
  for (const double a : {0.0, 0.9}) {
    auto m = a == 0 ? make_metric("Schwarzschild") : make_metric("KerrBL", {{"angmom", a}});
    const Vec4 x{{0, a == 0 ? 3.0 : 6.0, 1.0, 0.4}};
    const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
    // In the (e_r, e_θ) plane: no e_φ component, zero angular momentum about the axis.
    const Vec4 k = local_null_direction(e, a == 0 ? Vec3{0, -1, 0} : normalize(Vec3{0.05, -1, 0}), false);
    double ym[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    int crossings = 0;
    double jump = 0, dC = 0;
    Vec3 prev = cartesian(ym);
    auto cb = [&](const StepView& s) {
      if (std::sin(s.y0[2]) * std::sin(s.y1[2]) < 0) ++crossings;
      const Vec3 p = cartesian(s.y1);
      jump = std::max(jump, norm(p - prev) / (s.lambda1 - s.lambda0));  // ≤ ~|dx/dλ|: no jumps
      prev = p;
      Mat4 g;
      const Vec4 xs{{s.y1[0], s.y1[1], s.y1[2], s.y1[3]}}, ks{{s.y1[4], s.y1[5], s.y1[6], s.y1[7]}};
      m->metric_tensor(xs, g);
      dC = std::max(dC, std::fabs(dot(g, ks, ks)) / (ks[0] * ks[0]));
      return StepAction::Continue;
    };
    const double lambda_max = a == 0 ? 17.0 : 40.0;
    const GeodesicResult r = m->integrate(tight(true, lambda_max), GeodesicSystem::Geodesic, ym, 0.0, cb);
    EXPECT_EQ(r.reason, StopReason::LambdaMax) << "a = " << a;
    EXPECT_EQ(crossings, a == 0 ? 2 : 1) << "a = " << a;
    EXPECT_LT(jump, 3.0) << "a = " << a;
    EXPECT_LT(dC, 1e-9) << "a = " << a;
    if (a == 0) {
      EXPECT_NEAR(ym[1], 3.0, 1e-9);
      EXPECT_NEAR(ym[2], 1.0 - 17.0 / 3.0, 1e-9);  // θ continues below −π on the same great circle
      double yc[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
      ASSERT_EQ(m->integrate(tight(false, lambda_max), GeodesicSystem::Geodesic, yc, 0.0, {}).reason,
                StopReason::LambdaMax);
      EXPECT_LT(norm(cartesian(ym) - cartesian(yc)), 1e-9);
      EXPECT_NEAR(ym[0], yc[0], 1e-9);
    }
  }
}

TEST(KerrMino, ConstraintMonitorStopsANonNullStart) {
  // k 10 % off the light cone: the constraint value of the Mino state is g(k,k) of its BL view.
  auto m = make_metric("KerrBL", {{"angmom", 0.7}});
  const Vec4 x{{0, 12, 1.3, 0}};
  Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), Vec3{-0.6, 0.3, 0.74}, false);
  k[1] *= 1.1;
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg;
  cfg.eps_abs = 1e-8;
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
  EXPECT_EQ(r.reason, StopReason::Constraint);
  Mat4 g;
  m->metric_tensor(x, g);
  EXPECT_NEAR(r.constraint_drift, dot(g, k, k), 1e-6 * std::fabs(dot(g, k, k)));
}

TEST(KerrMino, RaysPassingCloseToTheAxisDoNotStall) {
  // Rays that pass the north pole at θ_min ≈ |L|/√(B + 2A): with the default solver they used to
  // stall there for 5e-6 < |L/E| < 3.5e-4 (θ_min 1e-6 .. 6e-5; kerr_mino.h file comment: the
  // polar turning point was lost in the integration error of z'² = Z) and end with max_steps. The
  // reported ray (geovis geodesic, test GeodesicCmd.NearAxisKerrRayThatUsedToStallGetsThrough) passes the
  // pole on an unstable near-spherical orbit at r ≈ 3M, where any two integrations part
  // exponentially; here a ray from r = 30 passes over the pole at r ≈ 30..40 and runs to λ = 100
  // (r ≈ 100).
  // L/E is swept from 1e-9 to 1e-2 (both signs, and L = 0) for a = 0.9 and 0.998: every ray must
  // get past the pole, with E, L, Q and g(k,k) = 0 conserved, and end at the point and in the
  // direction the coordinate-form DOP853 integration gives.
  int compared = 0, rays = 0;
  for (const double a : {0.9, 0.998}) {
    auto m = make_metric("KerrBL", {{"angmom", a}});
    const Vec4 x{{0, 30, 0.3, 0}};
    Mat4 g;
    m->metric_tensor(x, g);
    for (int i = -1; i <= 28; ++i) {
      // BL tangent with E = 1, L given, k^r = 0.3, k^θ < 0 (towards the north pole) from g(k,k) = 0:
      // E = −g_tt k^t − g_tφ k^φ, L = g_tφ k^t + g_φφ k^φ.
      const double L = i < 0 ? 0.0 : (i % 2 ? -1.0 : 1.0) * std::pow(10.0, -9.0 + 7.0 * i / 28.0);
      const double det = -g[0][0] * g[3][3] + g[0][3] * g[0][3];  // of [[−g_tt, −g_tφ], [g_tφ, g_φφ]]
      Vec4 k{{(g[3][3] * 1.0 + g[0][3] * L) / det, 0.3, 0.0, (-g[0][3] * 1.0 - g[0][0] * L) / det}};
      const double rest =
          g[0][0] * k[0] * k[0] + 2 * g[0][3] * k[0] * k[3] + g[3][3] * k[3] * k[3] + g[1][1] * k[1] * k[1];
      k[2] = -std::sqrt(-rest / g[2][2]);
      const KerrMinoConstants c0 = kerr_mino_constants(1.0, a, x, k, 0.0);
      SCOPED_TRACE(testing::Message() << "a = " << a << ", L/E = " << c0.L / c0.E);
      ASSERT_NEAR(c0.E, 1.0, 1e-12);
      ASSERT_NEAR(c0.L, L, 1e-15);
      SolverConfig cfg;  // default solver (Cash-Karp)
      cfg.eps_abs = 1e-9;
      cfg.max_steps = 30000;
      cfg.lambda_max = 100;
      double th_min = 10;
      auto cb = [&](const StepView& s) {
        th_min = std::min(th_min, std::fabs(s.y1[2]));
        return StepAction::Continue;
      };
      double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
      const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
      ++rays;
      ASSERT_EQ(r.reason, StopReason::LambdaMax) << stop_reason_name(r.reason) << " after " << r.steps << " steps";
      EXPECT_LT(th_min, 0.01);          // it came to the pole ...
      EXPECT_GT(std::fabs(y[2]), 0.1);  // ... and left it
      const Vec4 x1{{y[0], y[1], y[2], y[3]}}, k1{{y[4], y[5], y[6], y[7]}};
      const KerrMinoConstants c1 = kerr_mino_constants(1.0, a, x1, k1, 0.0);
      const double scale = std::sqrt(c0.Q + c0.L * c0.L + a * a * c0.E * c0.E);  // |angular momentum|
      EXPECT_NEAR(c1.E, c0.E, 1e-12);
      EXPECT_NEAR(c1.L, c0.L, 1e-12 * scale);
      EXPECT_NEAR(c1.Q, c0.Q, 1e-7 * scale * scale);
      Mat4 g1;
      m->metric_tensor(x1, g1);
      EXPECT_LT(std::fabs(dot(g1, k1, k1)), 1e-8);
      // The coordinate form (DOP853, tight) to the same sphere. It needs k^φ ∝ L/sin²θ resolved at
      // the pole and gives up (max-steps) for the closest passes; those are only checked above.
      SolverConfig cc = tight(false, cfg.lambda_max);
      cc.max_steps = 20000;
      double yc[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
      if (m->integrate(cc, GeodesicSystem::Geodesic, yc, 0.0, {}).reason != StopReason::LambdaMax) continue;
      EXPECT_LT(norm(cartesian(y) - cartesian(yc)), 1e-6 * 100);
      auto direction = [](const double* s) {  // d/dλ of cartesian(): the chain rule
        const double r = s[1], st = std::sin(s[2]), ct = std::cos(s[2]), sp = std::sin(s[3]), cp = std::cos(s[3]);
        const double dr = s[5], dth = s[6], dph = s[7];
        return normalize(Vec3{st * cp * dr + r * ct * cp * dth - r * st * sp * dph,
                              st * sp * dr + r * ct * sp * dth + r * st * cp * dph, ct * dr - r * st * dth});
      };
      EXPECT_LT(norm(direction(y) - direction(yc)), 1e-6);
      ++compared;
    }
  }
  std::printf("axis sweep: %d rays passed the pole, %d compared with the coordinate form\n", rays, compared);
  EXPECT_GT(compared, 30);
}
