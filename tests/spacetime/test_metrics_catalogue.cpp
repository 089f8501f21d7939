// The metrics added from Motion4D's catalogue (Goedel family, Kasner, Curzon,
// CosmicStringSchwarzschild, MinkowskiConformal, SchwarzschildTortoise, MinkowskiRotLattice,
// StraightSpinningString, ExtremeReissnerNordstromDihole, Kruskal, VaidyaIncRad,
// SultanaDyerBlackhole, FriedmanNonEmptyNull, TeoWHl, Pravda_C-Metric, and the gravitational
// waves, Weyl and quasi-Kerr metrics SchwarzschildGravWave, PlaneGravWave, BesselGravWaveCart,
// HalilsoyWave, Bonnor, ErezRosenVar, ChazyCurzonRot, TomimatsuSato, Glampedakis, HartleThorneGB and
// AlcubierreWarp) beyond the generated registry tests (test_metrics_registry.cpp): closed-form
// Christoffel symbols against AD at non-default parameters and away from the sample position,
// tetrads of every kind, and physics with independent expectations (Gödel's field equations, the
// Einstein static universe's null cone, the tortoise and Kruskal radial light rays, the rotating
// lattice and spinning string seen from inertial frames, Motion4D's k^t rescaling of
// AlcubierreWarpSimple, Majumdar–Papapetrou and Bonnor as electrovacua, Bonnor's dihole (mass 2m,
// strut, light capture), the plane wave's scales before the wave, the C-metric's horizon catching
// every light ray, Vaidya's null dust,
// conserved quantities of Sultana–Dyer and Teo light rays, Friedmann dust, the C-metric's Weyl
// coordinates, linearised vacuum perturbations, Killing constants along light rays, limits to
// Schwarzschild, Kerr, Curzon and Zipoy–Voorhees).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "metric_checks.h"
#include "spacetime/metric_registry.h"
#include "support/uniform.h"

using namespace geovis;
namespace mc = geovis::metric_checks;

namespace {

using Params = std::vector<std::pair<std::string, double>>;

using geovis::testing_support::uni;

}  // namespace

/// Christoffel symbols (closed form vs AD) and tetrads at random points and parameters.
TEST(MetricsCatalogue, ChristoffelsAndTetradsAtRandomPointsAndParameters) {
  std::mt19937 rng(11);
  struct Case {
    std::string name;
    Params params;
    std::function<Vec4(std::mt19937&)> point;
  };
  const std::vector<Case> cases = {
      {"Goedel",
       {{"a", 0.7}, {"zeta", 0.2}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 0.1, 1.2), uni(r, -3, 3), uni(r, -5, 5)}};
       }},
      {"GoedelScaled",
       {{"rg", 2.5}, {"zeta", -0.3}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 0.1, 0.8), uni(r, -3, 3), uni(r, -5, 5)}};
       }},
      {"GoedelCart",
       {{"a", 0.7}, {"zeta", 0.2}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, -0.8, 0.8), uni(r, -0.8, 0.8), uni(r, -5, 5)}};
       }},
      {"GoedelScaledCart",
       {{"rg", 2.5}, {"zeta", -0.3}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, -0.5, 0.5), uni(r, -0.5, 0.5), uni(r, -5, 5)}};
       }},
      {"Kasner",
       {{"u", 2.5}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, 0.2, 5), uni(r, -5, 5), uni(r, -5, 5), uni(r, -5, 5)}};
       }},
      {"Curzon",
       {{"mass", 1.7}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 0.5, 8), uni(r, -3, 3), uni(r, -6, 6)}};
       }},
      {"CosmicStringSchwarzschild",
       {{"mass", 0.8}, {"beta", 0.3}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 1.7, 20), uni(r, 0.2, 2.9), uni(r, -3, 3)}};
       }},
      {"MinkowskiConformal",
       {},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -3, 3), uni(r, 0.1, 3.0), uni(r, 0.2, 2.9), uni(r, -3, 3)}};
       }},
      {"SchwarzschildTortoise",
       {{"mass", 1.3}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, -10, 40), uni(r, 0.2, 2.9), uni(r, -3, 3)}};
       }},
      {"MinkowskiRotLattice",
       {{"omega", 0.3}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 0.1, 3.2), uni(r, -3, 3), uni(r, -5, 5)}};
       }},
      {"StraightSpinningString",
       {{"a", 0.7}, {"k", 0.6}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 1.3, 9), uni(r, -3, 3), uni(r, -5, 5)}};
       }},
      {"SchwarzschildGravWave",
       {{"mass", 0.8}, {"epsilon", 0.05}, {"sigma", 0.5}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 2.5, 8), uni(r, 0.2, 2.9), uni(r, -3, 3)}};
       }},
      // u = t − x across the wave and both flat regions.
      {"PlaneGravWave",
       {{"long_ext", 0.8}, {"degree", 12}},
       [](std::mt19937& r) {
         const double t = uni(r, -3, 3);
         return Vec4{{t, t - uni(r, -1.5, 0.9), uni(r, -3, 3), uni(r, -3, 3)}};
       }},
      // ρ up to 8: both the series (ρ < 2) and the library Bessel functions.
      {"BesselGravWaveCart",
       {{"c", 0.7}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, -6, 6), uni(r, -6, 6), uni(r, -5, 5)}};
       }},
      {"HalilsoyWave",
       {{"alpha", 0.6}, {"c", 0.8}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 0.2, 9), uni(r, -3, 3), uni(r, -5, 5)}};
       }},
      // Across the bubble wall (r_s near R = 1.5) and inside it.
      {"AlcubierreWarp",
       {{"sigma", 5.0}, {"r", 1.5}, {"vs", 0.9}},
       [](std::mt19937& r) {
         const double t = uni(r, -2, 2);
         return Vec4{{t, 0.9 * t + uni(r, -2, 2), uni(r, -2, 2), uni(r, -2, 2)}};
       }},
      // ρ >= 2.5: g_φφ > 0 there, so that the comoving tetrad exists.
      {"ChazyCurzonRot",
       {{"mass", 0.8}, {"p", -0.3}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 2.5, 8), uni(r, -3, 3), uni(r, -6, 6)}};
       }},
      {"TomimatsuSato",
       {{"k", 0.7}, {"p", 0.6}, {"q", -0.8}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 2.5, 9), uni(r, -0.95, 0.95), uni(r, -3, 3)}};
       }},
      {"Glampedakis",
       {{"mass", 1.2}, {"angmom", 0.7}, {"epsilon", 0.3}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 3.5, 20), uni(r, 0.2, 2.9), uni(r, -3, 3)}};
       }},
      {"HartleThorneGB",
       {{"mass", 0.9}, {"angmom", 0.5}, {"eta", 0.8}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 3.0, 20), uni(r, 0.2, 2.9), uni(r, -3, 3)}};
       }},
      {"ErezRosenVar",
       {{"mass", 1.3}, {"q", -0.7}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 2.8, 20), uni(r, 0.2, 2.9), uni(r, -3, 3)}};
       }},
      {"Bonnor",
       {{"mass", 0.7}, {"b", 0.9}},
       [](std::mt19937& r) {
         return Vec4{{uni(r, -5, 5), uni(r, 1.9, 12), uni(r, 0.2, 2.9), uni(r, -3, 3)}};
       }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const auto m = make_metric(c.name, c.params);
    for (int i = 0; i < 30; ++i) {
      const Vec4 x = c.point(rng);
      ASSERT_TRUE(m->is_valid(x)) << x[0] << " " << x[1] << " " << x[2] << " " << x[3];
      mc::expect_christoffel_matches_ad(*m, x, mc::kRuleRel, mc::kRuleFloorFrac);
      mc::expect_accel_matches_ad(*m, x, Vec4{{uni(rng, -1, 1), uni(rng, -1, 1), uni(rng, -1, 1), uni(rng, -1, 1)}},
                                  mc::kRuleRel, mc::kRuleFloorFrac);
      for (TetradKind k : m->info().tetrads) mc::expect_orthonormal(*m, x, k);
    }
  }
}

/// Gödel's field equations: R_ab = u_a u_b/a² for the dust 4-velocity u = ∂_t (Gödel, RMP 21
/// (1949) 447: dust of density ρ with 8πρ = 1/a² and Λ = −1/(2a²)), in all four charts.
TEST(MetricsCatalogue, GoedelRicciIsDustAlongTheTimeLines) {
  for (const auto& [name, a, scale] :
       std::vector<std::tuple<std::string, double, double>>{{"Goedel", 0.8, 1.0},
                                                            {"GoedelCart", 0.8, 1.0},
                                                            {"GoedelScaled", 0.5, 3.0},
                                                            {"GoedelScaledCart", 0.5, 3.0}}) {
    SCOPED_TRACE(name);
    const bool scaled = name.find("Scaled") != std::string::npos;
    const auto m = scaled ? make_metric(name, {{"rg", scale}}) : make_metric(name, {{"a", a}});
    // Scaled charts: r_G² times the a = 1/2 metric; R_ab is unchanged by the constant factor and
    // u_a (of the unit vector n = ∂_T/√(−g_TT)) grows by r_G, so R_ab = u_a u_b/(r_G/2)².
    const double a_eff = scaled ? 0.5 * scale : a;
    for (const Vec4& x : {Vec4{{0.3, 0.4, 0.2, -1.0}}, Vec4{{-2.0, 0.25, 1.3, 2.0}}}) {
      Mat4 g;
      m->metric_tensor(x, g);
      double riemann_scale = 0;
      const Mat4 ric = mc::ricci(*m, x, &riemann_scale);
      const double n0 = 1.0 / std::sqrt(-g[0][0]);
      // u_a = g_ab n^b for n = n0 ∂_0.
      Vec4 u;
      for (int b = 0; b < 4; ++b) u[b] = g[b][0] * n0;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          EXPECT_NEAR(ric[i][j], u[i] * u[j] / (a_eff * a_eff), 1e-10 * riemann_scale) << i << j;
    }
  }
}

