// KerrBL: closed-form Christoffel symbols and hand-written acceleration against automatic
// differentiation, natural tetrads, parameter errors, and physics with independent expectations:
// the constants of motion E, L_z, Carter's Q and g(k,k) = 0 along a light ray passing close to the
// hole (Carter, Phys. Rev. 174 (1968) 1559), the circular photon orbits at
// r_ph = 2M(1 + cos(2/3 arccos(∓a/M))) (Bardeen, Press & Teukolsky, ApJ 178 (1972) 347, eq. 2.18),
// and Ricci flatness (vacuum).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "metric_checks.h"
#include "spacetime/metric_registry.h"

using namespace geovis;
namespace mc = geovis::metric_checks;

namespace {

struct KerrPoint {
  double mass, a;
  Vec4 x;
};

/// Random parameters (|a| < M) and a point outside the outer horizon, off the axis.
KerrPoint random_kerr_point(std::mt19937& rng, double r_min_over_rplus = 1.05) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  KerrPoint p;
  p.mass = 0.5 + 1.5 * U(rng);
  p.a = (2.0 * U(rng) - 1.0) * 0.99 * p.mass;
  const double rp = p.mass + std::sqrt(p.mass * p.mass - p.a * p.a);
  const double r = rp * r_min_over_rplus + (30.0 - rp * r_min_over_rplus) * U(rng);
  p.x = Vec4{{10.0 * U(rng) - 5.0, r, 0.1 + (M_PI - 0.2) * U(rng), 2.0 * M_PI * U(rng) - M_PI}};
  return p;
}

}  // namespace

TEST(KerrBL, InfoMatchesMotion4D) {
  auto m = make_metric("KerrBL");
  EXPECT_EQ(m->info().coords[1], "r");
  EXPECT_EQ(m->info().coord_type, CoordType::Spherical);
  EXPECT_DOUBLE_EQ(m->param("mass"), 1.0);
  EXPECT_DOUBLE_EQ(m->param("angmom"), 0.5);
  EXPECT_TRUE(m->supports_tetrad(TetradKind::Default));
  EXPECT_TRUE(m->supports_tetrad(TetradKind::Static));
  EXPECT_TRUE(m->supports_tetrad(TetradKind::LNRF));
  EXPECT_FALSE(m->supports_tetrad(TetradKind::Comoving));
  // Pseudo-Cartesian: plain spherical-to-Cartesian map of (r, θ, φ), one chart (as Motion4D).
  const Vec4 x{{0.0, 7.0, 0.8, 2.1}};
  Vec3 p;
  EXPECT_EQ(m->to_pseudo_cartesian(x, p), 0);
  EXPECT_NEAR(p.x, 7.0 * std::sin(0.8) * std::cos(2.1), 1e-14);
  EXPECT_NEAR(p.y, 7.0 * std::sin(0.8) * std::sin(2.1), 1e-14);
  EXPECT_NEAR(p.z, 7.0 * std::cos(0.8), 1e-14);
}

TEST(KerrBL, ClosedChristoffelAndAccelMatchAD) {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  double worst_G = 0, worst_a = 0;
  for (int n = 0; n < 40; ++n) {
    const KerrPoint p = random_kerr_point(rng);
    auto m = make_metric("KerrBL", {{"mass", p.mass}, {"angmom", p.a}});
    worst_G = std::max(worst_G, mc::expect_christoffel_matches_ad(*m, p.x));
    const Vec4 k{{1.0 + 0.5 * U(rng), U(rng), 0.1 * U(rng), 0.1 * U(rng)}};
    worst_a = std::max(worst_a, mc::expect_accel_matches_ad(*m, p.x, k));
  }
  std::printf("KerrBL: worst relative |Gamma_closed - Gamma_AD| = %.3g, |accel - (-Gamma_AD k k)| = %.3g\n", worst_G,
              worst_a);
}

