// Tests of the Schwarzschild-family and other spherically symmetric metrics (engineer metrics-a):
// SchwarzschildCart, SchwarzschildIsotropic, EddFinkIn, PainleveGullstrand, ReissnerNordstrom,
// Kottler, BarriolaVilenkin, JanisNewmanWinicour, Ernst, TaubNUT.
//
// For every metric: the closed-form Christoffel symbols equal the automatic-differentiation ones
// at random valid points; every supported natural tetrad is orthonormal with a future-directed
// e_(0); bad parameters give an Error. Plus one independent physics check per metric against an
// analytic result (photon spheres, radial light travel times, null/free-fall coordinates).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "metric_checks.h"
#include "spacetime/metric_registry.h"

using namespace geovis;

namespace {

using Params = std::vector<std::pair<std::string, double>>;
using Sampler = std::function<Vec4(std::mt19937&)>;

double uniform(std::mt19937& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

/// Spherical-chart point with r in [r0, r1], θ away from the axis.
Sampler spherical(double r0, double r1) {
  return [=](std::mt19937& rng) {
    return Vec4{
        {uniform(rng, -5, 5), uniform(rng, r0, r1), uniform(rng, 0.15, M_PI - 0.15), uniform(rng, 0, 2 * M_PI)}};
  };
}
/// Cartesian-chart point at distance in [r0, r1] from the origin, random direction.
Sampler cartesian(double r0, double r1) {
  return [=](std::mt19937& rng) {
    const double r = uniform(rng, r0, r1), ct = uniform(rng, -1, 1), ph = uniform(rng, 0, 2 * M_PI);
    const double st = std::sqrt(1 - ct * ct);
    return Vec4{{uniform(rng, -5, 5), r * st * std::cos(ph), r * st * std::sin(ph), r * ct}};
  };
}

struct SphericalCase {
  std::string name;
  Params params;
  Sampler christoffel_points;  ///< valid points of the chart (may be inside a horizon)
  Sampler static_points;       ///< points where every supported tetrad is defined
};

std::vector<SphericalCase> spherical_cases() {
  return {
      {"SchwarzschildCart", {{"mass", 1.3}}, cartesian(2.7, 30), cartesian(2.7, 30)},
      {"SchwarzschildIsotropic", {{"mass", 1.3}}, cartesian(0.7, 30), cartesian(0.7, 30)},
      // Inside and outside the horizon r_s = 2.6: the chart is regular across it.
      {"EddFinkIn", {{"mass", 1.3}}, spherical(0.3, 30), spherical(2.7, 30)},
      {"PainleveGullstrand", {{"mass", 1.3}}, spherical(0.3, 30), spherical(2.7, 30)},
      {"ReissnerNordstrom", {{"mass", 1.0}, {"charge", 0.7}}, spherical(1.75, 30), spherical(1.75, 30)},
      {"ReissnerNordstrom", {{"mass", 0.5}, {"charge", 0.8}}, spherical(0.05, 30), spherical(0.05, 30)},
      {"Kottler", {{"mass", 1.0}, {"lambda", 0.05}}, spherical(2.5, 6.2), spherical(2.5, 6.2)},
      {"Kottler", {{"mass", 1.0}, {"lambda", -0.3}}, spherical(1.7, 40), spherical(1.7, 40)},
      {"BarriolaVilenkin", {{"k", 0.7}}, spherical(0.1, 30), spherical(0.1, 30)},
      // Motion4D's break radius r_s (1 + γ)²/(4γ²) = 3.56 for γ = 0.6.
      {"JanisNewmanWinicour", {{"mass", 1.0}, {"gamma", 0.6}}, spherical(3.6, 30), spherical(3.6, 30)},
      {"JanisNewmanWinicour", {{"mass", 1.0}, {"gamma", 1.0}}, spherical(2.1, 30), spherical(2.1, 30)},
      {"Ernst", {{"mass", 1.0}, {"b", 0.1}}, spherical(2.1, 20), spherical(2.1, 20)},
      {"TaubNUT", {{"mass", 1.0}, {"l", 0.5}}, spherical(2.2, 30), spherical(2.2, 30)},
      {"TaubNUT", {{"mass", 0.3}, {"l", -1.5}}, spherical(2.0, 30), spherical(2.0, 30)},
  };
}

std::string label(const SphericalCase& c) {
  std::string s = c.name;
  for (const auto& [k, v] : c.params) s += " " + k + "=" + std::to_string(v);
  return s;
}

}  // namespace

// ---- registry / catalogue §12 -----------------------------------------------------------------

TEST(MetricsSpherical, CatalogueNamesCoordinatesDefaultsAndTetrads) {
  struct Expect {
    std::string name;
    std::array<std::string, 4> coords;
    Params defaults;
    std::vector<TetradKind> tetrads;
  };
  using TK = TetradKind;
  const std::vector<Expect> expect = {
      {"SchwarzschildCart", {"t", "x", "y", "z"}, {{"mass", 1}}, {TK::Default, TK::Static}},
      {"SchwarzschildIsotropic", {"t", "x", "y", "z"}, {{"mass", 1}}, {TK::Default, TK::Static}},
      {"EddFinkIn", {"v", "r", "theta", "phi"}, {{"mass", 1}}, {TK::Default, TK::Static, TK::Freefall}},
      {"PainleveGullstrand", {"T", "r", "theta", "phi"}, {{"mass", 1}}, {TK::Default, TK::Static, TK::Freefall}},
      {"ReissnerNordstrom", {"t", "r", "theta", "phi"}, {{"charge", 0.1}, {"mass", 1}}, {TK::Default, TK::Static}},
      {"Kottler", {"t", "r", "theta", "phi"}, {{"lambda", 0.05}, {"mass", 1}}, {TK::Default, TK::Static}},
      {"BarriolaVilenkin", {"t", "r", "theta", "phi"}, {{"k", 0.8}}, {TK::Default, TK::Static}},
      {"JanisNewmanWinicour", {"t", "r", "theta", "phi"}, {{"gamma", 1}, {"mass", 1}}, {TK::Default}},
      {"Ernst", {"t", "r", "theta", "phi"}, {{"b", 0.1}, {"mass", 1}}, {TK::Default, TK::Static}},
      {"TaubNUT", {"t", "r", "theta", "phi"}, {{"l", 0.5}, {"mass", 1}}, {TK::Default, TK::Static}},
  };
  for (const auto& e : expect) {
    auto m = make_metric(e.name);
    EXPECT_EQ(m->name(), e.name);
    EXPECT_EQ(m->info().coords, e.coords) << e.name;
    ASSERT_EQ(m->info().params.size(), e.defaults.size()) << e.name;
    for (size_t i = 0; i < e.defaults.size(); ++i) {
      EXPECT_EQ(m->info().params[i].name, e.defaults[i].first) << e.name;
      EXPECT_EQ(m->param(e.defaults[i].first), e.defaults[i].second) << e.name;
    }
    EXPECT_EQ(m->info().tetrads, e.tetrads) << e.name;
    EXPECT_TRUE(m->has_closed_form_christoffel()) << e.name;
  }
}

// ---- closed-form Γ against automatic differentiation -------------------------------------------

TEST(MetricsSpherical, ClosedFormChristoffelMatchesAD) {
  std::mt19937 rng(12345);
  for (const SphericalCase& c : spherical_cases()) {
    auto m = make_metric(c.name, c.params);
    for (int n = 0; n < 25; ++n) {
      const Vec4 x = c.christoffel_points(rng);
      ASSERT_TRUE(m->is_valid(x)) << label(c);
      SCOPED_TRACE(label(c));
      metric_checks::expect_christoffel_matches_ad(*m, x, metric_checks::kRuleRel, metric_checks::kRuleFloorFrac);
    }
  }
}

/// The hand-written accelerations (−Γ^μ_{ab} k^a k^b) agree with the contraction of the AD Γ and
/// of the closed-form Γ.
TEST(MetricsSpherical, GeodesicRightHandSideMatchesAD) {
  std::mt19937 rng(777);
  for (const SphericalCase& c : spherical_cases()) {
    auto m = make_metric(c.name, c.params);
    for (int n = 0; n < 5; ++n) {
      const Vec4 x = c.christoffel_points(rng);
      const Vec4 k{{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)}};
      SCOPED_TRACE(label(c));
      metric_checks::expect_accel_matches_ad(*m, x, k, metric_checks::kRuleRel, metric_checks::kRuleFloorFrac);
      // and the closed-form symbols, of which the diagonal metrics' acceleration templates
      // (diagonal_metric_accel.h, also the SIMD packets' right-hand side) are the contraction.
      Christoffel G;
      m->christoffel(x, G);
      metric_checks::expect_accel_matches_symbols(*m, x, k, G, "closed", metric_checks::kRuleRel,
                                                  metric_checks::kRuleFloorFrac);
    }
  }
}