/// MinkowskiConformal: the conformal map t ± r = tan((ψ ± ξ)/2) of a straight Minkowski light ray
/// r(t) through the origin's neighbourhood is a null geodesic of the Einstein static universe: a
/// ray started at (ψ, ξ) radially outwards keeps ψ − ξ constant (radial null lines).
TEST(MetricsCatalogue, MinkowskiConformalRadialRaysAreStraightInThePenroseDiagram) {
  const auto m = make_metric("MinkowskiConformal");
  const Vec4 x{{-1.0, 0.5, 1.1, 0.4}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{1, 0, 0}, /*past_directed=*/false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 500;
  double worst = 0;
  auto cb = [&](const StepView& s) {
    worst = std::max(worst, std::fabs((s.y1[0] - s.y1[1]) - (x[0] - x[1])));
    return StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Invalid);  // reaches ξ = π (the antipode of the Einstein universe)
  EXPECT_LT(worst, 1e-9);
  EXPECT_NEAR(y[1], M_PI, 1e-2);
}

/// SchwarzschildTortoise: radial light rays are t ∓ ρ = const, and the chart's areal radius
/// satisfies ρ = r + r_s ln(r/r_s − 1) (checked through to_pseudo_cartesian).
TEST(MetricsCatalogue, SchwarzschildTortoiseRadialLightRaysAndArealRadius) {
  const double M = 1.3, rs = 2 * M;
  const auto m = make_metric("SchwarzschildTortoise", {{"mass", M}});
  for (double rho : {-20.0, -1.0, 3.0, 50.0}) {
    Vec3 p;
    m->to_pseudo_cartesian(Vec4{{0, rho, M_PI / 2, 0}}, p);
    const double r = norm(p);
    EXPECT_NEAR(r + rs * std::log(r / rs - 1), rho, 1e-12 * std::max(1.0, std::fabs(rho))) << rho;
    const Vec4 back = m->from_pseudo_cartesian(0.0, p);
    EXPECT_NEAR(back[1], rho, 1e-9 * std::max(1.0, std::fabs(rho)));
  }
  const Vec4 x{{0, 10.0, 1.0, 0.3}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{1, 0, 0}, false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 300;
  double worst = 0;
  auto cb = [&](const StepView& s) {
    worst = std::max(worst, std::fabs((s.y1[0] - s.y1[1]) - (x[0] - x[1])));
    return StepAction::Continue;
  };
  m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_LT(worst, 1e-8 * std::max(1.0, y[1]));
  EXPECT_GT(y[1], 20.0);
}

/// MinkowskiRotLattice: a light ray of the rotating frame is a straight line of the inertial frame
/// (x, y) = (r cos(φ + ω t), r sin(φ + ω t)); its LNRF observer is the inertial one at rest.
TEST(MetricsCatalogue, MinkowskiRotLatticeRaysAreInertialStraightLines) {
  const double w = 0.2;
  const auto m = make_metric("MinkowskiRotLattice", {{"omega", w}});
  const Vec4 x{{0, 1.5, 0.3, 0.2}};
  const Tetrad e = m->natural_tetrad(x, TetradKind::LNRF);
  // The LNRF observer's e_(0) = ∂_t − ω ∂_φ: dφ/dt = −ω, i.e. at rest in the inertial frame.
  EXPECT_NEAR(e[0][2] / e[0][0], -w, 1e-15);
  const Vec4 k = local_null_direction(e, Vec3{0.3, 1, 0.2}, false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  auto inertial = [w](const double* s) {
    return Vec3{s[1] * std::cos(s[2] + w * s[0]), s[1] * std::sin(s[2] + w * s[0]), s[3]};
  };
  const Vec3 p0 = inertial(y);
  // Inertial velocity: dX/dt at the start, from k.
  const double c = std::cos(x[2]), s = std::sin(x[2]);
  const Vec3 v{(k[1] * c - x[1] * s * (k[2] + w * k[0])) / k[0], (k[1] * s + x[1] * c * (k[2] + w * k[0])) / k[0],
               k[3] / k[0]};
  EXPECT_NEAR(norm(v), 1.0, 1e-12);  // light moves at c in the inertial frame
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 2000;
  double worst = 0;
  auto cb = [&](const StepView& st) {
    const Vec3 p = inertial(st.y1);
    const Vec3 expect = p0 + v * (st.y1[0] - x[0]);
    worst = std::max(worst, norm(p - expect));
    return StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Invalid);  // leaves through the light cylinder r = 1/ω = 5
  EXPECT_NEAR(y[1], 1 / w, 1e-2);
  EXPECT_LT(worst, 1e-8);
}

/// StraightSpinningString: with t' = t − a φ and φ' = k φ the metric is Minkowski in cylindrical
/// coordinates, so light rays are straight lines of (ρ cos kφ, ρ sin kφ, z) and move with unit
/// speed in t − a φ.
TEST(MetricsCatalogue, StraightSpinningStringIsMinkowskiInDisguise) {
  const double a = 0.7, kk = 0.6;
  const auto m = make_metric("StraightSpinningString", {{"a", a}, {"k", kk}});
  const Vec4 x{{0, 4.0, 0.2, 0.5}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{-0.8, 0.5, 0.1}, false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  auto flat = [kk](const double* s) { return Vec3{s[1] * std::cos(kk * s[2]), s[1] * std::sin(kk * s[2]), s[3]}; };
  const Vec3 p0 = flat(y);
  const double tp0 = x[0] - a * x[2];
  std::vector<std::pair<double, Vec3>> pts;
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 400;
  cfg.lambda_max = 40;  // a bounded stretch: the test compares absolute positions
  auto cb = [&](const StepView& st) {
    pts.emplace_back(st.y1[0] - a * st.y1[2], flat(st.y1));
    return StepAction::Continue;
  };
  m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  ASSERT_GT(pts.size(), 10u);
  const Vec3 v = (pts.back().second - p0) * (1.0 / (pts.back().first - tp0));
  EXPECT_NEAR(norm(v), 1.0, 1e-8);
  for (const auto& [tp, p] : pts) EXPECT_LT(norm(p - (p0 + v * (tp - tp0))), 1e-8);
}

/// AlcubierreWarpSimple rescales a light ray's k to |k^t| = 1 after every accepted step (Motion4D's
/// resize); timelike geodesics are not rescaled and keep their normalization.
TEST(MetricsCatalogue, AlcubierreRescalesKtToOneAfterEveryStep) {
  for (const std::string name : {"AlcubierreWarpSimple"}) {
    SCOPED_TRACE(name);
    const auto m = make_metric(name, {{"vs", 1.5}});
    const Vec4 x{{0, -3, 0.3, 0.1}};
    const Vec4 k = local_null_direction(m->natural_tetrad(x, TetradKind::Comoving), Vec3{1, 0.05, 0}, false);
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    SolverConfig cfg;
    cfg.eps_abs = 1e-10;
    cfg.max_steps = 400;
    int steps = 0;
    auto cb = [&](const StepView& s) {
      ++steps;
      EXPECT_NEAR(std::fabs(s.y1[4]), 1.0, 1e-15);
      return StepAction::Continue;
    };
    m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
    EXPECT_GT(steps, 20);
    // Timelike geodesics keep their normalization (no rescaling).
    const Vec4 u = local_four_velocity(m->natural_tetrad(x, TetradKind::Comoving), Vec3{0.2, 0, 0});
    double z[8] = {x[0], x[1], x[2], x[3], u[0], u[1], u[2], u[3]};
    cfg.type = GeodesicType::Timelike;
    cfg.max_steps = 50;
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, z, 0.0, {});
    EXPECT_LT(std::fabs(r.constraint_drift), 1e-8);
  }
}

/// Majumdar–Papapetrou is an electrovacuum (traceless Maxwell stress): R = g^ab R_ab = 0 while R_ab
/// itself does not vanish; far from the holes U → 1 + (m1 + m2)/r, so g_tt → −(1 − 2(m1 + m2)/r).
TEST(MetricsCatalogue, ExtremeReissnerNordstromDiholeIsElectrovac) {
  const auto m = make_metric("ExtremeReissnerNordstromDihole", {{"m1", 1.0}, {"m2", 0.5}});
  std::mt19937 rng(3);
  for (int i = 0; i < 10; ++i) {
    const Vec4 x{{uni(rng, -3, 3), uni(rng, -4, 4), uni(rng, -4, 4), uni(rng, -4, 4)}};
    if (!m->is_valid(x)) continue;
    mc::expect_christoffel_matches_ad(*m, x, mc::kRuleRel, mc::kRuleFloorFrac);
    double scale = 0;
    const Mat4 ric = mc::ricci(*m, x, &scale);
    Mat4 g;
    m->metric_tensor(x, g);
    const Mat4 gi = invert(g);
    double R = 0, rmax = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        R += gi[a][b] * ric[a][b];
        rmax = std::max(rmax, std::fabs(ric[a][b]));
      }
    EXPECT_LT(std::fabs(R), 1e-10 * scale);
    EXPECT_GT(rmax, 1e-6 * scale);
  }
  Mat4 g;
  const double r = 1e4;
  m->metric_tensor(Vec4{{0, r, 0, 0}}, g);
  EXPECT_NEAR(-g[0][0], 1.0 - 2.0 * 1.5 / r, 1e-7);
}

/// Kruskal: radial light rays are the straight lines T ± X = const (MTW 31.14, the (T, X) part is
/// conformally flat), the areal radius satisfies (r/r_s − 1) e^(r/r_s) = X² − T² (MTW 31.13), and
/// the static observer moves along the Killing vector X ∂_T + T ∂_X, i.e. keeps X² − T² (and r).
TEST(MetricsCatalogue, KruskalRadialRaysAreStraightAndTheRadiusIsAreal) {
  const double M = 1.3, rs = 2 * M;
  const auto m = make_metric("Kruskal", {{"mass", M}});
  for (const Vec4& x : {Vec4{{0.3, 2.0, 1.0, 0.2}}, Vec4{{-0.4, 0.1, 0.7, 0.0}}, Vec4{{0.2, -3.0, 2.0, 1.0}}}) {
    Vec3 p;
    const int chart = m->to_pseudo_cartesian(x, p);
    const double r = norm(p), u = x[1] * x[1] - x[0] * x[0];
    EXPECT_NEAR((r / rs - 1) * std::exp(r / rs), u, 1e-13 * std::max(1.0, std::fabs(u)));
    // g_θθ = r² (the areal radius), and the inverse map returns the point.
    Mat4 g;
    m->metric_tensor(x, g);
    EXPECT_NEAR(g[2][2], r * r, 1e-13 * r * r);
    const Vec4 back = m->from_pseudo_cartesian(x[0], p, chart);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(back[i], x[i], 1e-9) << i;
  }
  // An ingoing radial light ray from outside through the horizon keeps T + X constant.
  const Vec4 x{{0.0, 1.5, 1.0, 0.3}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{-1, 0, 0}, false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 2000;
  double worst = 0, u_min = 1e300;
  auto cb = [&](const StepView& s) {
    worst = std::max(worst, std::fabs((s.y1[0] + s.y1[1]) - (x[0] + x[1])));
    u_min = std::min(u_min, s.y1[1] * s.y1[1] - s.y1[0] * s.y1[0]);
    return StepAction::Continue;
  };
  const GeodesicResult res = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  // Stops at the singularity break X² − T² + 1 < horizon_eps (kruskal.cpp), i.e. r ≈ r_s √(2 eps).
  EXPECT_EQ(res.reason, StopReason::Invalid) << stop_reason_name(res.reason);
  EXPECT_GE(u_min, -1.0 + m->horizon_eps());
  EXPECT_LT(u_min, -1.0 + 1.01 * m->horizon_eps());
  EXPECT_LT(worst, 1e-9);
  // Static observer: e_(0) ∝ X ∂_T + T ∂_X.
  const Vec4 xs{{0.4, 1.2, 1.0, 0.0}};
  const Tetrad e = m->natural_tetrad(xs, TetradKind::Static);
  EXPECT_NEAR(e[0][1] / e[0][0], xs[0] / xs[1], 1e-15);
  EXPECT_GT(e[0][0], 0.0);
  EXPECT_THROW(m->natural_tetrad(Vec4{{1.0, 0.5, 1.0, 0.0}}, TetradKind::Static), Error);
}

/// Vaidya: a null dust, R_ab = (2 m'(v)/r²) δ^v_a δ^v_b (Poisson, A Relativist's Toolkit (2004)
/// §4.3.5), with m'(v) from a central difference of the mass function written out here; Minkowski
/// (R_ab = 0) for v >= v_l.
TEST(MetricsCatalogue, VaidyaIsANullDustWithTheMassFunctionsRate) {
  const double k = 1.3, sigma = 0.7, vl = 2.0;
  const auto m = make_metric("VaidyaIncRad", {{"k", k}, {"sigma", sigma}, {"vl", vl}});
  auto mass = [&](double v) { return v < vl ? k * std::cbrt(vl - v) * std::pow(std::tanh(sigma * (vl - v)), 2) : 0.0; };
  std::mt19937 rng(7);
  int curved = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec4 x{{uni(rng, -3, 3), uni(rng, 5, 15), uni(rng, 0.3, 2.8), uni(rng, -3, 3)}};
    ASSERT_TRUE(m->is_valid(x));
    mc::expect_christoffel_matches_ad(*m, x, mc::kRuleRel, mc::kRuleFloorFrac);
    for (TetradKind kind : m->info().tetrads) mc::expect_orthonormal(*m, x, kind);
    const double h = 1e-5, dm = (mass(x[0] + h) - mass(x[0] - h)) / (2 * h);
    double scale = 0;
    const Mat4 ric = mc::ricci(*m, x, &scale);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const double ref = (a == 0 && b == 0) ? 2.0 * dm / (x[1] * x[1]) : 0.0;
        // Finite-difference error of m' (h² times the third derivative, rounding/h) ~1e-10 relative; in
        // the flat region v >= v_l the components are rounding noise of Christoffel products ~1/r².
        EXPECT_NEAR(ric[a][b], ref, 1e-7 * std::fabs(2.0 * dm / (x[1] * x[1])) + 1e-14) << a << b << " v " << x[0];
      }
    if (x[0] < vl) ++curved;
  }
  EXPECT_GT(curved, 10);
}

/// Sultana–Dyer: ∂_t is a conformal Killing vector (g = t⁴ ĝ with static ĝ) and ∂_φ a Killing
/// vector, so E = −g(∂_t, k) and L = g(∂_φ, k) are constant along light rays (Wald (1984) App. C.3);
/// the conformally related null geodesics are Schwarzschild's.
TEST(MetricsCatalogue, SultanaDyerLightRaysConserveTheConformalEnergyAndAngularMomentum) {
  const auto m = make_metric("SultanaDyerBlackhole", {{"mass", 0.7}});
  for (TetradKind kind : {TetradKind::Static, TetradKind::Comoving}) {
    const Vec4 x{{2.0, 5.0, 1.2, 0.3}};
    mc::expect_orthonormal(*m, x, kind);
    const Vec4 k = local_null_direction(m->natural_tetrad(x, kind), Vec3{0.3, 0.8, -0.4}, true);
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    auto conserved = [&](const double* s) {
      Mat4 g;
      m->metric_tensor(Vec4{{s[0], s[1], s[2], s[3]}}, g);
      double E = 0, L = 0;
      for (int b = 0; b < 4; ++b) {
        E -= g[0][b] * s[4 + b];
        L += g[3][b] * s[4 + b];
      }
      return std::pair<double, double>{E, L};
    };
    const auto [E0, L0] = conserved(y);
    SolverConfig cfg;
    cfg.eps_abs = 1e-12;
    cfg.max_steps = 300;
    double worst = 0;
    int steps = 0;
    auto cb = [&](const StepView& s) {
      const auto [E, L] = conserved(s.y1);
      worst = std::max({worst, std::fabs(E - E0) / std::fabs(E0), std::fabs(L - L0) / std::fabs(L0)});
      ++steps;
      return StepAction::Continue;
    };
    m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
    EXPECT_GT(steps, 20);
    EXPECT_LT(worst, 1e-8);
  }
}

/// Friedmann dust: the Einstein tensor is that of pressure-free dust at rest in the chart,
/// G_ab = 8πρ u_a u_b with u = ∂_χ/R (no pressure, no flux), and the density falls as ρ ∝ R⁻³
/// (MTW (1973) §27.10), for k = 0, 1, −1 (the Kretschmann scalar is in the registry table).
TEST(MetricsCatalogue, FriedmanIsPressureFreeDustWithRhoR3Constant) {
  for (double k : {0.0, 1.0, -1.0}) {
    SCOPED_TRACE(k);
    const auto m = make_metric("FriedmanNonEmptyNull", {{"k", k}, {"mass", 2.0}});
    double rhoR3_first = 0;
    for (const Vec4& x : {Vec4{{0.7, 0.8, 1.0, 0.2}}, Vec4{{1.3, 0.5, 2.0, -1.0}}, Vec4{{2.2, 1.4, 0.6, 3.0}}}) {
      ASSERT_TRUE(m->is_valid(x));
      mc::expect_christoffel_matches_ad(*m, x, mc::kRuleRel, mc::kRuleFloorFrac);
      Mat4 g;
      m->metric_tensor(x, g);
      const Mat4 gi = invert(g);
      double scale = 0;
      const Mat4 ric = mc::ricci(*m, x, &scale);
      double Rs = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) Rs += gi[a][b] * ric[a][b];
      Mat4 G;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) G[a][b] = ric[a][b] - 0.5 * Rs * g[a][b];
      const double R2 = -g[0][0];  // R(χ)², u_χ = −R
      const double rho8pi = G[0][0] / R2;
      EXPECT_GT(rho8pi, 0.0);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          if (a != 0 || b != 0) {
            EXPECT_NEAR(G[a][b], 0.0, 1e-10 * scale * std::max(1.0, std::fabs(g[a][b]))) << a << b;
          }
      const double rhoR3 = rho8pi * std::pow(R2, 1.5);
      if (rhoR3_first == 0) rhoR3_first = rhoR3;
      EXPECT_NEAR(rhoR3, rhoR3_first, 1e-9 * rhoR3_first);
    }
  }
}

