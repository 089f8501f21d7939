// MorrisThorne, TeoSimpleWH, KastorTraschen, AlcubierreWarpSimple, EinsteinRosenWaveWWB,
// RotDihole, DeSitterUniv: closed-form Christoffel symbols and the integrator's acceleration
// against automatic differentiation at random valid points, orthonormal natural tetrads,
// parameter errors, and physics with independent expectations (throat crossing and chart switch,
// extreme Reissner-Nordström limit, de Sitter light propagation, vacuum field equations,
// geodesic Eulerian observers of the warp drive).
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "metric_checks.h"
#include "spacetime/metric_registry.h"
#include "support/uniform.h"

using namespace geovis;
namespace mc = geovis::metric_checks;

namespace {

using Params = std::vector<std::pair<std::string, double>>;

struct Sample {
  Params params;
  Vec4 x;
};

using geovis::testing_support::uni;

Vec3 random_unit(std::mt19937& rng) {
  const double z = uni(rng, -1, 1), ph = uni(rng, -M_PI, M_PI), s = std::sqrt(1 - z * z);
  return {s * std::cos(ph), s * std::sin(ph), z};
}

/// A random parameter set and a random valid point, per metric.
struct Case {
  std::string name;
  std::function<Sample(std::mt19937&)> sample;
  std::vector<TetradKind> tetrads;
};

Sample wormhole_sample(std::mt19937& rng) {
  return {{{"b0", uni(rng, 0.5, 2.0)}},
          Vec4{{uni(rng, -5, 5), uni(rng, -10, 10), uni(rng, 0.1, M_PI - 0.1), uni(rng, -M_PI, M_PI)}}};
}

/// Point at distance >= 0.3 from both centres c1, c2.
Vec3 away_from(std::mt19937& rng, const Vec3& c1, const Vec3& c2) {
  while (true) {
    const Vec3 p{uni(rng, -5, 5), uni(rng, -5, 5), uni(rng, -5, 5)};
    if (norm(p - c1) > 0.3 && norm(p - c2) > 0.3) return p;
  }
}

Sample kastor_sample(std::mt19937& rng) {
  Sample s;
  const double z1 = uni(rng, 1, 4), z2 = uni(rng, -4, -1);
  s.params = {{"h", uni(rng, -0.1, 0.1)}, {"m1", uni(rng, 0.2, 2)}, {"m2", uni(rng, 0.2, 2)}, {"z1", z1}, {"z2", z2}};
  const Vec3 p = away_from(rng, {0, 0, z1}, {0, 0, z2});
  s.x = Vec4{{uni(rng, -5, 5), p.x, p.y, p.z}};
  return s;
}

Sample rotdihole_sample(std::mt19937& rng) {
  Sample s;
  const double om = uni(rng, -1, 1), t = uni(rng, -5, 5);
  s.params = {{"mass1", uni(rng, 0.2, 2)}, {"mass2", uni(rng, 0.2, 2)}, {"omega", om}};
  const double sn = std::sin(om * t), cs = std::cos(om * t);
  const Vec3 p = away_from(rng, {0, -sn, cs}, {0, sn, -cs});
  s.x = Vec4{{t, p.x, p.y, p.z}};
  return s;
}

/// Alcubierre: two thirds of the points inside the bubble wall (where Γ != 0).
Sample alcubierre_sample(std::mt19937& rng, double vmax) {
  Sample s;
  const double R = uni(rng, 0.8, 2.0), dR = uni(rng, 0.1, 0.5), vs = uni(rng, -vmax, vmax);
  s.params = {{"dr", dR}, {"r", R}, {"vs", vs}};
  const double t = uni(rng, -5, 5);
  const double rs = uni(rng, 0, 3) < 2 ? uni(rng, R - 0.5 * dR, R + 0.5 * dR) : uni(rng, 0.05, 3 * R);
  const Vec3 n = random_unit(rng);
  s.x = Vec4{{t, vs * t + rs * n.x, rs * n.y, rs * n.z}};
  return s;
}

Sample erw_sample(std::mt19937& rng) {
  return {{{"a", uni(rng, 0.5, 2)}, {"c", uni(rng, -1.5, 1.5)}},
          Vec4{{uni(rng, -5, 5), uni(rng, 0.1, 8), uni(rng, -M_PI, M_PI), uni(rng, -5, 5)}}};
}

Sample desitter_sample(std::mt19937& rng) {
  return {{{"hubble", uni(rng, -0.5, 0.5)}},
          Vec4{{uni(rng, -3, 3), uni(rng, -10, 10), uni(rng, -10, 10), uni(rng, -10, 10)}}};
}

std::vector<Case> cases() {
  return {
      {"MorrisThorne", wormhole_sample, {TetradKind::Default, TetradKind::Static}},
      {"TeoSimpleWH", wormhole_sample, {TetradKind::Default, TetradKind::Static, TetradKind::LNRF}},
      {"KastorTraschen", kastor_sample, {TetradKind::Default, TetradKind::Static}},
      // |v_s| < 0.9 so that the static observer (|v_s f| < 1) exists everywhere.
      {"AlcubierreWarpSimple",
       [](std::mt19937& r) { return alcubierre_sample(r, 0.9); },
       {TetradKind::Default, TetradKind::Comoving, TetradKind::Static}},
      {"EinsteinRosenWaveWWB", erw_sample, {TetradKind::Default}},
      {"RotDihole", rotdihole_sample, {TetradKind::Default}},
      {"DeSitterUniv", desitter_sample, {TetradKind::Default, TetradKind::Static}},
  };
}

}  // namespace