// ---- natural tetrads ---------------------------------------------------------------------------

namespace {
void expect_orthonormal(const Metric& m, const Vec4& x, TetradKind kind, const std::string& what) {
  const Tetrad e = m.natural_tetrad(x, kind);
  Mat4 g;
  m.metric_tensor(x, g);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const double eta = a == b ? (a == 0 ? -1.0 : 1.0) : 0.0;
      EXPECT_NEAR(dot(g, e[a], e[b]), eta, 1e-12) << what << " " << tetrad_kind_name(kind) << " a=" << a << " b=" << b;
    }
  // Future-directed: in all these charts x^0 (t, v or T) increases along future-directed timelike
  // curves (it is a time function / advanced time), so e_(0)^0 > 0.
  EXPECT_GT(e[0][0], 0.0) << what << " " << tetrad_kind_name(kind);
}
}  // namespace

TEST(MetricsSpherical, NaturalTetradsAreOrthonormalAndFutureDirected) {
  std::mt19937 rng(4242);
  for (const SphericalCase& c : spherical_cases()) {
    auto m = make_metric(c.name, c.params);
    for (int n = 0; n < 20; ++n) {
      const Vec4 x = c.static_points(rng);
      for (TetradKind kind : m->info().tetrads) expect_orthonormal(*m, x, kind, label(c));
    }
  }
  // The free-fall tetrads also exist inside the horizon.
  for (const char* name : {"EddFinkIn", "PainleveGullstrand"}) {
    auto m = make_metric(name, {{"mass", 1.3}});
    for (int n = 0; n < 20; ++n) expect_orthonormal(*m, spherical(0.2, 2.59)(rng), TetradKind::Freefall, name);
  }
}