TEST(KerrBL, NaturalTetradsOrthonormal) {
  std::mt19937 rng(7);
  for (int n = 0; n < 25; ++n) {
    const KerrPoint p = random_kerr_point(rng);
    auto m = make_metric("KerrBL", {{"mass", p.mass}, {"angmom", p.a}});
    mc::expect_orthonormal(*m, p.x, TetradKind::Default);
    mc::expect_orthonormal(*m, p.x, TetradKind::LNRF);
    // Static observers exist outside the ergosphere r_E = M + √(M² − a² cos²θ) only.
    const double ct = std::cos(p.x[2]);
    const double r_ergo = p.mass + std::sqrt(p.mass * p.mass - p.a * p.a * ct * ct);
    if (p.x[1] > r_ergo * 1.01) mc::expect_orthonormal(*m, p.x, TetradKind::Static);
  }
}

TEST(KerrBL, LNRFHasZeroAngularMomentumAndDefaultIsLNRF) {
  // Bardeen et al. (1972): the LNRF four-velocity has u_φ = g_φa u^a = 0.
  auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 0.9}});
  const Vec4 x{{0.0, 3.0, 1.1, 0.3}};
  const Tetrad e = m->natural_tetrad(x, TetradKind::LNRF);
  const Tetrad d = m->natural_tetrad(x, TetradKind::Default);
  Mat4 g;
  m->metric_tensor(x, g);
  EXPECT_NEAR(g[3][0] * e[0][0] + g[3][3] * e[0][3], 0.0, 1e-14);
  for (int a = 0; a < 4; ++a)
    for (int mu = 0; mu < 4; ++mu) EXPECT_EQ(e[a][mu], d[a][mu]);
}

TEST(KerrBL, StaticTetradFollowsMotion4DSignConvention) {
  // Motion4D's static Kerr tetrad has e_(3) along −∂_φ; for a → 0 it is Schwarzschild's with e_(3) flipped.
  auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 0.0}});
  const Vec4 x{{0.0, 6.0, 1.0, 0.0}};
  const Tetrad e = m->natural_tetrad(x, TetradKind::Static);
  EXPECT_NEAR(e[0][0], 1.0 / std::sqrt(1.0 - 2.0 / 6.0), 1e-15);
  EXPECT_NEAR(e[3][3], -1.0 / (6.0 * std::sin(1.0)), 1e-15);
  EXPECT_EQ(e[3][0], 0.0);
}

TEST(KerrBL, BadParametersAndPlacesAreErrors) {
  EXPECT_THROW(make_metric("KerrBL", {{"angmom", 1.5}}), Error);             // |a| > M
  EXPECT_THROW(make_metric("KerrBL", {{"angmom", -1.01}}), Error);           // |a| > M
  EXPECT_THROW(make_metric("KerrBL", {{"mass", -1.0}}), Error);              // negative mass
  EXPECT_THROW(make_metric("KerrBL", {{"mass", 0.3}}), Error);               // default a = 0.5 > M
  EXPECT_THROW(make_metric("KerrBL", {{"angmon", 0.1}}), Error);             // unknown key
  EXPECT_NO_THROW(make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 1.0}}));  // extreme Kerr allowed
  auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 0.9}});
  // A rejected value leaves the metric unchanged.
  EXPECT_THROW(m->set_param("angmom", 2.0), Error);
  EXPECT_DOUBLE_EQ(m->param("angmom"), 0.9);
  try {
    m->set_param("angmom", 2.0);
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("angmom"), std::string::npos) << err.what();
  }
  // Static observer inside the ergosphere (r_E = 2M at the equator): clear error; LNRF is fine.
  const Vec4 ergo{{0.0, 1.9, M_PI / 2, 0.0}};
  EXPECT_THROW(m->natural_tetrad(ergo, TetradKind::Static), Error);
  EXPECT_NO_THROW(m->natural_tetrad(ergo, TetradKind::LNRF));
  try {
    m->natural_tetrad(ergo, TetradKind::Static);
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("ergosphere"), std::string::npos) << err.what();
  }
  // Inside the outer horizon r+ = 1 + √(1 − 0.81) ≈ 1.436: not valid, no tetrad.
  const double rp = 1.0 + std::sqrt(1.0 - 0.81);
  EXPECT_FALSE(m->is_valid(Vec4{{0.0, rp * 0.999, 1.0, 0.0}}));
  EXPECT_TRUE(m->is_valid(Vec4{{0.0, rp * 1.001, 1.0, 0.0}}));
  EXPECT_THROW(m->natural_tetrad(Vec4{{0.0, rp * 0.99, 1.0, 0.0}}, TetradKind::LNRF), Error);
  EXPECT_THROW(m->natural_tetrad(Vec4{{0.0, 5.0, 1.0, 0.0}}, TetradKind::Comoving), Error);
}