TEST(MetricsOther, ClosedChristoffelAndAccelMatchAD) {
  std::mt19937 rng(42);
  for (const Case& c : cases()) {
    double worst_G = 0, worst_a = 0;
    for (int n = 0; n < 24; ++n) {
      const Sample s = c.sample(rng);
      auto m = make_metric(c.name, s.params);
      ASSERT_TRUE(m->is_valid(s.x)) << c.name;
      worst_G = std::max(worst_G, mc::expect_christoffel_matches_ad(*m, s.x));
      const Vec4 k{{1.0 + uni(rng, 0, 0.5), uni(rng, -1, 1), uni(rng, -1, 1), uni(rng, -1, 1)}};
      worst_a = std::max(worst_a, mc::expect_accel_matches_ad(*m, s.x, k));
      // and the closed-form symbols, of which a hand-written acceleration (KastorTraschen's,
      // MorrisThorne's) is the contraction.
      Christoffel G;
      m->christoffel(s.x, G);
      mc::expect_accel_matches_symbols(*m, s.x, k, G, "closed", 1e-10, 0.0);
    }
    std::printf("%-22s worst relative |Gamma_closed - Gamma_AD| = %.3g, |accel + Gamma_AD k k| = %.3g\n",
                c.name.c_str(), worst_G, worst_a);
  }
}

TEST(MetricsOther, AlcubierreFasterThanLightStillMatchesAD) {
  std::mt19937 rng(5);
  for (int n = 0; n < 20; ++n) {
    const Sample s = alcubierre_sample(rng, 3.0);
    auto m = make_metric("AlcubierreWarpSimple", s.params);
    mc::expect_christoffel_matches_ad(*m, s.x);
    mc::expect_orthonormal(*m, s.x, TetradKind::Comoving);
  }
}

TEST(MetricsOther, NaturalTetradsOrthonormal) {
  std::mt19937 rng(1234);
  for (const Case& c : cases()) {
    auto m0 = make_metric(c.name);
    for (TetradKind k : c.tetrads) EXPECT_TRUE(m0->supports_tetrad(k)) << c.name << " " << tetrad_kind_name(k);
    EXPECT_EQ(m0->info().tetrads.size(), c.tetrads.size()) << c.name;
    for (int n = 0; n < 20; ++n) {
      const Sample s = c.sample(rng);
      auto m = make_metric(c.name, s.params);
      for (TetradKind k : c.tetrads) mc::expect_orthonormal(*m, s.x, k);
    }
  }
}