TEST(MetricsSpherical, TetradErrors) {
  // Static observers do not exist inside a horizon; the error names the alternative.
  for (const char* name : {"EddFinkIn", "PainleveGullstrand"}) {
    auto m = make_metric(name);
    const Vec4 inside{{0, 1.0, 1.0, 0}};
    EXPECT_THROW(m->natural_tetrad(inside, TetradKind::Static), Error) << name;
    EXPECT_THROW(m->natural_tetrad(inside, TetradKind::Default), Error) << name;
    EXPECT_NO_THROW(m->natural_tetrad(inside, TetradKind::Freefall)) << name;
    try {
      m->natural_tetrad(inside, TetradKind::Static);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("freefall"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(make_metric("SchwarzschildCart")->natural_tetrad(Vec4{{0, 1, 0.5, 0}}), Error);
  EXPECT_THROW(make_metric("SchwarzschildIsotropic")->natural_tetrad(Vec4{{0, 0.3, 0, 0}}), Error);
  EXPECT_THROW(make_metric("ReissnerNordstrom")->natural_tetrad(Vec4{{0, 1.5, 1, 0}}), Error);
  EXPECT_THROW(make_metric("Kottler")->natural_tetrad(Vec4{{0, 7.0, 1, 0}}), Error);  // beyond cosmological horizon
  EXPECT_THROW(make_metric("Ernst")->natural_tetrad(Vec4{{0, 1.5, 1, 0}}), Error);
  EXPECT_THROW(make_metric("TaubNUT")->natural_tetrad(Vec4{{0, 2.0, 1, 0}}), Error);
  EXPECT_THROW(make_metric("JanisNewmanWinicour", {{"gamma", 0.5}})->natural_tetrad(Vec4{{0, 3.9, 1, 0}}), Error);
  // Kinds a metric does not have.
  for (const char* name : {"SchwarzschildCart", "SchwarzschildIsotropic", "ReissnerNordstrom", "Kottler",
                           "BarriolaVilenkin", "Ernst", "TaubNUT"}) {
    EXPECT_THROW(make_metric(name)->natural_tetrad(Vec4{{0, 5, 1, 0.5}}, TetradKind::LNRF), Error) << name;
    EXPECT_THROW(make_metric(name)->natural_tetrad(Vec4{{0, 5, 1, 0.5}}, TetradKind::Freefall), Error) << name;
  }
  EXPECT_THROW(make_metric("JanisNewmanWinicour")->natural_tetrad(Vec4{{0, 5, 1, 0.5}}, TetradKind::Static), Error);
}

// ---- parameters --------------------------------------------------------------------------------

TEST(MetricsSpherical, BadParametersGiveErrors) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<std::string, Params>> bad = {
      {"SchwarzschildCart", {{"mass", -1}}},
      {"SchwarzschildIsotropic", {{"mass", -0.1}}},
      {"EddFinkIn", {{"mass", -1}}},
      {"PainleveGullstrand", {{"mass", nan}}},
      {"ReissnerNordstrom", {{"mass", -1}}},
      {"ReissnerNordstrom", {{"charge", inf}}},
      {"Kottler", {{"mass", -1}}},
      {"Kottler", {{"lambda", 0.2}}},                  // 9 Λ M² = 1.8 >= 1: no static region
      {"Kottler", {{"lambda", 0.01}, {"mass", 4.0}}},  // 9 Λ M² = 1.44
      {"BarriolaVilenkin", {{"k", 0.0}}},
      {"BarriolaVilenkin", {{"k", 1.5}}},
      {"BarriolaVilenkin", {{"k", -0.5}}},
      {"JanisNewmanWinicour", {{"gamma", 0.0}}},
      {"JanisNewmanWinicour", {{"gamma", 1.2}}},
      {"JanisNewmanWinicour", {{"mass", -2}}},
      {"Ernst", {{"mass", -1}}},
      {"Ernst", {{"b", nan}}},
      {"TaubNUT", {{"mass", -1}}},
      {"TaubNUT", {{"l", inf}}},
  };
  for (const auto& [name, params] : bad) EXPECT_THROW(make_metric(name, params), Error) << name;

  // A rejected value leaves the old one in place.
  auto k = make_metric("Kottler");
  EXPECT_THROW(k->set_param("lambda", 0.5), Error);
  EXPECT_EQ(k->param("lambda"), 0.05);
  EXPECT_NO_THROW(k->set_param("lambda", -3.0));  // anti-de Sitter: any M allowed

  // Unknown names, with a suggestion.
  for (const char* name : {"SchwarzschildCart", "SchwarzschildIsotropic", "EddFinkIn", "PainleveGullstrand",
                           "ReissnerNordstrom", "Kottler", "JanisNewmanWinicour", "Ernst", "TaubNUT"}) {
    auto m = make_metric(name);
    EXPECT_THROW(m->set_param("nosuchparameter", 1.0), Error) << name;
    try {
      m->set_param("mas", 1.0);
      ADD_FAILURE() << name << ": no error for 'mas'";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("mass"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(make_metric("BarriolaVilenkin")->set_param("mass", 1.0), Error);
  EXPECT_THROW(make_metric("SchwarzschildCartesian"), Error);
}

TEST(MetricsSpherical, ValidityDomains) {
  EXPECT_TRUE(make_metric("EddFinkIn")->is_valid(Vec4{{0, 1.0, 1, 0}}));  // inside the horizon
  EXPECT_FALSE(make_metric("EddFinkIn")->is_valid(Vec4{{0, -1.0, 1, 0}}));
  EXPECT_TRUE(make_metric("PainleveGullstrand")->is_valid(Vec4{{0, 0.5, 1, 0}}));
  EXPECT_FALSE(make_metric("SchwarzschildCart")->is_valid(Vec4{{0, 1.9, 0, 0}}));
  EXPECT_TRUE(make_metric("SchwarzschildCart")->is_valid(Vec4{{0, 0, 0, 2.1}}));  // on the z axis
  EXPECT_FALSE(make_metric("SchwarzschildIsotropic")->is_valid(Vec4{{0, 0.4, 0, 0}}));
  EXPECT_FALSE(make_metric("Kottler")->is_valid(Vec4{{0, 1.9, 1, 0}}));
  EXPECT_FALSE(make_metric("Kottler")->is_valid(Vec4{{0, 7.0, 1, 0}}));
  EXPECT_TRUE(make_metric("Kottler")->is_valid(Vec4{{0, 4.0, 1, 0}}));
  EXPECT_FALSE(make_metric("ReissnerNordstrom", {{"charge", 0.8}})->is_valid(Vec4{{0, 1.5, 1, 0}}));
  EXPECT_FALSE(make_metric("ReissnerNordstrom", {{"charge", 0.8}})->is_valid(Vec4{{0, 0.2, 1, 0}}));  // inside r-
  EXPECT_TRUE(make_metric("ReissnerNordstrom", {{"charge", 1.5}})->is_valid(Vec4{{0, 0.2, 1, 0}}));   // naked
  EXPECT_FALSE(make_metric("TaubNUT")->is_valid(Vec4{{0, 2.1, 1, 0}}));
  // γ = 0.5: singularity at r_s/γ = 4, Motion4D's break radius r_s (1 + γ)²/(4γ²) = 4.5.
  EXPECT_FALSE(make_metric("JanisNewmanWinicour", {{"gamma", 0.5}})->is_valid(Vec4{{0, 4.49, 1, 0}}));
  EXPECT_TRUE(make_metric("JanisNewmanWinicour", {{"gamma", 0.5}})->is_valid(Vec4{{0, 4.51, 1, 0}}));
  // γ = 1: Schwarzschild, stopped at the horizon break margin r_s (1 + horizon_eps).
  EXPECT_FALSE(make_metric("JanisNewmanWinicour")->is_valid(Vec4{{0, 2.0001, 1, 0}}));
  EXPECT_TRUE(make_metric("JanisNewmanWinicour")->is_valid(Vec4{{0, 2.0003, 1, 0}}));
}

// ---- physics -----------------------------------------------------------------------------------

namespace {

SolverConfig precise() {
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 200000;
  return cfg;
}

/// Starts a light ray at x in local direction d (static/default tetrad) and follows it for
/// `lambda_max` (or until it has drifted by more than 1e-2); returns max |r − x[1]| (r = x^1, a
/// spherical chart). `completed` tells whether the ray went the whole way (reason LambdaMax).
double photon_drift(const Metric& m, const Vec4& x, const Vec3& d, double lambda_max, bool* completed) {
  const Tetrad e = m.natural_tetrad(x);
  const Vec4 k = local_null_direction(e, d, false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg = precise();
  cfg.lambda_max = lambda_max;
  double drift = 0;
  auto cb = [&](const StepView& s) {
    drift = std::max(drift, std::fabs(s.y1[1] - x[1]));
    return drift > 1e-2 ? StepAction::Stop : StepAction::Continue;
  };
  const GeodesicResult r = m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  *completed = r.reason == StopReason::LambdaMax;
  return drift;
}

/// Max |r − r0| of a ray started tangentially on a circular photon orbit; expects the integration
/// to run the full affine length.
double circular_photon_drift(const Metric& m, const Vec4& x, const Vec3& d, double lambda_max) {
  bool completed = false;
  const double drift = photon_drift(m, x, d, lambda_max, &completed);
  EXPECT_TRUE(completed) << m.name() << " at r = " << x[1];
  return drift;
}

/// Drift of the same kind of ray started off the orbit (control: it must leave visibly).
double off_orbit_drift(const Metric& m, const Vec4& x, const Vec3& d, double lambda_max) {
  bool completed = false;
  return photon_drift(m, x, d, lambda_max, &completed);
}

/// Affine parameter for a little more than one full turn of a ray started as k = e_(0) + e_(3) at
/// θ = π/2 in a diagonal metric: there k^φ = 1/sqrt(g_φφ) and k^φ stays constant on a circular
/// orbit, so Δφ = 2π takes Δλ = 2π sqrt(g_φφ).
double full_turn_lambda(const Metric& m, const Vec4& x) {
  Mat4 g;
  m.metric_tensor(x, g);
  return 2.0 * M_PI * std::sqrt(g[3][3]) * 1.05;
}

/// Integrates a radial outgoing light ray from x (static tetrad, local direction d) until
/// `radius(x)` reaches r_end; returns x^0 there (found by bisection on the Hermite interpolant).
double time_at_radius(const Metric& m, const Vec4& x, const Vec3& d, const std::function<double(const Vec4&)>& radius,
                      double r_end) {
  const Vec4 k = local_null_direction(m.natural_tetrad(x), d, false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg = precise();
  cfg.step_max = 0.05;  // keeps the Hermite interpolation error far below the tolerance
  double t_end = std::numeric_limits<double>::quiet_NaN();
  auto cb = [&](const StepView& s) {
    const Vec4 x1{{s.y1[0], s.y1[1], s.y1[2], s.y1[3]}};
    if (radius(x1) < r_end) return StepAction::Continue;
    double lo = 0, hi = 1;
    Vec4 xs, ks;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      hermite_interpolate(s, mid, xs, ks);
      (radius(xs) < r_end ? lo : hi) = mid;
    }
    hermite_interpolate(s, 0.5 * (lo + hi), xs, ks);
    t_end = xs[0];
    return StepAction::Stop;
  };
  const GeodesicResult r = m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Callback) << m.name() << " " << stop_reason_name(r.reason);
  return t_end;
}

}  // namespace

/// Radial light travel time between Schwarzschild radii r1 < r2 (coordinate time of a static
/// observer at infinity): Δt = r2 − r1 + r_s ln((r2 − r_s)/(r1 − r_s)) (the integral of
/// dt/dr = 1/(1 − r_s/r) for a radial null ray, i.e. the tortoise coordinate). Schwarzschild,
/// SchwarzschildCart and SchwarzschildIsotropic share t, so all three must give it.
TEST(MetricsSpherical, SchwarzschildChartsGiveTheRadialLightTravelTime) {
  const double M = 1.0, rs = 2 * M, r1 = 3.0, r2 = 25.0;
  const double expected = r2 - r1 + rs * std::log((r2 - rs) / (r1 - rs));
  const Vec3 n{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};  // unit vector, off the axes

  auto schw = make_metric("Schwarzschild");
  const double t_s = time_at_radius(
      *schw, Vec4{{0, r1, std::acos(n.z), std::atan2(n.y, n.x)}}, Vec3{1, 0, 0}, [](const Vec4& x) { return x[1]; },
      r2);
  EXPECT_NEAR(t_s, expected, 1e-8 * expected);

  auto cart = make_metric("SchwarzschildCart");
  const double t_c = time_at_radius(
      *cart, Vec4{{0, r1 * n.x, r1 * n.y, r1 * n.z}}, n,
      [](const Vec4& x) { return std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]); }, r2);
  EXPECT_NEAR(t_c, expected, 1e-8 * expected);

  // Isotropic radius: r = ρ (1 + M/(2ρ))²  <=>  ρ = (r − M + sqrt(r² − 2Mr))/2.
  auto rho_of = [&](double r) { return 0.5 * (r - M + std::sqrt(r * r - 2 * M * r)); };
  auto iso = make_metric("SchwarzschildIsotropic");
  const double rho1 = rho_of(r1);
  const double t_i = time_at_radius(
      *iso, Vec4{{0, rho1 * n.x, rho1 * n.y, rho1 * n.z}}, n,
      [](const Vec4& x) { return std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]); }, rho_of(r2));
  EXPECT_NEAR(t_i, expected, 1e-8 * expected);
}

/// Ingoing Eddington-Finkelstein: radial ingoing light rays have v = const and cross the horizon;
/// outgoing ones obey dv/dr = 2/(1 − r_s/r), i.e. v = v0 + 2 (r − r0) + 2 r_s ln((r − r_s)/(r0 − r_s))
/// (from g(k,k) = 0 with k^θ = k^φ = 0: k^v = 0 or dv/dr = 2/(1 − r_s/r); Catalogue of Spacetimes,
/// Eddington-Finkelstein coordinates).
TEST(MetricsSpherical, EddFinkInRadialLightRays) {
  auto m = make_metric("EddFinkIn");
  const double rs = 2.0;
  {
    const Vec4 x{{1.5, 10.0, 1.1, 0.3}};
    const Tetrad e = m->natural_tetrad(x, TetradKind::Static);
    const Vec4 k = local_null_direction(e, Vec3{-1, 0, 0}, false);  // future, radially inwards
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    double dv = 0, rmin = 1e300;
    auto cb = [&](const StepView& s) {
      dv = std::max(dv, std::fabs(s.y1[0] - x[0]));
      rmin = std::min(rmin, s.y1[1]);
      return s.y1[1] < 0.1 ? StepAction::Stop : StepAction::Continue;
    };
    const GeodesicResult r = m->integrate(precise(), GeodesicSystem::Geodesic, y, 0.0, cb);
    EXPECT_EQ(r.reason, StopReason::Callback) << stop_reason_name(r.reason);
    EXPECT_LT(rmin, 0.1);  // crossed the horizon r_s = 2 without stopping
    EXPECT_LT(dv, 1e-12);
  }
  {
    const double r0 = 3.0, v0 = -0.7;
    const Vec4 x{{v0, r0, 1.1, 0.3}};
    const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{1, 0, 0}, false);
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    double err = 0;
    auto cb = [&](const StepView& s) {
      const double r = s.y1[1];
      const double v = v0 + 2 * (r - r0) + 2 * rs * std::log((r - rs) / (r0 - rs));
      err = std::max(err, std::fabs(s.y1[0] - v) / std::max(1.0, std::fabs(v)));
      return r > 40 ? StepAction::Stop : StepAction::Continue;
    };
    const GeodesicResult r = m->integrate(precise(), GeodesicSystem::Geodesic, y, 0.0, cb);
    EXPECT_EQ(r.reason, StopReason::Callback) << stop_reason_name(r.reason);
    EXPECT_LT(err, 1e-9);
  }
}