/// TeoWHl: stationary and axisymmetric, so E = −g(∂_t, k) and L = g(∂_φ, k) are constant along a
/// light ray that passes the throat into the other universe; the default frame is the static
/// observer (e_(0) ∝ ∂_t) and the lnrf frame rotates with ω = −g_tφ/g_φφ = b0²/(2r³) (Teo, PRD 58
/// (1998) 024014).
TEST(MetricsCatalogue, TeoWHlConservesEnergyAndAngularMomentumThroughTheThroat) {
  const double b0 = 1.4;
  const auto m = make_metric("TeoWHl", {{"b0", b0}});
  const Vec4 x{{0.0, 4.0, 1.3, 0.2}};
  const Tetrad e = m->natural_tetrad(x);
  EXPECT_EQ(e[0][1], 0.0);
  EXPECT_EQ(e[0][3], 0.0);
  const Tetrad lnrf = m->natural_tetrad(x, TetradKind::LNRF);
  const double r = std::sqrt(b0 * b0 + x[1] * x[1]);
  EXPECT_NEAR(lnrf[0][3] / lnrf[0][0], b0 * b0 / (2 * r * r * r), 1e-15);
  const Vec4 k = local_null_direction(e, Vec3{-1.0, 0.1, 0.15}, false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  auto conserved = [&](const double* s) {
    Mat4 g;
    m->metric_tensor(Vec4{{s[0], s[1], s[2], s[3]}}, g);
    double E = 0, L = 0;
    for (int b = 0; b < 4; ++b) {
      E -= g[0][b] * s[4 + b];
      L += g[3][b] * s[4 + b];
    }
    return std::pair<double, double>{E, L};
  };
  const auto [E0, L0] = conserved(y);
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 3000;
  cfg.lambda_max = 30;
  double worst = 0;
  auto cb = [&](const StepView& s) {
    const auto [E, L] = conserved(s.y1);
    worst = std::max({worst, std::fabs(E - E0) / std::fabs(E0), std::fabs(L - L0) / std::fabs(L0)});
    return StepAction::Continue;
  };
  m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_LT(y[1], -4.0);  // through the throat into the other universe
  EXPECT_LT(worst, 1e-9);
}

/// Pravda C-metric: a static axisymmetric vacuum, so ρ = √(−g_qq g_pp) and
/// z = (1 + mA xy (x − y) + xy)/(A² (x + y)²) are Weyl canonical coordinates (the form behind
/// Motion4D's Pravda_C-Metric_Canonical_Coords; Pravda & Pravdová, Czech. J. Phys. 50 (2000) 333):
/// the (x, y) part of the metric is conformal to dρ² + dz², i.e. the map (x, y) → (ρ, z) has
/// orthogonal columns with |∂_x(ρ, z)|²/g_xx = |∂_y(ρ, z)|²/g_yy.
TEST(MetricsCatalogue, PravdaCMetricHasWeylCanonicalCoordinates) {
  const double A = 0.15, mass = 0.8;
  const auto m = make_metric("Pravda_C-Metric", {{"a", A}, {"m", mass}});
  auto rho_z = [&](double x, double y) {
    Mat4 g;
    m->metric_tensor(Vec4{{0, x, y, 0}}, g);
    const double s = x + y;
    return std::pair<double, double>{std::sqrt(-g[0][0] * g[3][3]),
                                     (1 + mass * A * x * y * (x - y) + x * y) / (A * A * s * s)};
  };
  for (const auto& [x, y] : {std::pair{0.2, 2.0}, std::pair{-0.5, 3.0}, std::pair{0.7, 1.6}}) {
    ASSERT_TRUE(m->is_valid(Vec4{{0, x, y, 0}})) << x << " " << y;
    const double h = 1e-6;
    const auto [rxp, zxp] = rho_z(x + h, y);
    const auto [rxm, zxm] = rho_z(x - h, y);
    const auto [ryp, zyp] = rho_z(x, y + h);
    const auto [rym, zym] = rho_z(x, y - h);
    const double rx = (rxp - rxm) / (2 * h), zx = (zxp - zxm) / (2 * h);
    const double ry = (ryp - rym) / (2 * h), zy = (zyp - zym) / (2 * h);
    Mat4 g;
    m->metric_tensor(Vec4{{0, x, y, 0}}, g);
    const double nx = rx * rx + zx * zx, ny = ry * ry + zy * zy;
    EXPECT_NEAR((rx * ry + zx * zy) / std::sqrt(nx * ny), 0.0, 1e-7);
    EXPECT_NEAR((nx / g[1][1]) / (ny / g[2][2]), 1.0, 1e-7);
  }
}

/// Kruskal's escape test (the Schwarzschild photon-sphere criterion in the areal radius): a light ray
/// declared escaped keeps moving outward when followed further (over a stretch only: T and X grow
/// like e^(r/(2 r_s)), so the ray cannot be followed to r ~ 1e4 as in Escape.EscapedRaysNeverTurnBack).
TEST(MetricsCatalogue, KruskalEscapedRaysNeverTurnBack) {
  const auto m = make_metric("Kruskal");
  std::mt19937 rng(5);
  int escaped = 0;
  for (int n = 0; n < 30; ++n) {
    const Vec4 x{{uni(rng, -0.5, 0.5), uni(rng, 2.0, 4.0), uni(rng, 0.3, 2.8), uni(rng, -3, 3)}};
    const Vec3 d{uni(rng, -1, 1), uni(rng, -1, 1), uni(rng, -1, 1)};
    const Vec4 k = local_null_direction(m->natural_tetrad(x), d, n % 2 == 0);
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    SolverConfig cfg;
    cfg.kind = SolverKind::DormandPrince853;
    cfg.eps_abs = 1e-10;
    cfg.max_steps = 20000;
    cfg.escape_radius = 0;
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
    if (r.reason != StopReason::Escaped) continue;
    ++escaped;
    Vec3 p;
    m->to_pseudo_cartesian(Vec4{{y[0], y[1], y[2], y[3]}}, p);
    EXPECT_GT(norm(p), 1.5 * 2.0);  // beyond the photon sphere
    cfg.escape_radius = INFINITY;
    cfg.max_steps = 400;
    double prev = norm(p), worst = 0;
    auto cb = [&](const StepView& s) {
      Vec3 q;
      m->to_pseudo_cartesian(Vec4{{s.y1[0], s.y1[1], s.y1[2], s.y1[3]}}, q);
      worst = std::max(worst, (prev - norm(q)) / prev);
      prev = norm(q);
      return StepAction::Continue;
    };
    m->integrate(cfg, GeodesicSystem::Geodesic, y, r.lambda, cb);
    EXPECT_LE(worst, 1e-12) << "ray " << n;
    EXPECT_GT(prev, 2.0 * r.escape_radius) << "ray " << n;
  }
  EXPECT_GT(escaped, 5);
}

/// C-metric in boost-rotation symmetric coordinates: the boost ζ ∂_τ + τ ∂_ζ and the rotation ∂_φ
/// are Killing vectors (Bičák & Schmidt, PRD 40 (1989) 1827), so g(B, k) and g(∂_φ, k) are constant
/// along a light ray, on both sides of the roof (default tetrad exchanges e_(0) and e_(3) there).
TEST(MetricsCatalogue, PravdaCanonicalConservesBoostAndRotationCharges) {
  const auto m = make_metric("Pravda_C-Metric_Canonical_Coords", {{"a", 0.1}, {"m", 1.0}});
  for (const Vec4& x : {Vec4{{1.0, 1.0, 0.0, 0.2}}, Vec4{{0.3, 1.5, 0.4, 2.0}}}) {
    ASSERT_TRUE(m->is_valid(x));
    mc::expect_christoffel_matches_ad(*m, x, mc::kRuleRel, mc::kRuleFloorFrac);
    const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{0.4, -0.3, 0.8}, true);
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    auto charges = [&](const double* s) {
      Mat4 g;
      m->metric_tensor(Vec4{{s[0], s[1], s[2], s[3]}}, g);
      const double B[4] = {s[3], 0.0, 0.0, s[0]};  // ζ ∂_τ + τ ∂_ζ
      double EB = 0, L = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) EB += g[a][b] * B[a] * s[4 + b];
      for (int b = 0; b < 4; ++b) L += g[2][b] * s[4 + b];
      return std::pair<double, double>{EB, L};
    };
    const auto [E0, L0] = charges(y);
    SolverConfig cfg;
    cfg.eps_abs = 1e-12;
    cfg.max_steps = 300;
    double worst = 0;
    int steps = 0;
    auto cb = [&](const StepView& s) {
      const auto [E, L] = charges(s.y1);
      worst = std::max({worst, std::fabs(E - E0) / std::fabs(E0), std::fabs(L - L0) / std::fabs(L0)});
      ++steps;
      return StepAction::Continue;
    };
    m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
    EXPECT_GT(steps, 20);
    EXPECT_LT(worst, 1e-8);
  }
}