TEST(MetricsOther, BadParametersAreErrors) {
  EXPECT_THROW(make_metric("MorrisThorne", {{"b0", 0.0}}), Error);
  EXPECT_THROW(make_metric("MorrisThorne", {{"b0", -1.0}}), Error);
  EXPECT_THROW(make_metric("MorrisThorne", {{"b", 1.0}}), Error);
  EXPECT_THROW(make_metric("TeoSimpleWH", {{"b0", 0.0}}), Error);
  EXPECT_THROW(make_metric("KastorTraschen", {{"m1", -1.0}}), Error);
  EXPECT_THROW(make_metric("KastorTraschen", {{"m2", -0.5}}), Error);
  EXPECT_THROW(make_metric("KastorTraschen", {{"h", NAN}}), Error);
  EXPECT_THROW(make_metric("AlcubierreWarpSimple", {{"r", 0.0}}), Error);
  EXPECT_THROW(make_metric("AlcubierreWarpSimple", {{"dr", -0.1}}), Error);
  EXPECT_THROW(make_metric("EinsteinRosenWaveWWB", {{"a", 0.0}}), Error);
  EXPECT_THROW(make_metric("RotDihole", {{"mass1", -1.0}}), Error);
  EXPECT_THROW(make_metric("DeSitterUniv", {{"hubble", INFINITY}}), Error);
  try {
    make_metric("DeSitterUniv", {{"hubbel", 0.1}});
    ADD_FAILURE() << "unknown key accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("hubble"), std::string::npos) << e.what();  // did you mean
  }
  // Unsupported tetrad kinds and places without the observer are clear errors.
  EXPECT_THROW(make_metric("RotDihole")->natural_tetrad(Vec4{{0, 3, 0, 0}}, TetradKind::Static), Error);
  EXPECT_THROW(make_metric("EinsteinRosenWaveWWB")->natural_tetrad(Vec4{{0, 0.0, 0, 0}}), Error);
  EXPECT_THROW(make_metric("KastorTraschen")->natural_tetrad(Vec4{{0, 0, 0, 1.0}}), Error);  // on hole 1
  // v_s = 1 at the bubble centre (f = 1): ∂_t is null, no static observer; the comoving one exists.
  auto warp = make_metric("AlcubierreWarpSimple");
  EXPECT_THROW(warp->natural_tetrad(Vec4{{0, 0, 0, 0}}, TetradKind::Static), Error);
  EXPECT_THROW(warp->natural_tetrad(Vec4{{0, 0, 0, 0}}, TetradKind::Default), Error);
  EXPECT_NO_THROW(warp->natural_tetrad(Vec4{{0, 0, 0, 0}}, TetradKind::Comoving));
}

TEST(MetricsOther, ValidityDomains) {
  auto kt = make_metric("KastorTraschen", {{"z1", 2.0}});
  EXPECT_FALSE(kt->is_valid(Vec4{{0, 0, 0, 2.0}}));
  EXPECT_TRUE(kt->is_valid(Vec4{{0, 0, 0, 2.1}}));
  auto rd = make_metric("RotDihole", {{"omega", M_PI / 2}});
  EXPECT_FALSE(rd->is_valid(Vec4{{1.0, 0, -1.0, 0.0}}));  // hole 1 at (0, −sin ωt, cos ωt) = (0, −1, 0)
  EXPECT_FALSE(rd->is_valid(Vec4{{1.0, 0, 1.0, 0.0}}));   // hole 2 at (0, 1, 0)
  EXPECT_TRUE(rd->is_valid(Vec4{{1.0, 0, 0.0, 1.0}}));
  EXPECT_FALSE(make_metric("EinsteinRosenWaveWWB")->is_valid(Vec4{{0, 0.0, 0, 0}}));
  EXPECT_FALSE(make_metric("MorrisThorne")->is_valid(Vec4{{0, 1.0, 0.0, 0}}));  // polar axis
  EXPECT_TRUE(make_metric("MorrisThorne")->is_valid(Vec4{{0, -1.0, 1.0, 0}}));
}

// ---- Morris-Thorne / Teo: throat crossing and charts ---------------------------------------------