/// Painlevé-Gullstrand: the free-fall observer (from rest at infinity) is a timelike geodesic whose
/// proper time is T, with r(τ)^{3/2} = r0^{3/2} − (3/2) sqrt(r_s) τ (integral of
/// dr/dτ = −sqrt(r_s/r), energy per mass 1; Martel & Poisson, Am. J. Phys. 69 (2001) 476); it
/// falls through the horizon.
TEST(MetricsSpherical, PainleveGullstrandFreeFallObserver) {
  auto m = make_metric("PainleveGullstrand", {{"mass", 1.5}});
  const double rs = 3.0, r0 = 12.0, T0 = 0.4;
  const Vec4 x{{T0, r0, 0.9, 2.0}};
  const Vec4 u = m->natural_tetrad(x, TetradKind::Freefall)[0];
  double y[8] = {x[0], x[1], x[2], x[3], u[0], u[1], u[2], u[3]};
  SolverConfig cfg = precise();
  cfg.type = GeodesicType::Timelike;
  double errT = 0, errR = 0, rmin = 1e300;
  auto cb = [&](const StepView& s) {
    const double tau = s.lambda1;
    const double r_an = std::pow(std::pow(r0, 1.5) - 1.5 * std::sqrt(rs) * tau, 2.0 / 3.0);
    errT = std::max(errT, std::fabs(s.y1[0] - T0 - tau));
    errR = std::max(errR, std::fabs(s.y1[1] - r_an));
    rmin = std::min(rmin, s.y1[1]);
    return s.y1[1] < 0.5 ? StepAction::Stop : StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Callback) << stop_reason_name(r.reason);
  EXPECT_LT(rmin, 0.5);
  EXPECT_LT(errT, 1e-9);
  EXPECT_LT(errR, 1e-9);
}