namespace {

/// The largest |R_ab| at x and the Riemann scale there.
double max_ricci(const Metric& m, const Vec4& x, double* scale = nullptr) {
  const Mat4 ric = mc::ricci(m, x, scale);
  double worst = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) worst = std::max(worst, std::fabs(ric[a][b]));
  return worst;
}

}  // namespace

/// SchwarzschildGravWave: ε = 0 is Schwarzschild, and the perturbation solves the linearised vacuum
/// equations, so R_ab = O(ε²): doubling ε quadruples the Ricci tensor (it would double if the
/// perturbation violated the field equations at first order).
TEST(MetricsCatalogue, SchwarzschildGravWaveIsALinearisedVacuumPerturbation) {
  const auto s = make_metric("Schwarzschild", {{"mass", 1.2}});
  const auto w0 = make_metric("SchwarzschildGravWave", {{"mass", 1.2}, {"epsilon", 0.0}, {"sigma", 0.7}});
  const Vec4 x{{0.4, 5.5, 1.1, 0.3}};
  Mat4 gs, gw;
  s->metric_tensor(x, gs);
  w0->metric_tensor(x, gw);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) EXPECT_NEAR(gw[a][b], gs[a][b], 1e-14 * std::fabs(gs[a][a])) << a << b;
  for (const Vec4& y : {x, Vec4{{2.0, 9.0, 0.6, 1.0}}, Vec4{{-1.3, 3.1, 2.0, 0.0}}}) {
    const auto w1 = make_metric("SchwarzschildGravWave", {{"mass", 1.2}, {"epsilon", 1e-3}, {"sigma", 0.7}});
    const auto w2 = make_metric("SchwarzschildGravWave", {{"mass", 1.2}, {"epsilon", 2e-3}, {"sigma", 0.7}});
    double scale = 0;
    const double r1 = max_ricci(*w1, y, &scale), r2 = max_ricci(*w2, y);
    EXPECT_GT(r1, 1e-9 * scale);  // not zero (the test measures the scaling)
    EXPECT_NEAR(r2 / r1, 4.0, 0.05) << "at r = " << y[1];
  }
}

