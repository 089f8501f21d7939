// Capture (spacetime/capture.h): a light ray below SolverConfig::capture_radius that provably
// falls to the horizon break radius stops there early with StopReason::Invalid. Checked: the
// certificate R > 0 on [r_break, r] against the sampled radial potential; rays stopped early end
// with the reason of the same rays integrated to the break radius, in every system (Mino
// geodesic, coordinate geodesic, Jacobi on the metric function table); and a ray whose turning
// point lies just outside the photon orbit is not stopped.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "spacetime/jacobi.h"
#include "spacetime/kerr_mino.h"
#include "spacetime/metric_registry.h"

using namespace geovis;

namespace {

/// R(r) of constants c (kerr_mino.h: R = r⁴ W(1/r)).
double radial_potential(const KerrMinoConstants& c, double r) { return r * r * r * r * c.W(1.0 / r); }
/// dR/dr by central differences (only its sign is used).
double radial_potential_slope(const KerrMinoConstants& c, double r) {
  const double h = 1e-5 * r;
  return (radial_potential(c, r + h) - radial_potential(c, r - h)) / (2 * h);
}

/// The horizon break radius of KerrBL (Metric::horizon_eps).
double r_break(double M, double a) { return (M + std::sqrt(M * M - a * a)) * (1.0 + Metric::kDefaultHorizonEps); }

/// Radius of the equatorial circular photon orbit, prograde or retrograde (Bardeen, Press &
/// Teukolsky, ApJ 178 (1972) 347, eq. 2.18): r = 2M (1 + cos(⅔ arccos(∓a/M))).
double photon_orbit(double M, double a, bool prograde) {
  return 2.0 * M * (1.0 + std::cos(2.0 / 3.0 * std::acos((prograde ? -a : a) / M)));
}

struct Form {
  const char* name;
  GeodesicSystem sys;
  bool separable;
  SolverKind kind;
};
const Form kForms[] = {
    {"Mino geodesic", GeodesicSystem::Geodesic, true, SolverKind::CashKarp45},
    {"coordinate geodesic", GeodesicSystem::Geodesic, false, SolverKind::CashKarp45},
    {"coordinate geodesic DOP853 (function table)", GeodesicSystem::Geodesic, false, SolverKind::DormandPrince853},
    {"Jacobi (function table)", GeodesicSystem::Jacobi, false, SolverKind::CashKarp45},
};

/// A ray's start state for system `sys`: (x, k), and for the Jacobi system the Sachs vectors and
/// Jacobi fields of a bundle with its vertex at x (tracer.cpp start_state), built from the
/// tetrad's e_(2), e_(3) (orthogonal to k for a direction in the 1-2-3 plane only approximately,
/// which does not matter here: the fields ride along without acting on the ray).
void start(const Metric& m, const Vec4& x, const Vec4& k, GeodesicSystem sys, double* y) {
  for (int i = 0; i < kMaxSystemDim; ++i) y[i] = 0;
  for (int i = 0; i < 4; ++i) {
    y[i] = x[i];
    y[4 + i] = k[i];
  }
  if (sys != GeodesicSystem::Jacobi) return;
  const Tetrad e = m.natural_tetrad(x, TetradKind::Default);
  for (int i = 0; i < 4; ++i) {
    y[kJacobiS1 + i] = y[kJacobiDY1 + i] = e[2][i];
    y[kJacobiS2 + i] = y[kJacobiDY2 + i] = e[3][i];
  }
}

SolverConfig config(const Form& f) {
  SolverConfig cfg;
  cfg.kind = f.kind;
  cfg.separable = f.separable;
  cfg.eps_abs = 1e-8;
  cfg.max_steps = 3000;
  cfg.box_ll = Vec4{{-DBL_MAX, 0, -DBL_MAX, -DBL_MAX}};
  cfg.box_ur = Vec4{{DBL_MAX, 70, DBL_MAX, DBL_MAX}};
  return cfg;
}

/// A light ray from (x, k) integrated in the coordinate form (up to 100 000 steps) with capture
/// everywhere and without, and the radius where the captured run ended.
struct CaptureRuns {
  GeodesicResult with, without;
  double r_end;
};
CaptureRuns with_and_without_capture(const Metric& m, const Vec4& x, const Vec4& k) {
  SolverConfig cfg = config(kForms[1]);
  cfg.max_steps = 100000;
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  const GeodesicResult without = m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
  cfg.capture_radius = INFINITY;
  double y2[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  const GeodesicResult with = m.integrate(cfg, GeodesicSystem::Geodesic, y2, 0.0, {});
  return {with, without, y2[1]};
}

}  // namespace

TEST(Capture, CertificateHoldsWhereverTheSampledPotentialSaysSo) {
  // Random light rays at random radii of Kerr holes: whenever the Bernstein certificate says
  // R > 0 on [r_break, r], R sampled densely on the interval is positive; and where the samples
  // show R clearly positive (min above 1e-6 of the size of R), the certificate says so too in
  // nearly all cases (it may decline only close to a double root).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int certified = 0, clear = 0, clear_certified = 0, with_root = 0;
  for (const double a : {0.0, 0.5, 0.9, 0.998, 1.0, -0.7}) {
    auto m = make_metric("KerrBL", {{"angmom", a}, {"mass", 1.0}});
    const double rb = r_break(1.0, a);
    for (int n = 0; n < 400; ++n) {
      const Vec4 x{{0, rb * (1.0 + 1e-3) + 8.0 * U(rng) * U(rng), 0.2 + 2.7 * U(rng), 0}};
      const Vec3 d = normalize(Vec3{2 * U(rng) - 1, 2 * U(rng) - 1, 2 * U(rng) - 1});
      const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), d, n % 2 == 0);
      const KerrMinoConstants c = kerr_mino_constants(1.0, a, x, k, 0.0);
      double rmin = INFINITY, size = 0;
      for (int i = 0; i <= 4000; ++i) {
        const double r = rb + (x[1] - rb) * i / 4000.0;
        rmin = std::min(rmin, radial_potential(c, r));
        size = std::max(size, c.E * c.E * r * r * r * r + c.K * r * r);
      }
      const bool cert = c.radial_potential_positive_on(rb, x[1]);
      certified += cert;
      with_root += rmin <= 0;
      if (cert) {
        EXPECT_GT(rmin, 0.0) << "a = " << a << ", r = " << x[1];
      }
      if (rmin > 1e-6 * size) {
        ++clear;
        clear_certified += cert;
      }
    }
  }
  std::printf("capture certificate: %d certified, %d of %d clear cases, %d with a root\n", certified, clear_certified,
              clear, with_root);
  EXPECT_GT(with_root, 300);
  EXPECT_GT(clear, 1000);
  EXPECT_GE(clear_certified, clear - clear / 100);
}