/// Reissner-Nordström photon sphere r = (3M + sqrt(9M² − 8Q²))/2 (Catalogue of Spacetimes,
/// Reissner-Nordström; from d/dr (f/r²) = 0).
TEST(MetricsSpherical, ReissnerNordstromPhotonSphere) {
  const double M = 1.0, Q = 0.8;
  auto m = make_metric("ReissnerNordstrom", {{"mass", M}, {"charge", Q}});
  const double rps = 0.5 * (3 * M + std::sqrt(9 * M * M - 8 * Q * Q));
  const Vec4 x{{0, rps, M_PI / 2, 0}};
  EXPECT_LT(circular_photon_drift(*m, x, Vec3{0, 0, 1}, full_turn_lambda(*m, x)), 1e-8);
  // Control: slightly off the photon sphere the same ray drifts away visibly.
  const Vec4 x2{{0, rps * 1.001, M_PI / 2, 0}};
  EXPECT_GT(off_orbit_drift(*m, x2, Vec3{0, 0, 1}, full_turn_lambda(*m, x2)), 1e-3);
}

/// Kottler: the photon sphere stays at r = 3M for any Λ (Λ drops out of d/dr (f/r²) = 0;
/// Catalogue of Spacetimes, Kottler; Stuchlík & Hledík, Phys. Rev. D 60 (1999) 044006).
TEST(MetricsSpherical, KottlerPhotonSphereIsThreeM) {
  for (double lambda : {0.05, -0.2}) {
    auto m = make_metric("Kottler", {{"mass", 1.0}, {"lambda", lambda}});
    const Vec4 x{{0, 3.0, M_PI / 2, 0.2}};
    EXPECT_LT(circular_photon_drift(*m, x, Vec3{0, 0, 1}, full_turn_lambda(*m, x)), 1e-8) << lambda;
  }
}

