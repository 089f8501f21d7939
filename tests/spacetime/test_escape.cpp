// StopReason::Escaped (spacetime/escape.h): which metrics declare it, that the photon-sphere radii
// they use are the critical points of h² = C/A of their own metric tensor, and that a ray stopped
// as escaped never turns back when it is followed further.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "spacetime/kerr_mino.h"
#include "spacetime/metric_registry.h"

using namespace geovis;

namespace {

struct Case {
  const char* name;
  std::vector<std::pair<std::string, double>> params;
  bool separable = true;
};

/// Radial coordinate of x as the escape test measures it (|p|) and the position at radial
/// coordinate q in the equatorial plane / on the x axis.
bool cartesian_chart(const Metric& m) { return m.info().coord_type == CoordType::Cartesian; }
Vec4 at_radius(const Metric& m, double q) {
  return cartesian_chart(m) ? Vec4{{0, q, 0, 0}} : Vec4{{0, q, 0.5 * std::numbers::pi, 0}};
}
double p_norm(const Metric& m, const double* y) {
  Vec3 p;
  m.to_pseudo_cartesian(Vec4{{y[0], y[1], y[2], y[3]}}, p);
  return norm(p);
}
/// h² = C/A at radial coordinate q from the metric tensor (C = g_φφ at θ = π/2, resp. g_yy q² on
/// the x axis; A = −g_tt). EddFinkIn/PG are not diagonal in t: A = −g_00 still (1 − r_s/r).
double h2(const Metric& m, double q) {
  Mat4 g;
  m.metric_tensor(at_radius(m, q), g);
  const double C = cartesian_chart(m) ? g[2][2] * q * q : g[3][3];
  return C / -g[0][0];
}

}  // namespace

TEST(Escape, DeclaredByTheAsymptoticallyFlatMetrics) {
  const std::set<std::string> flat = {"Minkowski",
                                      "Schwarzschild",
                                      "SchwarzschildCart",
                                      "SchwarzschildIsotropic",
                                      "EddFinkIn",
                                      "PainleveGullstrand",
                                      "KerrBL",
                                      "ReissnerNordstrom",
                                      "JanisNewmanWinicour",
                                      "MorrisThorne",
                                      "Kruskal"};
  for (const std::string& n : metric_names()) {
    if (n == "Kottler") continue;
    EXPECT_EQ(make_metric(n)->asymptotically_flat(), flat.count(n) == 1) << n;
  }
  // Kottler: only without the cosmological constant.
  EXPECT_FALSE(make_metric("Kottler", {{"lambda", 0.01}})->asymptotically_flat());
  EXPECT_FALSE(make_metric("Kottler", {{"lambda", -0.01}})->asymptotically_flat());
  EXPECT_TRUE(make_metric("Kottler", {{"lambda", 0.0}})->asymptotically_flat());
}

TEST(Escape, OutwardRadialRayStopsJustOutsideTheOutermostPhotonSphere) {
  // An outward radial light ray started inside the photon sphere (static observer, backward
  // trace as the renderer) with small steps must stop as escaped at the first step end beyond the
  // outermost critical point of h² = C/A, found here numerically from the metric tensor.
  const std::vector<Case> cases = {
      {"Schwarzschild", {{"mass", 1.3}}, false},
      {"SchwarzschildCart", {{"mass", 0.7}}},
      {"SchwarzschildIsotropic", {{"mass", 1.0}}},
      {"EddFinkIn", {{"mass", 1.0}}},
      {"PainleveGullstrand", {{"mass", 1.0}}},
      {"ReissnerNordstrom", {{"mass", 1.0}, {"charge", 0.8}}},
      {"ReissnerNordstrom", {{"mass", 1.0}, {"charge", 1.05}}},  // naked, still a photon sphere
      {"ReissnerNordstrom", {{"mass", 1.0}, {"charge", 1.2}}},   // naked, 8Q² > 9M²: none
      {"JanisNewmanWinicour", {{"mass", 1.0}, {"gamma", 0.8}}},
      {"JanisNewmanWinicour", {{"mass", 1.0}, {"gamma", 0.4}}},  // none outside the singularity
      {"Kottler", {{"mass", 1.0}, {"lambda", 0.0}}},
      {"Minkowski", {}},
  };
  for (const Case& c : cases) {
    auto m = make_metric(c.name, c.params);
    SCOPED_TRACE(testing::Message() << c.name << " " << (c.params.empty() ? 0.0 : c.params.back().second));
    // Outermost critical point of h² by scanning inward from q = 50 (h² grows beyond it).
    double q_edge = 1e-6;
    while (!m->is_valid(at_radius(*m, q_edge))) q_edge *= 1.01;  // validity edge (horizon / singularity)
    q_edge *= 1.02;
    double q_ph = q_edge;
    for (double q = 50; q > q_edge; q *= 0.9999)
      if (h2(*m, q * 0.9999) >= h2(*m, q)) {
        q_ph = q;
        break;
      }
    const double q0 = q_ph > q_edge ? std::max(q_edge, 0.9 * q_ph) : std::max(2 * q_edge, 1.0);
    const Vec4 x = at_radius(*m, q0);
    const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
    const Vec4 k = local_null_direction(e, Vec3{1, 0, 0}, true);  // past-directed, outward
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    SolverConfig cfg;
    cfg.kind = SolverKind::DormandPrince853;
    cfg.eps_abs = 1e-10;
    cfg.separable = c.separable;
    cfg.step_max = 1e-3;
    cfg.max_steps = 1000000;
    cfg.escape_radius = 0;
    double last_start = 0;
    auto cb = [&](const StepView& s) {
      last_start = p_norm(*m, s.y0);
      return StepAction::Continue;
    };
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
    ASSERT_EQ(r.reason, StopReason::Escaped) << stop_reason_name(r.reason);
    EXPECT_NEAR(r.escape_radius, p_norm(*m, y), 1e-12 * r.escape_radius);
    if (q_ph > q_edge) {
      EXPECT_GT(r.escape_radius, q_ph * (1 - 1e-4));
      EXPECT_LE(last_start, q_ph * (1 + 1e-4));
    } else {
      EXPECT_EQ(r.steps, 1);  // no photon sphere: escaped at once
    }
  }
}