TEST(MorrisThorne, RadialRayCrossesThroatAndSwitchesChart) {
  auto m = make_metric("MorrisThorne", {{"b0", 1.0}});
  const double l0 = 5.0;
  const Vec4 x0{{0.0, l0, M_PI / 2, 0.3}};
  const Tetrad e = m->natural_tetrad(x0);
  const Vec4 k = local_null_direction(e, Vec3{-1, 0, 0}, false);  // future-directed, inward
  double y[8] = {x0[0], x0[1], x0[2], x0[3], k[0], k[1], k[2], k[3]};
  Vec3 p;
  EXPECT_EQ(m->to_pseudo_cartesian(x0, p), 0);
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 100000;
  int first_chart = -1, last_chart = -1, switches = 0;
  double dev = 0, ang = 0;
  auto cb = [&](const StepView& s) {
    Vec3 q;
    const int chart = m->to_pseudo_cartesian(Vec4{{s.y1[0], s.y1[1], s.y1[2], s.y1[3]}}, q);
    if (first_chart < 0) first_chart = chart;
    if (last_chart >= 0 && chart != last_chart) ++switches;
    last_chart = chart;
    // Radial null ray with g_tt = −1, g_ll = 1: l(t) = l0 − t exactly, angles unchanged.
    dev = std::max(dev, std::fabs(s.y1[1] - (l0 - s.y1[0])));
    ang = std::max(ang, std::fabs(s.y1[2] - M_PI / 2) + std::fabs(s.y1[3] - 0.3));
    return s.y1[1] < -l0 ? StepAction::Stop : StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Callback);
  EXPECT_EQ(first_chart, 0);
  EXPECT_EQ(last_chart, 1);
  EXPECT_EQ(switches, 1);
  EXPECT_LT(y[1], -l0);
  EXPECT_LT(dev, 1e-10);
  EXPECT_LT(ang, 1e-12);
}

TEST(MorrisThorne, PseudoCartesianRoundTripBothCharts) {
  for (const char* name : {"MorrisThorne", "TeoSimpleWH", "TeoWHl"}) {
    auto m = make_metric(name);
    for (double l : {3.0, -3.0, 0.5, -0.5}) {
      const Vec4 x{{1.5, l, 1.1, -2.0}};
      Vec3 p;
      const int chart = m->to_pseudo_cartesian(x, p);
      EXPECT_EQ(chart, l > 0 ? 0 : 1);
      // Signed-l spherical map (Motion4D): the point of the second universe is point-reflected.
      EXPECT_NEAR(p.x, l * std::sin(1.1) * std::cos(-2.0), 1e-15);
      EXPECT_NEAR(p.z, l * std::cos(1.1), 1e-15);
      const Vec4 back = m->from_pseudo_cartesian(x[0], p, chart);
      for (int i = 0; i < 4; ++i) EXPECT_NEAR(back[i], x[i], 1e-14) << name << " l=" << l << " i=" << i;
    }
  }
}

TEST(TeoSimpleWH, LNRFHasZeroAngularMomentum) {
  // The locally non-rotating observer has u_φ = 0 (Bardeen et al. 1972), and ω = b0²/(2r³).
  auto m = make_metric("TeoSimpleWH", {{"b0", 1.3}});
  const Vec4 x{{0, 0.7, 1.0, 0.2}};
  const Tetrad e = m->natural_tetrad(x, TetradKind::LNRF);
  Mat4 g;
  m->metric_tensor(x, g);
  EXPECT_NEAR(g[3][0] * e[0][0] + g[3][3] * e[0][3], 0.0, 1e-15);
  const double r = std::sqrt(1.3 * 1.3 + 0.7 * 0.7);
  EXPECT_NEAR(e[0][3] / e[0][0], 1.3 * 1.3 / (2 * r * r * r), 1e-15);
}

// ---- Kastor-Traschen: extreme Reissner-Nordström limit -------------------------------------------

TEST(KastorTraschen, ReducesToExtremeReissnerNordstromIsotropic) {
  // ERN in isotropic coordinates: ds² = −dt²/(1 + M/ρ)² + (1 + M/ρ)² (dx² + dy² + dz²).
  const double M = 1.3, zc = 0.7;
  auto exact = make_metric("KastorTraschen", {{"h", 0.0}, {"m1", M}, {"m2", 0.0}, {"z1", zc}});
  const double far = 1e8;
  auto distant = make_metric("KastorTraschen", {{"h", 0.0}, {"m1", M}, {"m2", 1.0}, {"z1", zc}, {"z2", -far}});
  std::mt19937 rng(99);
  for (int n = 0; n < 20; ++n) {
    const Vec4 x{{uni(rng, -50, 50), uni(rng, -8, 8), uni(rng, -8, 8), uni(rng, -8, 8)}};
    const double rho = std::sqrt(x[1] * x[1] + x[2] * x[2] + (x[3] - zc) * (x[3] - zc));
    const double U = 1.0 + M / rho;
    const double ern[4] = {-1.0 / (U * U), U * U, U * U, U * U};
    Mat4 g, gd;
    exact->metric_tensor(x, g);
    distant->metric_tensor(x, gd);
    // The far hole changes Ω by ε = m2/r2 <= 1/(far − 20), hence g by a relative 2ε (+ O(ε²)).
    const double eps = 1.0 / (far - 20.0);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const double ref = i == j ? ern[i] : 0.0;
        EXPECT_NEAR(g[i][j], ref, 1e-14 * std::fabs(ern[i]));
        EXPECT_NEAR(gd[i][j], ref, 2.0 * eps * (1 + eps) * std::fabs(ern[i]));
      }
  }
}