TEST(KerrBL, RicciFlat) {
  auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 0.9}});
  for (const Vec4& x : {Vec4{{0.0, 2.5, 0.7, 0.0}}, Vec4{{1.0, 4.0, 1.5, 2.0}}, Vec4{{0.0, 9.0, 2.6, -1.0}}}) {
    double scale = 0;
    const Mat4 ric = mc::ricci(*m, x, &scale);
    double worst = 0;
    for (int b = 0; b < 4; ++b)
      for (int d = 0; d < 4; ++d) {
        worst = std::max(worst, std::fabs(ric[b][d]) / scale);
        EXPECT_LE(std::fabs(ric[b][d]), 1e-10 * scale) << b << d;
      }
    std::printf("KerrBL r=%g: max |R_ab| / max |R^a_bcd| = %.3g\n", x[1], worst);
  }
}

namespace {

struct KerrConstants {
  double E, L, Q, C;
};

KerrConstants kerr_constants(const Metric& m, double a, const double* y) {
  const Vec4 x{{y[0], y[1], y[2], y[3]}};
  const Vec4 k{{y[4], y[5], y[6], y[7]}};
  Mat4 g;
  m.metric_tensor(x, g);
  KerrConstants c;
  c.E = -(g[0][0] * k[0] + g[0][3] * k[3]);  // −k_t
  c.L = g[3][0] * k[0] + g[3][3] * k[3];     // k_φ
  const double kth = g[2][2] * k[2];         // k_θ = Σ k^θ
  const double st = std::sin(x[2]), ct = std::cos(x[2]);
  c.Q = kth * kth + ct * ct * (c.L * c.L / (st * st) - a * a * c.E * c.E);
  c.C = dot(g, k, k);
  return c;
}

}  // namespace

namespace {

/// separable: Carter's equations in Mino time (kerr_mino.h), where E, L, Q are parameters of the
/// integration, so this checks the conversion back to (x, k) and the null constraint kept by the
/// integrated d(1/r)/dσ and d(cos θ)/dσ; else the coordinate form, where all four drift.
void constants_along_close_light_ray(bool separable) {
  const double a = 0.9;
  auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", a}});
  const Vec4 x0{{0.0, 20.0, 1.2, 0.0}};
  const Tetrad e = m->natural_tetrad(x0, TetradKind::Default);
  SolverConfig cfg;
  cfg.kind = SolverKind::CashKarp45;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 200000;
  cfg.separable = separable;
  // Find (deterministically) an inward ray that passes r < 4 and escapes again.
  bool tested = false;
  for (double frac = 0.40; frac > 0.05 && !tested; frac -= 0.01) {
    const Vec3 d{-std::sqrt(1.0 - frac * frac), 0.6 * frac, 0.8 * frac};  // e_(1) = radial, e_(2) = θ, e_(3) = φ
    const Vec4 k = local_null_direction(e, d, false);
    double y[8] = {x0[0], x0[1], x0[2], x0[3], k[0], k[1], k[2], k[3]};
    const KerrConstants c0 = kerr_constants(*m, a, y);
    double rmin = 1e300, dE = 0, dL = 0, dQ = 0, dC = 0;
    auto cb = [&](const StepView& s) {
      rmin = std::min(rmin, s.y1[1]);
      const KerrConstants c = kerr_constants(*m, a, s.y1);
      dE = std::max(dE, std::fabs(c.E - c0.E) / std::fabs(c0.E));
      dL = std::max(dL, std::fabs(c.L - c0.L) / std::fabs(c0.L));
      dQ = std::max(dQ, std::fabs(c.Q - c0.Q) / std::fabs(c0.Q));
      dC = std::max(dC, std::fabs(c.C) / (c0.E * c0.E));
      return s.y1[1] > 25.0 ? StepAction::Stop : StepAction::Continue;
    };
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
    if (r.reason != StopReason::Callback || rmin >= 4.0) continue;  // captured, or not close enough
    tested = true;
    std::printf(
        "KerrBL a=0.9 ray (%s): frac %.2f, r_min %.4f, %d steps; max rel drift E %.2g L %.2g Q %.2g, "
        "|g(k,k)|/E^2 %.2g (Q0 = %.4g)\n",
        separable ? "Mino" : "coordinates", frac, rmin, r.steps, dE, dL, dQ, dC, c0.Q);
    EXPECT_GT(std::fabs(c0.Q), 1.0);  // a genuinely non-equatorial ray
    EXPECT_LE(dE, 1e-9);
    EXPECT_LE(dL, 1e-9);
    EXPECT_LE(dQ, 1e-9);
    EXPECT_LE(dC, 1e-9);
  }
  EXPECT_TRUE(tested) << "no escaping ray with r_min < 4 found";
}

}  // namespace