/// Janis-Newman-Winicour photon sphere r = (1 + 2γ) M/γ (Virbhadra, Narasimha & Chitre,
/// Astron. Astrophys. 337 (1998) 1;
/// Motion4D report "r_ph = rs (1 + 2γ)/(2γ)"), from d/dr (α^(2γ−1)/r²) = 0.
TEST(MetricsSpherical, JanisNewmanWinicourPhotonSphere) {
  for (double gamma : {0.8, 0.6}) {
    const double M = 1.0;
    auto m = make_metric("JanisNewmanWinicour", {{"mass", M}, {"gamma", gamma}});
    const Vec4 x{{0, (1 + 2 * gamma) * M / gamma, M_PI / 2, 0}};
    EXPECT_LT(circular_photon_drift(*m, x, Vec3{0, 0, 1}, full_turn_lambda(*m, x)), 1e-8) << gamma;
  }
}

/// Barriola-Vilenkin: space is a cone; on the equator dr² + k² r² dφ² is flat in ψ = kφ, so a light
/// ray with periapsis r0 is a straight line r cos(kφ) = r0 (deflection π(1/k − 1) overall).
TEST(MetricsSpherical, BarriolaVilenkinRaysAreStraightOnTheCone) {
  const double k = 0.8, r0 = 2.0;
  auto m = make_metric("BarriolaVilenkin", {{"k", k}});
  const Vec4 x{{0, r0, M_PI / 2, 0}};
  const Vec4 kv = local_null_direction(m->natural_tetrad(x), Vec3{0, 0, 1}, false);
  double y[8] = {x[0], x[1], x[2], x[3], kv[0], kv[1], kv[2], kv[3]};
  double err = 0;
  auto cb = [&](const StepView& s) {
    const double r_an = r0 / std::cos(k * s.y1[3]);
    err = std::max(err, std::fabs(s.y1[1] - r_an) / r_an);
    return s.y1[1] > 40 ? StepAction::Stop : StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(precise(), GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Callback) << stop_reason_name(r.reason);
  EXPECT_LT(err, 1e-9);
}

/// Ernst: equatorial circular light orbits sit where d/dr (Λ⁴ f / r²) = 0 (Λ = 1 + B²r² on the
/// equator, the ratio −g_tt/g_φφ), i.e. at the roots of 3B²r³ − 5MB²r² − r + 3M = 0; the inner
/// root tends to 3M as B → 0. (The symmetry θ → π − θ keeps the orbit equatorial.)
TEST(MetricsSpherical, ErnstEquatorialPhotonOrbit) {
  const double M = 1.0, B = 0.05;
  auto poly = [&](double r) { return 3 * B * B * r * r * r - 5 * M * B * B * r * r - r + 3 * M; };
  double lo = 3 * M, hi = 3.5 * M;  // poly(lo) > 0 > poly(hi)
  ASSERT_GT(poly(lo), 0);
  ASSERT_LT(poly(hi), 0);
  for (int i = 0; i < 200; ++i) (poly(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double rc = 0.5 * (lo + hi);
  auto m = make_metric("Ernst", {{"mass", M}, {"b", B}});
  const Vec4 x{{0, rc, M_PI / 2, 0}};
  EXPECT_LT(circular_photon_drift(*m, x, Vec3{0, 0, 1}, full_turn_lambda(*m, x)), 1e-8);
  const Vec4 x2{{0, 3.0 * M, M_PI / 2, 0}};  // the Schwarzschild value is not an orbit here
  EXPECT_GT(off_orbit_drift(*m, x2, Vec3{0, 0, 1}, full_turn_lambda(*m, x2)), 1e-3);
}

/// Taub-NUT: light rays started tangentially on the sphere r³ − 3Mr² − 3l²r + Ml² = 0, i.e.
/// r = M + 2 sqrt(M² + l²) cos(arccos(M/sqrt(M² + l²))/3) (the extremum of Δ/Σ²; Motion4D's
/// calcPhotonOrbit), stay on it for any tangential direction, although the orbit is not planar.
TEST(MetricsSpherical, TaubNUTPhotonSphere) {
  const double M = 1.0, l = 0.5;
  auto m = make_metric("TaubNUT", {{"mass", M}, {"l", l}});
  const double w = std::sqrt(M * M + l * l);
  const double rps = M + 2 * w * std::cos(std::acos(M / w) / 3);
  for (const Vec3& d : {Vec3{0, 0, 1}, Vec3{0, 0.6, 0.8}, Vec3{0, -0.8, -0.6}}) {
    const Vec4 x{{0, rps, 1.2, 0.3}};
    EXPECT_LT(circular_photon_drift(*m, x, d, 2 * M_PI * std::sqrt(rps * rps + l * l)), 1e-8);
  }
}

// ---- curvature: the line elements themselves ------------------------------------------------
// The Γ tests above only prove closed form == AD of our own g_{μν}. These check g_{μν} against
// curvature known in closed form (Riemann from second-order AD of g).

namespace {

struct Curvature {
  double ricci[4][4];  ///< R_{bd} = R^a_{bad}
  double kretschmann;  ///< R_{abcd} R^{abcd}
};

Curvature curvature(const Metric& m, const Vec4& x) {
  Riemann R;
  m.riemann(x, R);
  Mat4 g;
  m.metric_tensor(x, g);
  const Mat4 gi = invert(g);
  Curvature c{};
  for (int b = 0; b < 4; ++b)
    for (int d = 0; d < 4; ++d)
      for (int a = 0; a < 4; ++a) c.ricci[b][d] += R.R[a][b][a][d];
  // R^{a}_{bcd} -> R_{abcd} and R^{abcd}.
  static double low[4][4][4][4], up[4][4][4][4];
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int cc = 0; cc < 4; ++cc)
        for (int d = 0; d < 4; ++d) {
          double s = 0;
          for (int e = 0; e < 4; ++e) s += g[a][e] * R.R[e][b][cc][d];
          low[a][b][cc][d] = s;
        }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int cc = 0; cc < 4; ++cc)
        for (int d = 0; d < 4; ++d) {
          double s = 0;
          for (int f = 0; f < 4; ++f)
            for (int h = 0; h < 4; ++h)
              for (int k = 0; k < 4; ++k)
                if (gi[b][f] != 0 && gi[cc][h] != 0 && gi[d][k] != 0)
                  s += gi[b][f] * gi[cc][h] * gi[d][k] * R.R[a][f][h][k];
          up[a][b][cc][d] = s;  // R^{a bcd}
        }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int cc = 0; cc < 4; ++cc)
        for (int d = 0; d < 4; ++d) c.kretschmann += low[a][b][cc][d] * up[a][b][cc][d];
  return c;
}

double max_abs_ricci(const Curvature& c) {
  double s = 0;
  for (auto& row : c.ricci)
    for (double v : row) s = std::max(s, std::fabs(v));
  return s;
}

}  // namespace