TEST(Capture, SchwarzschildPhotonSphereIsTheBoundOfTheSphericalTest) {
  // a = 0: below r = 3M every inward light ray has R > 0 down to the horizon (capture.h); the
  // Kerr certificate agrees with the spherical test there, and a tangential ray at 3M (1 + 1e-3)
  // is at a periastron: R vanishes there and it is not captured.
  auto m = make_metric("Schwarzschild", {{"mass", 1.0}});
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double rb = 2.0 * (1.0 + Metric::kDefaultHorizonEps);
  for (int n = 0; n < 300; ++n) {
    const Vec4 x{{0, rb * (1 + 1e-3) + (3.0 - rb * (1 + 1e-3)) * U(rng), 0.3 + 2.5 * U(rng), 1.0}};
    Vec3 d = normalize(Vec3{-U(rng), 2 * U(rng) - 1, 2 * U(rng) - 1});  // inward (e_(1) is radial)
    const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), d, true);
    EXPECT_TRUE(kerr_mino_constants(1.0, 0.0, x, k, 0.0).radial_potential_positive_on(rb, x[1])) << x[1];
  }
  const Vec4 x{{0, 3.0 * (1 + 1e-3), 0.5 * std::numbers::pi, 0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), Vec3{0, 0, 1}, true);
  EXPECT_FALSE(kerr_mino_constants(1.0, 0.0, x, k, 0.0).radial_potential_positive_on(rb, x[1]));
}