TEST(KerrBL, ConstantsOfMotionAlongCloseLightRay) {
  constants_along_close_light_ray(false);
  constants_along_close_light_ray(true);
}

namespace {

/// Integrates the equatorial circular photon orbit at r_ph for one revolution and returns the
/// largest |r − r_ph| and |θ − π/2|.
void circular_photon_orbit(double a, bool prograde, bool separable, double& dr_max, double& dth_max,
                           StopReason& reason) {
  auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", a}});
  // Bardeen, Press & Teukolsky (1972) eq. (2.18): r_ph = 2M(1 + cos(2/3 arccos(∓a/M))).
  const double r_ph = 2.0 * (1.0 + std::cos(2.0 / 3.0 * std::acos(prograde ? -a : a)));
  const Vec4 x{{0.0, r_ph, M_PI / 2, 0.0}};
  Mat4 g;
  m->metric_tensor(x, g);
  // k = (1, 0, 0, Ω) null: g_φφ Ω² + 2 g_tφ Ω + g_tt = 0; prograde is the root with Ω > 0 (a > 0).
  const double disc = std::sqrt(g[0][3] * g[0][3] - g[0][0] * g[3][3]);
  const double Om = (-g[0][3] + (prograde ? disc : -disc)) / g[3][3];
  double y[8] = {x[0], x[1], x[2], x[3], 1.0, 0.0, 0.0, Om};
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 100000;
  cfg.separable = separable;
  dr_max = dth_max = 0;
  auto cb = [&](const StepView& s) {
    dr_max = std::max(dr_max, std::fabs(s.y1[1] - r_ph));
    dth_max = std::max(dth_max, std::fabs(s.y1[2] - M_PI / 2));
    return std::fabs(s.y1[3]) > 2 * M_PI ? StepAction::Stop : StepAction::Continue;
  };
  reason = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb).reason;
}

}  // namespace

TEST(KerrBL, CircularPhotonOrbitsStayCircular) {
  for (bool separable : {false, true})
    for (bool prograde : {true, false}) {
      double dr = 0, dth = 0;
      StopReason reason{};
      circular_photon_orbit(0.9, prograde, separable, dr, dth, reason);
      std::printf("KerrBL a=0.9 %s photon orbit (%s): max |r - r_ph| = %.3g over one revolution\n",
                  prograde ? "prograde" : "retrograde", separable ? "Mino" : "coordinates", dr);
      EXPECT_EQ(reason, StopReason::Callback);
      EXPECT_LT(dr, 1e-8);
      EXPECT_LT(dth, 1e-12);
    }
}