/// Every Schwarzschild chart (also inside the horizon for EF/PG) is vacuum with the Kretschmann
/// scalar 48 M²/r⁶ of the areal radius r, Taub-NUT is vacuum, and Reissner-Nordström has
/// K = (48M²r² − 96MQ²r + 56Q⁴)/r⁸ (R. C. Henry, ApJ 535 (2000) 350, Kerr-Newman with a = 0)
/// with vanishing Ricci scalar (traceless Maxwell stress tensor).
TEST(MetricsSpherical, CurvatureOfSchwarzschildChartsTaubNUTAndReissnerNordstrom) {
  const double M = 1.3;
  struct P {
    std::string name;
    Vec4 x;
    double r;  ///< areal radius of x
  };
  const double rho = 2.0, r_iso = rho * (1 + M / (2 * rho)) * (1 + M / (2 * rho));
  const std::vector<P> pts = {
      {"SchwarzschildCart", {{0, 1.0, -2.0, 3.0}}, std::sqrt(14.0)},
      {"SchwarzschildIsotropic", {{0, 1.2, 0.0, -1.6}}, r_iso},
      {"EddFinkIn", {{0, 5.0, 0.7, 1.0}}, 5.0},
      {"EddFinkIn", {{0, 1.5, 0.7, 1.0}}, 1.5},  // inside r_s = 2.6
      {"PainleveGullstrand", {{0, 5.0, 0.7, 1.0}}, 5.0},
      {"PainleveGullstrand", {{0, 1.5, 0.7, 1.0}}, 1.5},
  };
  for (const P& p : pts) {
    auto m = make_metric(p.name, {{"mass", M}});
    const Curvature c = curvature(*m, p.x);
    const double K = 48 * M * M / std::pow(p.r, 6);
    EXPECT_NEAR(c.kretschmann, K, 1e-9 * K) << p.name << " r=" << p.r;
    EXPECT_LT(max_abs_ricci(c), 1e-10 * std::sqrt(K)) << p.name << " r=" << p.r;
  }
  {
    auto m = make_metric("TaubNUT", {{"mass", 1.0}, {"l", 0.7}});
    const Curvature c = curvature(*m, Vec4{{0, 4.0, 1.1, 0.3}});
    EXPECT_LT(max_abs_ricci(c), 1e-10 * std::sqrt(std::fabs(c.kretschmann)));
    EXPECT_GT(c.kretschmann, 0.0);
  }
  {
    const double Mq = 1.0, Q = 0.8, r = 3.0;
    auto m = make_metric("ReissnerNordstrom", {{"mass", Mq}, {"charge", Q}});
    const Vec4 x{{0, r, 1.1, 0.3}};
    const Curvature c = curvature(*m, x);
    const double K = (48 * Mq * Mq * r * r - 96 * Mq * Q * Q * r + 56 * Q * Q * Q * Q) / std::pow(r, 8);
    EXPECT_NEAR(c.kretschmann, K, 1e-9 * K);
    Mat4 g;
    m->metric_tensor(x, g);
    const Mat4 gi = invert(g);
    double Rs = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) Rs += gi[a][b] * c.ricci[a][b];
    EXPECT_LT(std::fabs(Rs), 1e-10 * std::sqrt(K));
    // Einstein-Maxwell: R_tt = Q² f / r⁴ for the Coulomb field (T_tt = Q² f/(8π r⁴)).
    const double f = 1 - 2 * Mq / r + Q * Q / (r * r);
    EXPECT_NEAR(c.ricci[0][0], Q * Q * f / std::pow(r, 4), 1e-10);
  }
}