/// PlaneGravWave: flat before (u < −a) and after (0 < u < 1) the wave; inside it the Ricci
/// residual of the truncated sine series (relative to the curvature) decreases with its degree; and a light ray
/// crossing the wave keeps the Killing constants p² k^y, q² k^z and −k^t + k^x (g_ab ξ^a k^b for ξ = ∂_y, ∂_z, ∂_t +
/// ∂_x).
TEST(MetricsCatalogue, PlaneGravWaveIsFlatOutsideTheWaveAndKeepsItsKillingConstants) {
  const auto m = make_metric("PlaneGravWave", {{"long_ext", 1.3}});
  for (const Vec4& x : {Vec4{{0, 2.0, 0.3, -1}}, Vec4{{0.5, 0.2, 1, 2}}}) {  // u = −2 and u = 0.3
    Riemann R;
    m->riemann(x, R);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 4; ++c)
          for (int d = 0; d < 4; ++d) EXPECT_NEAR(R.R[a][b][c][d], 0.0, 1e-13) << a << b << c << d;
  }
  double residual_prev = 1e300;
  for (double degree : {10.0, 30.0, 90.0}) {
    const auto md = make_metric("PlaneGravWave", {{"long_ext", 1.3}, {"degree", degree}});
    double residual = 0;
    for (double u : {-1.1, -0.65, -0.2}) {
      const Vec4 x{{u, 0.0, 0.4, 0.1}};
      double scale = 0;
      residual = std::max(residual, max_ricci(*md, x, &scale) / scale);
      EXPECT_GT(scale, 0.1);
    }
    EXPECT_LT(residual, residual_prev) << "degree " << degree;
    residual_prev = residual;
    std::printf("PlaneGravWave degree %g: max |R_ab| / max |R^a_bcd| = %.3g\n", degree, residual);
  }
  EXPECT_LT(residual_prev, 0.05);
  // A future-directed ray from before the wave, through it and beyond.
  const Vec4 x{{0, 2.0, 0.0, 0.0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{-0.6, 0.5, 0.3}, false);
  auto constants = [&](const double* y) {
    Mat4 g;
    m->metric_tensor(Vec4{{y[0], y[1], y[2], y[3]}}, g);
    return std::array<double, 3>{g[2][2] * y[6], g[3][3] * y[7], -y[4] + y[5]};
  };
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  const auto c0 = constants(y);
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 3000;
  cfg.lambda_max = 3.0;
  double worst = 0, u_max = -1e300;
  auto cb = [&](const StepView& s) {
    const auto c = constants(s.y1);
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::fabs(c[i] - c0[i]));
    u_max = std::max(u_max, s.y1[0] - s.y1[1]);
    return StepAction::Continue;
  };
  m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_GT(u_max, 0.1);  // the ray has crossed the whole wave
  EXPECT_LT(worst, 1e-9);
}

/// PlaneGravWave before the wave (u < −a): flat, with the transverse scales p0, q0 of the objects'
/// coordinates (their gallery thumbnail from u = −20 shows a coordinate circle as an ellipse with
/// axes p0 R, q0 R): p0 q0 = (1 + a/2)² (L(−a) = 1 + a/2), and p0/q0 = e^(2 m(−a)) with
/// m(−a) = ∫_{−a}^0 √(−L″/L) du (file comment of plane_grav_wave.cpp), here by an independent
/// midpoint quadrature, approached by the truncated sine series as its degree grows.
TEST(MetricsCatalogue, PlaneGravWaveBeforeTheWaveScalesYAndZByP0AndQ0) {
  const double a = 1.0;
  const int n = 200000;
  double m_a = 0;
  for (int i = 0; i < n; ++i) {
    const double u = -a + (i + 0.5) * a / n;
    const double L = 1 - u + u * u * u / (a * a) + u * u * u * u / (2 * a * a * a);
    m_a += std::sqrt(-6 * u * (u + a) / (a * a * a * L)) * a / n;
  }
  const double ratio = std::exp(2 * m_a);
  double err_prev = 1e300;
  for (double degree : {10.0, 30.0, 90.0}) {
    const auto m = make_metric("PlaneGravWave", {{"long_ext", a}, {"degree", degree}});
    Mat4 g;
    m->metric_tensor(Vec4{{0, 20, 0.3, -0.2}}, g);  // u = −20
    const double p0 = std::sqrt(g[2][2]), q0 = std::sqrt(g[3][3]);
    EXPECT_NEAR(p0 * q0, std::pow(1 + a / 2, 2), 1e-12);
    const double err = std::fabs(p0 / q0 / ratio - 1);
    EXPECT_LT(err, err_prev) << degree;
    err_prev = err;
  }
  EXPECT_LT(err_prev, 2e-3);  // degree 90: 1.1e-3
}