TEST(Escape, MorrisThorneRaysEscapeIntoEitherUniverse) {
  auto m = make_metric("MorrisThorne", {{"b0", 1.0}});
  for (const double l0 : {-3.0, -0.2, 0.2, 3.0}) {
    for (const double dir : {-1.0, 1.0}) {
      const Vec4 x{{0, l0, 1.1, 0.3}};
      const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), Vec3{dir, 0.01, 0}, true);
      double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
      SolverConfig cfg;
      cfg.eps_abs = 1e-10;
      cfg.step_max = 0.05;
      cfg.escape_radius = 1.0;
      const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
      ASSERT_EQ(r.reason, StopReason::Escaped) << "l0 = " << l0 << " dir " << dir;
      EXPECT_GT(std::fabs(y[1]), 1.0);
      EXPECT_LT(std::fabs(y[1]), std::max(1.2, std::fabs(l0) + 0.1));
      EXPECT_EQ(r.escape_radius, std::fabs(y[1]));
      EXPECT_EQ(y[1] > 0, dir > 0) << "l0 = " << l0;  // k^l = +e_(1): the universe it heads for
    }
  }
}

TEST(Escape, EscapedRaysNeverTurnBack) {
  // Random light rays (both time orientations) in every metric that declares escape, KerrBL in
  // both forms: when a ray stops as escaped, following it further (escape off) to 1e4 times the
  // radius must never bring it closer to the origin.
  const std::vector<Case> cases = {
      {"Schwarzschild", {}, true},
      {"Schwarzschild", {}, false},
      {"KerrBL", {{"angmom", 0.9}}, true},
      {"KerrBL", {{"angmom", -0.998}}, true},
      {"KerrBL", {{"angmom", 0.7}}, false},
      {"SchwarzschildCart", {}},
      {"SchwarzschildIsotropic", {}},
      {"ReissnerNordstrom", {{"charge", 0.9}}},
      {"ReissnerNordstrom", {{"charge", 1.1}}},
      {"JanisNewmanWinicour", {{"gamma", 0.7}}},
      {"JanisNewmanWinicour", {{"gamma", 0.3}}},
      {"MorrisThorne", {}},
      {"Minkowski", {}},
      {"PainleveGullstrand", {}},
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int escaped = 0, turned = 0;
  for (const Case& c : cases) {
    auto m = make_metric(c.name, c.params);
    SCOPED_TRACE(testing::Message() << c.name << (c.separable ? "" : " (coordinate form)"));
    for (int n = 0; n < 40; ++n) {
      const bool cart = cartesian_chart(*m);
      const double q = c.name == std::string("MorrisThorne") ? 8 * U(rng) - 4 : 2.5 + 10 * U(rng);
      const double th = 0.3 + (std::numbers::pi - 0.6) * U(rng), ph = 2 * std::numbers::pi * U(rng);
      const Vec4 x = cart
                         ? Vec4{{0, q * std::sin(th) * std::cos(ph), q * std::sin(th) * std::sin(ph), q * std::cos(th)}}
                         : Vec4{{0, q, th, ph}};
      if (!m->is_valid(x)) continue;
      const Vec3 d = normalize(Vec3{2 * U(rng) - 1, 2 * U(rng) - 1, 2 * U(rng) - 1});
      const bool backward = n % 2 == 0;
      const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), d, backward);
      double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
      SolverConfig cfg;
      cfg.kind = SolverKind::DormandPrince853;
      cfg.eps_abs = 1e-10;
      cfg.separable = c.separable;
      cfg.max_steps = 100000;
      cfg.escape_radius = 0;
      double pmin_seen = 1e300, prev = p_norm(*m, y);
      bool turned_here = false;
      auto watch = [&](const StepView& s) {
        const double p = p_norm(*m, s.y1);
        if (p < prev) turned_here = true;  // moving inward at some point before the escape
        prev = p;
        pmin_seen = std::min(pmin_seen, p);
        return StepAction::Continue;
      };
      const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, watch);
      if (r.reason != StopReason::Escaped) {
        // Into the hole or the singularity (the horizon-free charts may also end there by step
        // underflow or max-steps). JNW stops at Motion4D's break radius r_s (1 + γ)²/(4γ²) outside
        // its singularity r = 2M/γ (9.39M for γ = 0.3, 2.17M for γ = 0.7; M = 1); the state is the
        // last accepted one before the break, within its (small) last step: 1 % above the radius.
        double r_end = 7.0;
        if (c.name == std::string("JanisNewmanWinicour")) {
          const double g = c.params.at(0).second, f = (1 + g) / (2 * g);
          r_end = std::max(r_end, 1.01 * 2.0 * f * f);
        }
        EXPECT_LE(p_norm(*m, y), r_end) << stop_reason_name(r.reason);
        continue;
      }
      ++escaped;
      if (turned_here) ++turned;
      const double p_escape = p_norm(*m, y);
      EXPECT_NEAR(r.escape_radius, p_escape, 1e-12 * p_escape);
      cfg.escape_radius = INFINITY;
      cfg.lambda_max = 1e6 * (1 + p_escape);
      double p_prev = p_escape, worst = 0;
      auto outward = [&](const StepView& s) {
        const double p = p_norm(*m, s.y1);
        worst = std::max(worst, (p_prev - p) / p_prev);
        p_prev = p;
        return p > 1e4 * p_escape ? StepAction::Stop : StepAction::Continue;
      };
      const GeodesicResult r2 = m->integrate(cfg, GeodesicSystem::Geodesic, y, r.lambda, outward);
      EXPECT_EQ(r2.reason, StopReason::Callback) << stop_reason_name(r2.reason);
      EXPECT_LE(worst, 1e-12) << "ray " << n << " came back after escaping at " << p_escape;
    }
  }
  std::printf("escape: %d rays escaped, %d of them after turning outward on the way\n", escaped, turned);
  EXPECT_GT(escaped, 200);
  EXPECT_GT(turned, 20);
}