namespace {
/// GeoViS's kastorTraschen.scm: H = 0.02, m1 = m2 = 1 at z = ±4, the observer at rest at x = 40,
/// Cash–Karp at eps_abs 1e-12, maxNumPoints 6000, box ±200. Integrates the backward light ray
/// leaving the observer in local direction d.
GeodesicResult kastor_scene_ray(const Metric& m, const Vec3& d, double* y) {
  const Vec4 obs{{0, 40, 0, 0}};
  const Vec4 k = local_null_direction(m.natural_tetrad(obs), d, true);
  for (int i = 0; i < 4; ++i) y[i] = obs[i], y[4 + i] = k[i];
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.step_size = 0.01;
  cfg.max_steps = 6000;
  cfg.box_ll = Vec4{{-DBL_MAX, -200, -200, -200}};
  cfg.box_ur = Vec4{{DBL_MAX, 200, 200, 200}};
  return m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
}
double kastor_omega(const Vec4& x, double h) {
  const double r1 = std::sqrt(x[1] * x[1] + x[2] * x[2] + (x[3] - 4) * (x[3] - 4));
  const double r2 = std::sqrt(x[1] * x[1] + x[2] * x[2] + (x[3] + 4) * (x[3] + 4));
  return 1.0 + (1.0 / r1 + 1.0 / r2) / std::exp(h * x[0]);
}
const Params kKastorScene = {{"h", 0.02}, {"m1", 1.0}, {"m2", 1.0}, {"z1", 4.0}, {"z2", -4.0}};
}  // namespace

TEST(KastorTraschen, RayIntoAHoleStopsAtTheRedshiftMargin) {
  // Aimed at hole 1: the ray's comoving distance from the hole freezes while t → −∞ (the horizon
  // a r_1 → 0); before the Ω margin it ran to maxNumPoints (docs/PERFORMANCE.md). It must now
  // stop with Invalid (horizon), long before the step budget, where 1/Ω² reaches horizon_eps.
  auto m = make_metric("KastorTraschen", kKastorScene);
  double y[8];
  const GeodesicResult r = kastor_scene_ray(*m, Vec3{-40, 0, 4}, y);
  EXPECT_EQ(r.reason, StopReason::Invalid);
  EXPECT_LT(r.steps, 6000 / 3);  // before: all 6000
  const double om = kastor_omega(Vec4{{y[0], y[1], y[2], y[3]}}, 0.02);
  const double om_break = 1.0 / std::sqrt(m->horizon_eps());  // 100
  EXPECT_LE(om, om_break);
  EXPECT_GT(om, 0.5 * om_break) << "stopped before the margin";
}

TEST(KastorTraschen, RayFarFromTheHolesIsUnaffectedByTheMargin) {
  // Passing ~24 from the origin (the holes at z = ±4): the same steps and end as with a margin so
  // small (1e-300) that it never fires.
  auto m = make_metric("KastorTraschen", kKastorScene);
  auto no_margin = make_metric("KastorTraschen", kKastorScene);
  no_margin->set_horizon_eps(1e-300);
  double y[8], y0[8];
  const GeodesicResult r = kastor_scene_ray(*m, Vec3{-40, 30, 0}, y);
  const GeodesicResult r0 = kastor_scene_ray(*no_margin, Vec3{-40, 30, 0}, y0);
  EXPECT_EQ(r.reason, StopReason::BoundingBox);
  EXPECT_EQ(r.reason, r0.reason);
  EXPECT_EQ(r.steps, r0.steps);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(y[i], y0[i]);
}