/// BesselGravWaveCart: vacuum away from the axis too (where J0, J1 come from the library instead of
/// the series), and a light ray keeps the Killing constants of ∂_z and of the rotation
/// x ∂_y − y ∂_x: e^(2U) k^z and g(x ∂_y − y ∂_x, k).
TEST(MetricsCatalogue, BesselGravWaveCartIsVacuumAndKeepsItsKillingConstants) {
  const auto m = make_metric("BesselGravWaveCart", {{"c", 0.8}});
  for (const Vec4& x : {Vec4{{0.3, 3.0, -2.0, 1.0}}, Vec4{{1.9, -0.4, 5.5, 0.0}}, Vec4{{-0.7, 0.5, 0.2, 2.0}}}) {
    double scale = 0;
    const double ric = max_ricci(*m, x, &scale);
    EXPECT_GT(scale, 1e-3);
    EXPECT_LT(ric, 1e-10 * scale) << "at (" << x[1] << ", " << x[2] << ")";
  }
  const Vec4 x{{0.2, 1.0, 0.5, 0.0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{0.8, 0.3, 0.4}, false);
  auto constants = [&](const double* y) {
    Mat4 g;
    m->metric_tensor(Vec4{{y[0], y[1], y[2], y[3]}}, g);
    double L = 0;
    for (int b = 0; b < 4; ++b) L += (y[1] * g[2][b] - y[2] * g[1][b]) * y[4 + b];
    return std::array<double, 2>{g[3][3] * y[7], L};
  };
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  const auto c0 = constants(y);
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 3000;
  cfg.lambda_max = 8.0;
  double worst = 0, rho_max = 0;
  auto cb = [&](const StepView& s) {
    const auto c = constants(s.y1);
    for (int i = 0; i < 2; ++i) worst = std::max(worst, std::fabs(c[i] - c0[i]));
    rho_max = std::max(rho_max, std::hypot(s.y1[1], s.y1[2]));
    return StepAction::Continue;
  };
  m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_GT(rho_max, 2.5);  // into the library branch of J0, J1
  EXPECT_LT(worst, 1e-9);
}

/// HalilsoyWave: α = 0 is the Bessel wave, so its metric equals BesselGravWaveCart's pulled back to
/// cylindrical coordinates (x = ρ cos φ, y = ρ sin φ; two independent implementations); for α != 0
/// it is vacuum and a light ray keeps the Killing constants g(∂_φ, k) and g(∂_z, k) (the
/// cross-polarisation couples φ and z).
TEST(MetricsCatalogue, HalilsoyWaveIsTheBesselWaveAtAlphaZeroAndKeepsItsKillingConstants) {
  const auto h = make_metric("HalilsoyWave", {{"c", 0.9}});
  const auto b = make_metric("BesselGravWaveCart", {{"c", 0.9}});
  for (const Vec4& x : {Vec4{{0.3, 2.5, 0.7, 1.0}}, Vec4{{-1.2, 6.0, 2.5, -3.0}}}) {
    const double rho = x[1], ph = x[2], c = std::cos(ph), s = std::sin(ph);
    Mat4 gb, gh;
    b->metric_tensor(Vec4{{x[0], rho * c, rho * s, x[3]}}, gb);
    h->metric_tensor(x, gh);
    // J^a_μ = ∂X^a/∂x^μ for X = (t, x, y, z), x = (t, ρ, φ, z).
    double J[4][4] = {{1, 0, 0, 0}, {0, c, -rho * s, 0}, {0, s, rho * c, 0}, {0, 0, 0, 1}};
    for (int m = 0; m < 4; ++m)
      for (int n = 0; n < 4; ++n) {
        double v = 0;
        for (int a = 0; a < 4; ++a)
          for (int bb = 0; bb < 4; ++bb) v += J[a][m] * J[bb][n] * gb[a][bb];
        EXPECT_NEAR(gh[m][n], v, 1e-12 * std::max(1.0, std::fabs(v))) << m << n;
      }
  }
  const auto m = make_metric("HalilsoyWave", {{"alpha", 0.5}, {"c", 0.9}});
  const Vec4 x{{0.2, 3.0, 0.5, 0.0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{0.5, 0.6, 0.4}, false);
  auto constants = [&](const double* y) {
    Mat4 g;
    m->metric_tensor(Vec4{{y[0], y[1], y[2], y[3]}}, g);
    std::array<double, 2> c{};
    for (int bb = 0; bb < 4; ++bb) {
      c[0] += g[2][bb] * y[4 + bb];
      c[1] += g[3][bb] * y[4 + bb];
    }
    return c;
  };
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  const auto c0 = constants(y);
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 3000;
  cfg.lambda_max = 6.0;
  double worst = 0;
  int steps = 0;
  auto cb = [&](const StepView& s) {
    const auto c = constants(s.y1);
    for (int i = 0; i < 2; ++i) worst = std::max(worst, std::fabs(c[i] - c0[i]));
    ++steps;
    return StepAction::Continue;
  };
  m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_GT(steps, 20);
  EXPECT_LT(worst, 1e-9);
}

namespace {

/// Einstein–Maxwell (non-null field) test: R = 0 and Rainich's algebraic condition
/// R^a_c R^c_b = ¼ δ^a_b (R_cd R^cd) (Rainich, Trans. Amer. Math. Soc. 27 (1925) 106; Misner & Wheeler, Ann. Phys. 2
/// (1957) 525), relative to the size of R_ab R^ab; also checks that the Ricci tensor does not vanish (not vacuum).
void expect_electrovac_rainich(const Metric& m, const Vec4& x) {
  Mat4 g;
  m.metric_tensor(x, g);
  const Mat4 gi = invert(g);
  double scale = 0;
  const Mat4 ric = mc::ricci(m, x, &scale);
  Mat4 mixed{};  // R^a_b
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c) mixed[a][b] += gi[a][c] * ric[c][b];
  double R = 0, rr = 0, rmax = 0;
  for (int a = 0; a < 4; ++a) {
    R += mixed[a][a];
    for (int b = 0; b < 4; ++b) {
      rr += mixed[a][b] * mixed[b][a];
      rmax = std::max(rmax, std::fabs(mixed[a][b]));
    }
  }
  EXPECT_GT(rmax, 1e-6 * scale) << "Ricci-flat here: the test would prove nothing";
  EXPECT_LT(std::fabs(R), 1e-10 * scale);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      double sq = 0;
      for (int c = 0; c < 4; ++c) sq += mixed[a][c] * mixed[c][b];
      EXPECT_NEAR(sq, a == b ? 0.25 * rr : 0.0, 1e-9 * rr) << a << b;
    }
}

}  // namespace

/// Bonnor's dipole is an Einstein–Maxwell field (R = 0 and Rainich's condition hold, R_ab != 0);
/// at b = 0 it is the Zipoy–Voorhees δ = 2 vacuum with g_tt = −(1 − 2m/r)².
TEST(MetricsCatalogue, BonnorIsElectrovacAndZipoyVoorheesAtZeroDipole) {
  const auto m = make_metric("Bonnor", {{"mass", 1.0}, {"b", 0.8}});
  for (const Vec4& x : {Vec4{{0, 4.0, 0.7, 0.1}}, Vec4{{1, 9.0, 1.5, 2.0}}, Vec4{{0, 3.0, 2.6, 0.0}}}) {
    SCOPED_TRACE(x[1]);
    expect_electrovac_rainich(*m, x);
  }
  const auto zv = make_metric("Bonnor", {{"mass", 1.3}, {"b", 0.0}});
  Mat4 g;
  zv->metric_tensor(Vec4{{0, 5.0, 0.9, 0}}, g);
  EXPECT_NEAR(g[0][0], -std::pow(1.0 - 2.0 * 1.3 / 5.0, 2), 1e-15);
}

/// Bonnor's solution is a black dihole (Emparan, Phys. Rev. D 61 (2000) 104009), which is what its
/// gallery thumbnail shows (docs/gallery/metrics/README.md): total mass 2m (−g_tt = 1 − 4m/r + …);
/// two extreme horizons at the poles of the rod Z = 0, r_b = m + √(m² + b²), where g_tt has a double
/// zero; between them a strut, a conical singularity along the rod: circumference / (2π · proper
/// radius) of the φ circles → (m² + b²)²/b⁴ there (from g_φφ = Z Y² sin²θ/P², g_rr = Y²P²/(Q³Z)
/// with P = b² sin²θ, Q = (m² + b²) sin²θ, Z′ = 2√(m² + b²) at r_b), while the axis beyond the rod
/// is regular (ratio 1). At b = 0 (Zipoy–Voorhees δ = 2) the equatorial photon orbit is the minimum
/// of g_φφ/(−g_tt) = r²/(1 − 2m/r)³ at r = (1 + 2δ) m = 5m, critical impact parameter 5m/0.6^(3/2).
TEST(MetricsCatalogue, BonnorIsADiholeOfMassTwoMWithAStrutAlongTheRod) {
  const double m = 1.3, b = 0.4;
  const auto bon = make_metric("Bonnor", {{"mass", m}, {"b", b}});
  auto g_at = [&](const Metric& mt, double r, double th) {
    Mat4 g;
    mt.metric_tensor(Vec4{{0, r, th, 0.3}}, g);
    return g;
  };
  for (double r : {1e4, 1e5}) EXPECT_NEAR((1.0 + g_at(*bon, r, 1.0)[0][0]) * r, 4.0 * m, 5.0 * m * m / r);
  const double rb = m + std::sqrt(m * m + b * b);
  // Double zero of g_tt on the axis: halving r − r_b quarters it.
  const double gt1 = g_at(*bon, rb * (1 + 2e-5), 0.0)[0][0], gt2 = g_at(*bon, rb * (1 + 1e-5), 0.0)[0][0];
  EXPECT_NEAR(gt1 / gt2, 4.0, 1e-3);
  // Circumference per proper radius of the φ circles, d√g_φφ/ds along the normal of the rod
  // (r direction, at r = r_b (1 + δ)) or of the axis (θ direction, at θ = δ); the limit δ → 0 is
  // approached linearly in δ.
  auto cone_ratio = [&](double r, double th, int dir, double delta) {
    if (dir == 1) {
      r = rb * (1 + delta);
      const double h = 1e-3 * delta * r;
      const double d = (std::sqrt(g_at(*bon, r + h, th)[3][3]) - std::sqrt(g_at(*bon, r - h, th)[3][3])) / (2 * h);
      return d / std::sqrt(g_at(*bon, r, th)[1][1]);
    }
    th = delta;
    const double h = 1e-3 * delta;
    const double d = (std::sqrt(g_at(*bon, r, th + h)[3][3]) - std::sqrt(g_at(*bon, r, th - h)[3][3])) / (2 * h);
    return d / std::sqrt(g_at(*bon, r, th)[2][2]);
  };
  const double strut = std::pow(m * m + b * b, 2) / std::pow(b, 4);
  for (double th : {0.4, 1.2, 2.0}) {
    const double dev6 = cone_ratio(0, th, 1, 1e-6) / strut - 1, dev7 = cone_ratio(0, th, 1, 1e-7) / strut - 1;
    EXPECT_LT(std::fabs(dev7), 1e-3) << th;
    EXPECT_LT(std::fabs(dev7), 0.2 * std::fabs(dev6)) << th;
  }
  for (double r : {rb * 1.5, rb * 4}) EXPECT_NEAR(cone_ratio(r, 0, 2, 1e-6), 1.0, 1e-6) << r;
  // Zipoy–Voorhees δ = 2 photon orbit.
  const auto zv = make_metric("Bonnor", {{"mass", m}, {"b", 0.0}});
  auto h_eq = [&](double r) {
    const Mat4 g = g_at(*zv, r, M_PI / 2);
    return g[3][3] / -g[0][0];
  };
  EXPECT_LT(h_eq(5 * m), h_eq(5 * m * (1 + 1e-3)));
  EXPECT_LT(h_eq(5 * m), h_eq(5 * m * (1 - 1e-3)));
  EXPECT_NEAR(std::sqrt(h_eq(5 * m)), 5 * m / std::pow(0.6, 1.5), 1e-12 * m);
}