/// Kottler is an Einstein space, R_μν = Λ g_μν; Ernst is electrovac (R = 0, R_μν ≠ 0 for B ≠ 0);
/// Janis-Newman-Winicour is sourced by a static massless scalar φ(r), R_μν = 8π ∂_μφ ∂_νφ, so only
/// R_rr ≠ 0; Barriola-Vilenkin has R_tt = R_rr = 0, R_θθ = 1 − k², R_φφ = (1 − k²) sin²θ
/// (Barriola & Vilenkin 1989: energy density (1 − k²)/(8π k² r²)).
TEST(MetricsSpherical, CurvatureOfKottlerErnstJNWAndBarriolaVilenkin) {
  const Vec4 x{{0, 3.5, 1.1, 0.3}};
  for (double lambda : {0.05, -0.3}) {
    auto m = make_metric("Kottler", {{"mass", 1.0}, {"lambda", lambda}});
    const Curvature c = curvature(*m, x);
    Mat4 g;
    m->metric_tensor(x, g);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        EXPECT_NEAR(c.ricci[a][b], lambda * g[a][b], 1e-12 * (1 + std::fabs(g[a][b]))) << lambda << " " << a << b;
  }
  {
    auto m = make_metric("Ernst", {{"mass", 1.0}, {"b", 0.2}});
    const Curvature c = curvature(*m, x);
    Mat4 g;
    m->metric_tensor(x, g);
    const Mat4 gi = invert(g);
    double Rs = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) Rs += gi[a][b] * c.ricci[a][b];
    EXPECT_LT(std::fabs(Rs), 1e-10 * max_abs_ricci(c));
    EXPECT_GT(max_abs_ricci(c), 1e-3);  // not vacuum: the magnetic field curves spacetime
  }
  {
    auto m = make_metric("JanisNewmanWinicour", {{"mass", 1.0}, {"gamma", 0.6}});
    const Curvature c = curvature(*m, Vec4{{0, 5.0, 1.1, 0.3}});
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (!(a == 1 && b == 1)) {
          EXPECT_NEAR(c.ricci[a][b], 0.0, 1e-12) << a << b;
        }
    EXPECT_GT(c.ricci[1][1], 1e-3);
  }
  {
    const double k = 0.7;
    auto m = make_metric("BarriolaVilenkin", {{"k", k}});
    const Curvature c = curvature(*m, x);
    const double st = std::sin(x[2]);
    const double expect[4] = {0, 0, 1 - k * k, (1 - k * k) * st * st};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) EXPECT_NEAR(c.ricci[a][b], a == b ? expect[a] : 0.0, 1e-12) << a << b;
  }
}