TEST(Capture, EarlyStopsEndAsTheRaysIntegratedToTheBreakRadius) {
  // A fan of light rays from an observer at r = 50 aimed at the hole (the geometry of GeoViS's
  // Kerr-disk scene), in every form of the integration, with capture below 6 and everywhere:
  // a ray stops as Invalid exactly when the plain geodesic integrated to the break radius (Mino
  // time, no step limit) ends there; a ray that does not fall in ends as without capture, after
  // the same steps; and the captured rays take fewer steps.
  for (const double a : {0.0, 0.998}) {
    auto m = make_metric("KerrBL", {{"angmom", a}, {"mass", 1.0}});
    const Vec4 x{{0, 50.0, 80.0 * std::numbers::pi / 180.0, 0}};
    const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
    for (const Form& f : kForms) {
      SCOPED_TRACE(testing::Message() << "a = " << a << ", " << f.name);
      int captured = 0;
      long steps_early = 0, steps_full = 0;
      for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
          const double ax = (i - 2) * 0.05, ay = (j - 2) * 0.05;
          const Vec3 d = normalize(Vec3{-1, std::tan(ax), std::tan(ay)});  // e_(1) points outward
          const Vec4 k = local_null_direction(e, d, true);
          double y_ref[kMaxSystemDim];
          start(*m, x, k, GeodesicSystem::Geodesic, y_ref);
          SolverConfig ref = config(kForms[0]);
          ref.max_steps = 1000000;
          const GeodesicResult r_ref = m->integrate(ref, GeodesicSystem::Geodesic, y_ref, 0.0, {});
          ASSERT_TRUE(r_ref.reason == StopReason::Invalid || r_ref.reason == StopReason::BoundingBox)
              << stop_reason_name(r_ref.reason);
          const bool falls_in = r_ref.reason == StopReason::Invalid;
          double y_full[kMaxSystemDim];
          start(*m, x, k, f.sys, y_full);
          SolverConfig cfg = config(f);
          const GeodesicResult r_full = m->integrate(cfg, f.sys, y_full, 0.0, {});
          for (const double cr : {6.0, double(INFINITY)}) {
            double y[kMaxSystemDim];
            start(*m, x, k, f.sys, y);
            cfg.capture_radius = cr;
            const GeodesicResult r = m->integrate(cfg, f.sys, y, 0.0, {});
            SCOPED_TRACE(testing::Message() << "ray " << i << "," << j << ", capture below " << cr << ": "
                                            << stop_reason_name(r.reason) << " after " << r.steps << " steps, without "
                                            << stop_reason_name(r_full.reason) << " after " << r_full.steps);
            EXPECT_EQ(r.reason == StopReason::Invalid, falls_in);
            if (!falls_in) {
              EXPECT_EQ(r.reason, r_full.reason);
              EXPECT_EQ(r.steps, r_full.steps);
            } else if (cr == 6.0) {
              ++captured;
              steps_early += r.steps;
              steps_full += r_full.steps;
              EXPECT_LT(y[1], 6.0);
            }
          }
        }
      EXPECT_GE(captured, 5);
      EXPECT_LT(steps_early, steps_full);
    }
  }
}