/// Bonnor's black disk in the gallery (m = 1, b = 0.1, observer at r = 20 on the equator): a light
/// ray traced back with impact parameter 2 % below the equatorial critical one (the minimum of
/// g_φφ/(−g_tt), found here by golden section) runs down to the rod and stops at the break margin
/// r_b (1 + horizon_eps), with E = −g_tt k^t and L = g_φφ k^φ kept; 2 % above, it turns round
/// outside the photon orbit and leaves.
TEST(MetricsCatalogue, BonnorCapturesLightInsideItsPhotonOrbit) {
  const auto m = make_metric("Bonnor");
  auto h_eq = [&](double r) {
    Mat4 g;
    m->metric_tensor(Vec4{{0, r, M_PI / 2, 0}}, g);
    return g[3][3] / -g[0][0];
  };
  double lo = 2.1, hi = 20.0;
  for (int i = 0; i < 100; ++i) {
    const double a = lo + 0.382 * (hi - lo), c = lo + 0.618 * (hi - lo);
    if (h_eq(a) < h_eq(c))
      hi = c;
    else
      lo = a;
  }
  const double r_ph = 0.5 * (lo + hi), b_c = std::sqrt(h_eq(r_ph));
  EXPECT_NEAR(r_ph, 5.0, 0.01);  // close to the b = 0 orbit 5m
  const double r0 = 20.0, rb = 1.0 + std::sqrt(1.01);
  const Vec4 x{{0, r0, M_PI / 2, 0}};
  for (double f : {0.98, 1.02}) {
    // static observer: sin α = b_imp / √h(r0) off the inward radial direction
    const double sa = f * b_c / std::sqrt(h_eq(r0));
    const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{-std::sqrt(1 - sa * sa), 0, sa}, true);
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    auto EL = [&](const double* s) {
      Mat4 g;
      m->metric_tensor(Vec4{{s[0], s[1], s[2], s[3]}}, g);
      return std::array<double, 2>{-g[0][0] * s[4], g[3][3] * s[7]};
    };
    const auto c0 = EL(y);
    double r_min = r0;
    SolverConfig cfg;
    cfg.eps_abs = 1e-8;
    cfg.max_steps = 5000;
    cfg.lambda_max = 200.0;
    const GeodesicResult res = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, [&](const StepView& s) {
      r_min = std::min(r_min, s.y1[1]);
      return StepAction::Continue;
    });
    const auto c1 = EL(y);
    EXPECT_NEAR(c1[0] / c0[0], 1.0, 1e-6) << f;
    EXPECT_NEAR(c1[1] / c0[1], 1.0, 1e-6) << f;
    if (f < 1) {
      EXPECT_EQ(res.reason, StopReason::Invalid) << stop_reason_name(res.reason);
      EXPECT_LT(y[1], rb * (1 + 1.01 * m->horizon_eps()));
    } else {
      EXPECT_NE(res.reason, StopReason::Invalid);
      EXPECT_GT(r_min, r_ph);
      EXPECT_GT(y[1], r0);
    }
  }
}

/// Petrov_Type_D_C_ES (a = −1, b = 1): the static region y > y0 = 1.3247 (the real root of
/// G(y) = y³ − y − 1) ends at the Killing horizon G = 0, and light falls to it whichever way it is
/// sent: rays traced back from the sample position in eight directions (the thumbnail's camera looks
/// along +y) all stop at the break margin G < horizon_eps, with E = G k^t/(x + y)² kept. Hence the
/// gallery puts sky and ring inside the static region (docs/gallery/make_metric_gallery.py).
TEST(MetricsCatalogue, PetrovTypeDCLightFallsToTheHorizonFromEveryDirection) {
  const auto m = make_metric("Petrov_Type_D_C_ES");
  const Vec4 x{{0, 0, 1.0, 1.5}};
  double y0 = 1.3;  // Newton on G(y) = y^3 - y - 1
  for (int i = 0; i < 50; ++i) y0 -= (y0 * y0 * y0 - y0 - 1) / (3 * y0 * y0 - 1);
  const double eps_h = m->horizon_eps();
  for (const Vec3& d : {Vec3{0, 0.2, 1}, Vec3{0.3, -0.3, 1}, Vec3{0, 1, 0}, Vec3{0, -1, 0}, Vec3{1, 0, 0},
                        Vec3{-1, 0.5, 0.2}, Vec3{0.2, 0.1, -1}, Vec3{0.5, 0.5, 0.5}}) {
    const Vec4 k = local_null_direction(m->natural_tetrad(x), d, true);
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    auto E = [](const double* s) {
      const double G = s[3] * s[3] * s[3] - s[3] - 1, q = s[2] + s[3];
      return G * s[4] / (q * q);
    };
    const double e0 = E(y);
    SolverConfig cfg;
    cfg.eps_abs = 1e-8;
    cfg.max_steps = 5000;
    const GeodesicResult res = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
    const std::string what =
        "d (" + std::to_string(d.x) + ", " + std::to_string(d.y) + ", " + std::to_string(d.z) + ")";
    EXPECT_EQ(res.reason, StopReason::Invalid) << what << ": " << stop_reason_name(res.reason);
    EXPECT_NEAR(y[3], y0, 2 * eps_h) << what;  // G′(y0) = 4.26: G = eps_h at y0 + eps_h/4.26
    EXPECT_NEAR(E(y) / e0, 1.0, 1e-6) << what;
  }
}

/// AlcubierreWarp: light rays through the bubble wall keep g(k,k) = 0 to 1e-8 of the size of its
/// terms without any rescaling or projection of k (Motion4D projects k onto the null cone for this
/// metric; geovis integrates the geodesic equation as it is), for subluminal and superluminal
/// bubbles, from inside and from outside the bubble.
TEST(MetricsCatalogue, AlcubierreWarpRaysThroughTheWallKeepTheirConstraint) {
  double overall = 0;
  for (double vs : {0.5, 1.0, 2.0}) {
    const auto m = make_metric("AlcubierreWarp", {{"vs", vs}});
    for (const Vec4& x : {Vec4{{0, 0, 0.3, 0}}, Vec4{{0, -3, 0.2, 0.1}}, Vec4{{0, 0.5, 1.2, -0.3}}}) {
      const Tetrad e = m->natural_tetrad(x, TetradKind::Comoving);
      for (const Vec3& d : {Vec3{1, 0, 0}, Vec3{-1, 0.3, 0.2}, Vec3{0.2, 1, 0}, Vec3{0.1, -0.2, 1}, Vec3{1, 0.5, 0}}) {
        for (bool past : {true, false}) {
          const Vec4 k = local_null_direction(e, d, past);
          double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
          SolverConfig cfg;
          cfg.kind = SolverKind::DormandPrince853;
          cfg.eps_abs = 1e-12;
          cfg.max_steps = 1000;
          cfg.lambda_max = 10.0;
          cfg.constraint_tol = 1e300;
          double worst = 0, fmax = 0;
          auto cb = [&](const StepView& s) {
            Mat4 g;
            m->metric_tensor(Vec4{{s.y1[0], s.y1[1], s.y1[2], s.y1[3]}}, g);
            double kk = 0, size = 0;
            for (int a = 0; a < 4; ++a)
              for (int b = 0; b < 4; ++b) {
                kk += g[a][b] * s.y1[4 + a] * s.y1[4 + b];
                size += std::fabs(g[a][b] * s.y1[4 + a] * s.y1[4 + b]);
              }
            worst = std::max(worst, std::fabs(kk) / size);
            fmax = std::max(fmax, std::fabs(g[0][1]));
            overall = std::max(overall, worst);
            return StepAction::Continue;
          };
          const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
          EXPECT_LE(worst, 1e-8) << "vs " << vs << " from x = " << x[1] << ", " << x[2] << " direction " << d.x << ","
                                 << d.y << "," << d.z << (past ? " past" : " future") << " over " << r.steps
                                 << " steps, max |v f| " << fmax;
        }
      }
    }
  }
  std::printf("AlcubierreWarp: worst relative null-constraint drift %.3g\n", overall);
}