TEST(KastorTraschen, ValidWhereverOmegaIsModerate) {
  // The margin cuts only where Ω > 1/√horizon_eps = 100: every point with Ω < 99 (random times
  // and places, both holes) stays valid, every point with Ω > 101 is not.
  auto m = make_metric("KastorTraschen", kKastorScene);
  std::mt19937 rng(13);
  int moderate = 0, large = 0;
  for (int n = 0; n < 4000; ++n) {
    const Vec4 x{{uni(rng, -400, 50), uni(rng, -6, 6), uni(rng, -6, 6), uni(rng, -10, 10)}};
    const double om = kastor_omega(x, 0.02);
    if (om < 99) {
      ++moderate;
      EXPECT_TRUE(m->is_valid(x)) << "Ω = " << om;
    } else if (om > 101) {
      ++large;
      EXPECT_FALSE(m->is_valid(x)) << "Ω = " << om;
    }
  }
  EXPECT_GT(moderate, 100);
  EXPECT_GT(large, 100);
}

// ---- de Sitter: light propagation and Λ -----------------------------------------------------------

TEST(DeSitterUniv, RadialLightRayComovingDistanceIsAnalytic) {
  const double H = 0.3, t0 = 0.5, x0 = 1.0;
  auto m = make_metric("DeSitterUniv", {{"hubble", H}});
  const Vec4 xs{{t0, x0, 0.0, 0.0}};
  const Tetrad e = m->natural_tetrad(xs);
  const Vec4 k = local_null_direction(e, Vec3{1, 0, 0}, false);
  double y[8] = {xs[0], xs[1], xs[2], xs[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 100000;
  double dx = 0, dkt = 0, dyz = 0;
  int steps = 0;
  auto cb = [&](const StepView& s) {
    const double t = s.y1[0];
    // χ(t) = χ0 + (e^{−H t0} − e^{−H t})/H; cosmological redshift k^t ∝ 1/a(t) = e^{−H t}.
    dx = std::max(dx, std::fabs(s.y1[1] - (x0 + (std::exp(-H * t0) - std::exp(-H * t)) / H)));
    dkt = std::max(dkt, std::fabs(s.y1[4] - k[0] * std::exp(-H * (t - t0))) / k[0]);
    dyz = std::max(dyz, std::fabs(s.y1[2]) + std::fabs(s.y1[3]));
    ++steps;
    return t > 8.0 ? StepAction::Stop : StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  std::printf("DeSitterUniv radial ray: %d steps, max |chi - chi_analytic| = %.3g, k^t rel %.3g\n", steps, dx, dkt);
  EXPECT_EQ(r.reason, StopReason::Callback);
  EXPECT_GT(y[0], 8.0);
  EXPECT_LT(dx, 1e-9);
  EXPECT_LT(dkt, 1e-9);
  EXPECT_EQ(dyz, 0.0);
}

TEST(DeSitterUniv, RicciIsLambdaTimesMetric) {
  // de Sitter is a vacuum solution with Λ = 3H²: R_ab = Λ g_ab.
  const double H = 0.4;
  auto m = make_metric("DeSitterUniv", {{"hubble", H}});
  const Vec4 x{{0.7, 1.0, -2.0, 3.0}};
  const Mat4 ric = mc::ricci(*m, x);
  Mat4 g;
  m->metric_tensor(x, g);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) EXPECT_NEAR(ric[a][b], 3 * H * H * g[a][b], 1e-12 * std::fabs(3 * H * H * g[1][1]));
}

// ---- Einstein-Rosen wave: vacuum -------------------------------------------------------------------

TEST(EinsteinRosenWaveWWB, RicciFlat) {
  // The Weber-Wheeler-Bonnor pulse is an exact vacuum solution: the Ricci tensor vanishes.
  auto m = make_metric("EinsteinRosenWaveWWB", {{"a", 1.2}, {"c", 0.8}});
  for (const Vec4& x : {Vec4{{0.0, 0.5, 0.0, 0.0}}, Vec4{{1.0, 1.0, 1.0, 2.0}}, Vec4{{3.0, 2.5, -1.0, 0.0}},
                        Vec4{{-2.0, 4.0, 2.0, -3.0}}}) {
    double scale = 0;
    const Mat4 ric = mc::ricci(*m, x, &scale);
    double worst = 0;
    for (int b = 0; b < 4; ++b)
      for (int d = 0; d < 4; ++d) {
        worst = std::max(worst, std::fabs(ric[b][d]) / scale);
        EXPECT_LE(std::fabs(ric[b][d]), 1e-9 * scale) << "R_" << b << d << " at t=" << x[0] << " rho=" << x[1];
      }
    std::printf("EinsteinRosenWaveWWB t=%g rho=%g: max |R_ab| / max |R^a_bcd| = %.3g\n", x[0], x[1], worst);
  }
}

// ---- Alcubierre: Eulerian observers are geodesics ---------------------------------------------------

TEST(AlcubierreWarpSimple, EulerianObserversAreGeodesics) {
  // With unit lapse the Eulerian (comoving) observers u = ∂_t + v_s f ∂_x are geodesic
  // (Alcubierre 1994): a timelike geodesic started with u keeps u^t = 1, u^y = u^z = 0 and
  // u^x = v_s f(r_s) along its path, and proper time equals coordinate time.
  const double R = 1.0, dR = 0.4, vs = 0.8;
  auto m = make_metric("AlcubierreWarpSimple", {{"r", R}, {"dr", dR}, {"vs", vs}});
  auto f = [&](double t, double x, double y, double z) {  // shape function, from its definition
    const double rs = std::sqrt((x - vs * t) * (x - vs * t) + y * y + z * z);
    const double R1 = R - dR / 2;
    if (rs <= R1) return 1.0;
    if (rs >= R + dR / 2) return 0.0;
    const double w = (rs - R1) / dR;
    return (1 - w * w) * (1 - w * w);
  };
  const Vec4 x0{{0.0, 0.3, 0.85, 0.2}};  // inside the wall
  const Tetrad e = m->natural_tetrad(x0, TetradKind::Comoving);
  double y[8] = {x0[0], x0[1], x0[2], x0[3], e[0][0], e[0][1], e[0][2], e[0][3]};
  SolverConfig cfg;
  cfg.type = GeodesicType::Timelike;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 100000;
  double dev = 0;
  auto cb = [&](const StepView& s) {
    const double* q = s.y1;
    dev = std::max({dev, std::fabs(q[4] - 1.0), std::fabs(q[5] - vs * f(q[0], q[1], q[2], q[3])), std::fabs(q[6]),
                    std::fabs(q[7]), std::fabs(q[0] - s.lambda1)});
    return s.lambda1 > 3.0 ? StepAction::Stop : StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Callback);
  EXPECT_LT(dev, 1e-9);
}

// ---- Electrovacuum checks: the Maxwell stress tensor is traceless --------------------------------

namespace {

/// Ricci scalar R = g^{ab} R_ab (AD Riemann) and the largest Riemann component for scale.
double ricci_scalar(const Metric& m, const Vec4& x, double& riemann_scale) {
  const Mat4 ric = mc::ricci(m, x, &riemann_scale);
  Mat4 g;
  m.metric_tensor(x, g);
  const Mat4 gi = invert(g);
  double R = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) R += gi[a][b] * ric[a][b];
  return R;
}

}  // namespace

TEST(KastorTraschen, RicciScalarIsFourLambda) {
  // Einstein-Maxwell with Λ = 3H² (Kastor & Traschen 1993): the trace of G_ab + Λ g_ab = 8π T_ab
  // with traceless T_ab gives R = 4Λ = 12 H².
  for (double H : {0.0, 0.05, -0.1}) {
    auto m = make_metric("KastorTraschen", {{"h", H}, {"m1", 1.0}, {"m2", 0.7}, {"z1", 2.0}, {"z2", -1.5}});
    for (const Vec4& x : {Vec4{{0.0, 1.0, 0.5, 0.3}}, Vec4{{2.0, -3.0, 1.0, 2.5}}, Vec4{{-4.0, 0.2, -0.4, -1.0}}}) {
      double scale = 0;
      const double R = ricci_scalar(*m, x, scale);
      EXPECT_NEAR(R, 12 * H * H, 1e-10 * std::max(scale, 12 * H * H)) << "H=" << H << " t=" << x[0];
    }
  }
}

TEST(RotDihole, StaticDiholeIsElectrovacuum) {
  // ω = 0: Majumdar-Papapetrou dihole, an Einstein-Maxwell solution, so R = 0.
  auto m = make_metric("RotDihole", {{"mass1", 1.0}, {"mass2", 0.5}, {"omega", 0.0}});
  for (const Vec4& x : {Vec4{{0.0, 0.5, 0.3, 0.2}}, Vec4{{1.0, -2.0, 1.0, 3.0}}, Vec4{{0.0, 0.1, -0.2, -1.4}}}) {
    double scale = 0;
    const double R = ricci_scalar(*m, x, scale);
    EXPECT_LE(std::fabs(R), 1e-10 * scale) << "x=" << x[1] << " y=" << x[2] << " z=" << x[3];
  }
}