TEST(Capture, RayTurningJustOutsideThePhotonOrbitIsNotStopped) {
  // A light ray tangential at r_t = r_ph (1 ± 1e-3) in the equatorial plane, with r_ph the
  // circular photon orbit of its sense of rotation: just outside, r_t is a periastron; the ray is
  // followed outward to r = 8 and reversed, so that it comes in towards r_t. With capture below
  // 1e3 it must pass its periastron and escape. Just inside, r_t is an apoastron: the ray falls
  // in and is captured at once, with the reason the integration to the break radius gives.
  for (const double a : {0.0, 0.9, -0.9}) {
    auto m = make_metric("KerrBL", {{"angmom", a}, {"mass", 1.0}});
    for (const double sense : {1.0, -1.0}) {
      // Prograde when L/E > 0 (the equations are even in (E, L, k)).
      const Vec4 x_probe{{0, 10.0, 0.5 * std::numbers::pi, 0}};
      const Vec4 k_probe =
          local_null_direction(m->natural_tetrad(x_probe, TetradKind::Default), Vec3{0, 0, sense}, true);
      const KerrMinoConstants c_probe = kerr_mino_constants(1.0, a, x_probe, k_probe, 0.0);
      const double r_ph = photon_orbit(1.0, std::fabs(a), c_probe.L * c_probe.E * (a >= 0 ? 1 : -1) > 0);
      for (const Form& f : kForms) {
        SCOPED_TRACE(testing::Message() << "a = " << a << ", sense " << sense << ", " << f.name);
        // Outside: periastron.
        const Vec4 xo{{0, r_ph * (1 + 1e-3), 0.5 * std::numbers::pi, 0}};
        const Vec4 ko = local_null_direction(m->natural_tetrad(xo, TetradKind::Default), Vec3{0, 0, sense}, true);
        const KerrMinoConstants co = kerr_mino_constants(1.0, a, xo, ko, 0.0);
        ASSERT_GT(radial_potential_slope(co, xo[1]), 0.0);  // a minimum of r
        double y[kMaxSystemDim];
        start(*m, xo, ko, f.sys, y);
        SolverConfig cfg = config(f);
        cfg.eps_abs = 1e-10;
        auto out_to_8 = [&](const StepView& s) { return s.y1[1] > 8.0 ? StepAction::Stop : StepAction::Continue; };
        ASSERT_EQ(m->integrate(cfg, f.sys, y, 0.0, out_to_8).reason, StopReason::Callback);
        for (int i = 4; i < kMaxSystemDim; ++i) y[i] = -y[i];  // the same path, coming in
        cfg.capture_radius = 1e3;
        cfg.escape_radius = 20.0;
        double r_min = INFINITY;
        auto watch = [&](const StepView& s) {
          r_min = std::min(r_min, s.y1[1]);
          return StepAction::Continue;
        };
        double y_in[kMaxSystemDim];
        for (int i = 0; i < kMaxSystemDim; ++i) y_in[i] = y[i];
        const GeodesicResult r = m->integrate(cfg, f.sys, y, 0.0, watch);
        EXPECT_NE(r.reason, StopReason::Invalid);
        if (f.sys == GeodesicSystem::Geodesic) {
          EXPECT_EQ(r.reason, StopReason::Escaped) << stop_reason_name(r.reason);
          EXPECT_LT(r_min, r_ph * (1 + 2e-3));
        } else {
          // The Jacobi fields grow fast on the orbits around the photon orbit and the error
          // control may run out of steps first: whatever ends the ray, capture must not.
          cfg.capture_radius = 0;
          EXPECT_EQ(r.reason, m->integrate(cfg, f.sys, y_in, 0.0, {}).reason) << stop_reason_name(r.reason);
        }
        // Inside: apoastron, falls in.
        const Vec4 xi{{0, r_ph * (1 - 1e-3), 0.5 * std::numbers::pi, 0}};
        const Vec4 ki = local_null_direction(m->natural_tetrad(xi, TetradKind::Default), Vec3{0, 0, sense}, true);
        ASSERT_LT(radial_potential_slope(kerr_mino_constants(1.0, a, xi, ki, 0.0), xi[1]), 0.0);
        start(*m, xi, ki, f.sys, y);
        SolverConfig full = config(f);
        const GeodesicResult r_full = m->integrate(full, f.sys, y, 0.0, {});
        start(*m, xi, ki, f.sys, y);
        full.capture_radius = 1e3;
        const GeodesicResult r_cap = m->integrate(full, f.sys, y, 0.0, {});
        EXPECT_EQ(r_cap.reason, StopReason::Invalid) << stop_reason_name(r_cap.reason);
        if (f.sys == GeodesicSystem::Geodesic) {
          EXPECT_EQ(r_full.reason, StopReason::Invalid);
        }
        EXPECT_LT(r_cap.steps, r_full.steps);
      }
    }
  }
}