TEST(Escape, KerrPotentialTestIsThePhotonSphereForSchwarzschild) {
  // a = 0: every outward light ray beyond r = 3M has R > 0, R' > 0, R'' > 0 (kerr_mino.h), so it
  // escapes at its first step; random directions, r just above 3M.
  auto m = make_metric("KerrBL", {{"angmom", 0.0}, {"mass", 1.0}});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int n = 0; n < 200; ++n) {
    const Vec4 x{{0, 3.0 * (1 + 1e-6) + 5 * U(rng) * U(rng), 0.2 + 2.7 * U(rng), 0}};
    Vec3 d = normalize(Vec3{U(rng), 2 * U(rng) - 1, 2 * U(rng) - 1});
    const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), d, true);
    const KerrMinoConstants c = kerr_mino_constants(1.0, 0.0, x, k, 0.0);
    EXPECT_TRUE(c.no_radial_turning_point_beyond(x[1])) << "r = " << x[1];
  }
  // And inside the photon sphere a ray that turns back (periastron below 3M is impossible, so:
  // apoastron) exists: tangential at r = 2.9M it falls in; its R' < 0 there.
  const Vec4 x{{0, 2.9, 0.5 * std::numbers::pi, 0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Default), Vec3{1e-3, 0, 1}, true);
  EXPECT_FALSE(kerr_mino_constants(1.0, 0.0, x, k, 0.0).no_radial_turning_point_beyond(2.9));
  // Bound timelike orbits (E < 1) never escape.
  const Vec4 u = local_four_velocity(m->natural_tetrad(Vec4{{0, 20, 1.5, 0}}, TetradKind::Default), Vec3{0.1, 0, 0.2});
  EXPECT_FALSE(kerr_mino_constants(1.0, 0.0, Vec4{{0, 20, 1.5, 0}}, u, 1.0).no_radial_turning_point_beyond(20));
}