/// AlcubierreWarp: with unit lapse the Eulerian observers u = ∂_t + v_s f ∂_x are geodesics
/// (Alcubierre, CQG 11 (1994) L73): a timelike geodesic started with u inside the wall keeps
/// u^t = 1, u^y = u^z = 0 and u^x = v_s f with f from Alcubierre's tanh definition, which
/// the metric evaluates in a different, cancellation-free form.
TEST(MetricsCatalogue, AlcubierreWarpEulerianObserversAreGeodesics) {
  const double sigma = 4.0, R = 1.2, vs = 1.7;
  const auto m = make_metric("AlcubierreWarp", {{"sigma", sigma}, {"r", R}, {"vs", vs}});
  auto f = [&](const double* q) {
    const double rs = std::sqrt((q[1] - vs * q[0]) * (q[1] - vs * q[0]) + q[2] * q[2] + q[3] * q[3]);
    return (std::tanh(sigma * (rs + R)) - std::tanh(sigma * (rs - R))) / (2.0 * std::tanh(sigma * R));
  };
  const Vec4 x0{{0.0, 0.4, 1.0, 0.2}};  // r_s = 1.1, in the wall
  const Tetrad e = m->natural_tetrad(x0, TetradKind::Comoving);
  double y[8] = {x0[0], x0[1], x0[2], x0[3], e[0][0], e[0][1], e[0][2], e[0][3]};
  SolverConfig cfg;
  cfg.type = GeodesicType::Timelike;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 100000;
  double dev = 0;
  auto cb = [&](const StepView& s) {
    const double* q = s.y1;
    dev = std::max({dev, std::fabs(q[4] - 1.0), std::fabs(q[5] - vs * f(q)), std::fabs(q[6]), std::fabs(q[7]),
                    std::fabs(q[0] - s.lambda1)});
    return s.lambda1 > 3.0 ? StepAction::Stop : StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Callback);
  EXPECT_LT(dev, 1e-9);
}

/// ChazyCurzonRot: p = −1 is the static Curzon particle (compared with the Curzon metric, an
/// independent implementation), and for |p| < 1 a light ray keeps the Killing constants g(∂_t, k)
/// and g(∂_φ, k) of the stationary, axisymmetric vacuum.
TEST(MetricsCatalogue, ChazyCurzonRotIsCurzonAtPMinusOneAndKeepsItsKillingConstants) {
  const auto rot = make_metric("ChazyCurzonRot", {{"mass", 1.3}, {"p", -1.0}});
  const auto cur = make_metric("Curzon", {{"mass", 1.3}});
  for (const Vec4& x : {Vec4{{0.3, 2.5, 0.7, 1.0}}, Vec4{{-1.2, 6.0, 2.5, -3.0}}}) {
    Mat4 a, b;
    rot->metric_tensor(x, a);
    cur->metric_tensor(x, b);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(a[i][j], b[i][j], 1e-13 * std::max(1.0, std::fabs(b[i][j]))) << i << j;
  }
  const auto m = make_metric("ChazyCurzonRot", {{"mass", 1.0}, {"p", 0.5}});
  const Vec4 x{{0.0, 4.0, 0.3, 1.0}};
  const Vec4 k = local_null_direction(m->natural_tetrad(x), Vec3{-0.6, 0.5, 0.4}, false);
  auto constants = [&](const double* y) {
    Mat4 g;
    m->metric_tensor(Vec4{{y[0], y[1], y[2], y[3]}}, g);
    std::array<double, 2> c{};
    for (int bb = 0; bb < 4; ++bb) {
      c[0] += g[0][bb] * y[4 + bb];
      c[1] += g[2][bb] * y[4 + bb];
    }
    return c;
  };
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  const auto c0 = constants(y);
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 3000;
  cfg.lambda_max = 20.0;
  double worst = 0;
  int steps = 0;
  auto cb = [&](const StepView& s) {
    const auto c = constants(s.y1);
    for (int i = 0; i < 2; ++i) worst = std::max(worst, std::fabs(c[i] - c0[i]));
    ++steps;
    return StepAction::Continue;
  };
  m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_GT(steps, 20);
  EXPECT_LT(worst, 1e-9);
}

/// TomimatsuSato: p = 1, q = 0 is the static Zipoy–Voorhees δ = 2 solution, g_tt = −((x − 1)/(x + 1))²;
/// far out g_tt -> −(1 − 2M/R) with M = 2k/p and R = k x; the pseudo-Cartesian map inverts.
TEST(MetricsCatalogue, TomimatsuSatoLimitsAndChart) {
  const auto zv = make_metric("TomimatsuSato", {{"k", 0.8}, {"p", 1.0}, {"q", 0.0}});
  for (const Vec4& x : {Vec4{{0, 1.7, 0.3, 0}}, Vec4{{0, 4.0, -0.8, 1}}}) {
    Mat4 g;
    zv->metric_tensor(x, g);
    EXPECT_NEAR(g[0][0], -std::pow((x[1] - 1) / (x[1] + 1), 2), 1e-14);
    EXPECT_EQ(g[0][3], 0.0);
  }
  const double k = 0.6, p = 0.8;
  const auto m = make_metric("TomimatsuSato", {{"k", k}, {"p", p}, {"q", 0.6}});
  const double x = 1e5;
  Mat4 g;
  m->metric_tensor(Vec4{{0, x, 0.2, 0}}, g);
  const double M = 2 * k / p, R = k * x;
  EXPECT_NEAR(-g[0][0], 1.0 - 2.0 * M / R, 10.0 * M * M / (R * R));
  const Vec4 X{{0.5, 2.3, -0.4, 1.1}};
  Vec3 c;
  m->to_pseudo_cartesian(X, c);
  const Vec4 back = m->from_pseudo_cartesian(0.5, c);
  for (int i = 1; i < 4; ++i) EXPECT_NEAR(back[i], X[i], 1e-12) << i;
}

/// Glampedakis: epsilon = 0 is Kerr (compared with KerrBL, an independent implementation), and for
/// a = 0 the quadrupole deviation solves the vacuum equations linearised about Schwarzschild:
/// doubling epsilon quadruples the Ricci tensor.
TEST(MetricsCatalogue, GlampedakisIsKerrPlusALinearisedVacuumQuadrupole) {
  const auto gk = make_metric("Glampedakis", {{"mass", 1.1}, {"angmom", 0.6}, {"epsilon", 0.0}});
  const auto kerr = make_metric("KerrBL", {{"mass", 1.1}, {"angmom", 0.6}});
  for (const Vec4& x : {Vec4{{0, 4.0, 0.7, 0.1}}, Vec4{{1, 9.0, 2.0, 2.0}}}) {
    Mat4 a, b;
    gk->metric_tensor(x, a);
    kerr->metric_tensor(x, b);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(a[i][j], b[i][j], 1e-13 * std::max(1.0, std::fabs(b[i][j]))) << i << j;
  }
  for (const Vec4& x : {Vec4{{0, 4.5, 0.7, 0.1}}, Vec4{{1, 9.0, 1.2, 2.0}}}) {
    const auto m1 = make_metric("Glampedakis", {{"mass", 1.0}, {"epsilon", 1e-3}});
    const auto m2 = make_metric("Glampedakis", {{"mass", 1.0}, {"epsilon", 2e-3}});
    double scale = 0;
    const double r1 = max_ricci(*m1, x, &scale), r2 = max_ricci(*m2, x);
    EXPECT_GT(r1, 1e-12 * scale);
    EXPECT_NEAR(r2 / r1, 4.0, 0.05) << "at r = " << x[1];
  }
}

/// HartleThorneGB is the quasi-Kerr metric with epsilon = eta a² (Motion4D writes its components
/// out separately; here both share quasi_kerr.h, so the check is that the parameters map).
TEST(MetricsCatalogue, HartleThorneGBIsQuasiKerrWithEpsilonEtaASquared) {
  const auto ht = make_metric("HartleThorneGB", {{"mass", 1.3}, {"angmom", 0.4}, {"eta", 2.5}});
  const auto gb = make_metric("Glampedakis", {{"mass", 1.3}, {"angmom", 0.4}, {"epsilon", 2.5 * 0.16}});
  const Vec4 x{{0, 6.0, 0.8, 0.2}};
  Mat4 a, b;
  ht->metric_tensor(x, a);
  gb->metric_tensor(x, b);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(a[i][j], b[i][j], 1e-14 * std::max(1.0, std::fabs(b[i][j]))) << i << j;
}

/// ErezRosenVar: vacuum for large |q| and close in (where the q² part of γ matters), and far out
/// g_tt = −e^(2ψ) with ψ -> ½ ln(1 − 2m/r) − (2/15) q (m/r)³ P2(cos θ) (the Newtonian quadrupole;
/// the leading corrections are O((m/r)⁴)).
TEST(MetricsCatalogue, ErezRosenVarIsVacuumWithANewtonianQuadrupoleFarOut) {
  const auto m = make_metric("ErezRosenVar", {{"mass", 1.0}, {"q", 2.5}});
  for (const Vec4& x : {Vec4{{0, 2.3, 0.4, 0}}, Vec4{{0, 3.5, 1.2, 1}}, Vec4{{0, 8.0, 2.5, 2}}}) {
    double scale = 0;
    const double ric = max_ricci(*m, x, &scale);
    EXPECT_LT(ric, 1e-10 * scale) << "at r = " << x[1];
  }
  const double q = 0.6, r = 200.0, th = 0.7;
  const auto w = make_metric("ErezRosenVar", {{"mass", 1.0}, {"q", q}});
  Mat4 g;
  w->metric_tensor(Vec4{{0, r, th, 0}}, g);
  const double P2 = 0.5 * (3 * std::cos(th) * std::cos(th) - 1);
  const double psi = 0.5 * std::log(-g[0][0]);
  const double quad = psi - 0.5 * std::log(1 - 2 / r);
  EXPECT_NEAR(quad, -2.0 / 15.0 * q * P2 / (r * r * r), 5.0 * q / std::pow(r, 4));
}