TEST(Capture, OnlyWhereNothingElseEndsTheFall) {
  // A ray straight at a Kerr hole (a = 0.9), Mino and coordinate form: GeoViS's open box
  // (±gpDBLMAX = 2⁶⁴) lets the capture stop it early; a box that ends above the break radius, a
  // limit on t, or a limit on the affine parameter could end the fall first, so there the ray
  // runs exactly as without capture.
  auto m = make_metric("KerrBL", {{"angmom", 0.9}, {"mass", 1.0}});
  const Vec4 x{{0, 50.0, 1.2, 0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), Vec3{-1, 0.01, 0.02}, true);
  const double gp_dbl_max = 1.844674407370955616e19;
  for (const Form& f : kForms) {
    SCOPED_TRACE(f.name);
    auto run = [&](SolverConfig cfg, double cr) {
      double y[kMaxSystemDim];
      start(*m, x, k, f.sys, y);
      cfg.capture_radius = cr;
      return m->integrate(cfg, f.sys, y, 0.0, {});
    };
    SolverConfig open = config(f);
    open.box_ll = Vec4{{-gp_dbl_max, 0, -gp_dbl_max, -gp_dbl_max}};
    open.box_ur = Vec4{{gp_dbl_max, 70, gp_dbl_max, gp_dbl_max}};
    const GeodesicResult early = run(open, 10.0);
    EXPECT_EQ(early.reason, StopReason::Invalid);
    EXPECT_LT(early.steps, run(open, 0.0).steps);
    SolverConfig above = open, t_limited = open, lambda_limited = open;
    above.box_ll[1] = 2.5;
    t_limited.box_ll[0] = -1e3;
    lambda_limited.lambda_max = 1e6;
    for (const SolverConfig& c : {above, t_limited, lambda_limited}) {
      const GeodesicResult with = run(c, 10.0), without = run(c, 0.0);
      EXPECT_EQ(with.reason, without.reason) << stop_reason_name(with.reason);
      EXPECT_EQ(with.steps, without.steps);
    }
    EXPECT_EQ(run(above, 10.0).reason, StopReason::BoundingBox);
  }
}

TEST(Capture, SphericalHolesStopOnlyRaysThatFallIn) {
  // Schwarzschild (coordinate form) and Reissner–Nordström with a horizon: random light rays
  // between the horizon and 1.5 times the photon sphere, both time orientations, integrated with
  // capture everywhere and without: the same stop reason for every ray, never more steps.
  // Naked Reissner–Nordström (|Q| > M) has no horizon and never captures.
  struct Case {
    const char* name;
    std::vector<std::pair<std::string, double>> params;
    double r_photon;
  };
  const Case cases[] = {
      {"Schwarzschild", {{"mass", 1.0}}, 3.0},
      {"ReissnerNordstrom", {{"mass", 1.0}, {"charge", 0.6}}, 0.5 * (3.0 + std::sqrt(9.0 - 8 * 0.36))},
      {"ReissnerNordstrom", {{"mass", 1.0}, {"charge", 0.9}}, 0.5 * (3.0 + std::sqrt(9.0 - 8 * 0.81))},
      {"ReissnerNordstrom", {{"mass", 1.0}, {"charge", 1.05}}, 0.5 * (3.0 + std::sqrt(9.0 - 8 * 1.1025))}};
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (const Case& c : cases) {
    auto m = make_metric(c.name, c.params);
    const bool naked = c.params.size() == 2 && c.params[1].second > 1.0;
    SCOPED_TRACE(testing::Message() << c.name << " " << c.params.back().second);
    int captured = 0;
    double r_lo = 0.01;
    while (!m->is_valid(Vec4{{0, r_lo, 1.0, 0}})) r_lo *= 1.01;
    for (int n = 0; n < 60; ++n) {
      const Vec4 x{{0, r_lo * 1.01 + (1.5 * c.r_photon - r_lo * 1.01) * U(rng), 0.3 + 2.5 * U(rng), 0.5}};
      const Vec3 d = normalize(Vec3{2 * U(rng) - 1, 2 * U(rng) - 1, 2 * U(rng) - 1});
      const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), d, n % 2 == 0);
      const auto [with, without, r_end] = with_and_without_capture(*m, x, k);
      EXPECT_EQ(with.reason, without.reason) << stop_reason_name(with.reason) << " r = " << x[1];
      EXPECT_LE(with.steps, without.steps);
      captured += with.steps < without.steps;
    }
    if (naked) {
      EXPECT_EQ(captured, 0);
    } else {
      EXPECT_GT(captured, 10);
    }
  }
}

TEST(Capture, EddFinkInStopsOnlyPastDirectedRaysThatFallIn) {
  // Schwarzschild in ingoing Eddington–Finkelstein coordinates (coordinate form, the packet's
  // and the scalar integrator's): random light rays between the horizon break band and 1.5 times
  // the photon sphere, both time orientations, integrated with capture everywhere and without:
  // the same stop reason for every ray and never more steps. Past-directed infalling rays (the
  // renderer's, E > 0) are captured and end where leaves_chart would end them (Invalid);
  // future-directed ones (E < 0) cross the horizon to the singularity and must not be captured
  // (the same steps as without).
  auto m = make_metric("EddFinkIn", {{"mass", 1.0}});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double r_band = 2.0 * (1.0 + m->horizon_eps());
  int captured_past = 0, captured_future = 0;
  for (int n = 0; n < 80; ++n) {
    const bool past = n % 2 == 0;
    const Vec4 x{{0, r_band * 1.01 + (4.5 - r_band * 1.01) * U(rng), 0.3 + 2.5 * U(rng), 0.5}};
    const Vec3 d = normalize(Vec3{2 * U(rng) - 1, 2 * U(rng) - 1, 2 * U(rng) - 1});
    const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), d, past);
    const auto [with, without, r_end] = with_and_without_capture(*m, x, k);
    SCOPED_TRACE(testing::Message() << (past ? "past" : "future") << "-directed, r = " << x[1] << ": "
                                    << stop_reason_name(with.reason) << " after " << with.steps << ", without "
                                    << stop_reason_name(without.reason) << " after " << without.steps);
    EXPECT_EQ(with.reason, without.reason);
    EXPECT_LE(with.steps, without.steps);
    if (with.steps < without.steps) {
      EXPECT_EQ(with.reason, StopReason::Invalid);
      EXPECT_GT(r_end, r_band);  // stopped outside the horizon, before leaves_chart would
      ++(past ? captured_past : captured_future);
    }
  }
  EXPECT_GT(captured_past, 10);
  EXPECT_EQ(captured_future, 0);
  // Integrated backwards (direction −1) nothing is captured: leaves_chart reads the stored k as
  // the direction of travel, so the capture's premise does not hold there.
  const Vec4 x{{0, 2.5, 1.0, 0.5}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), Vec3{-1, 0, 0}, false);
  SolverConfig cfg = config(kForms[1]);
  cfg.capture_radius = INFINITY;
  cfg.direction = -1.0;
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  const GeodesicResult back = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
  cfg.capture_radius = 0;
  double y0[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  EXPECT_EQ(back.steps, m->integrate(cfg, GeodesicSystem::Geodesic, y0, 0.0, {}).steps);
}
