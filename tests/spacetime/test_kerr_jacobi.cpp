// The Jacobi system of Kerr and Schwarzschild light rays through the Mino-time flow and the
// Walker–Penrose screen (spacetime/kerr_jacobi.h) against the independent coordinate Jacobi system
// (spacetime/jacobi.h: parallel transport of the Sachs basis and the geodesic deviation equation
// with the closed-form KerrBL terms, checked against the Riemann tensor in test_jacobi.cpp), on
// many rays: past the photon sphere and near the polar axis included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "spacetime/jacobi.h"
#include "spacetime/kerr_jacobi.h"
#include "spacetime/metric_registry.h"

using namespace geovis;

namespace {

constexpr double kPi = 3.14159265358979323846;

SolverConfig config(bool separable, double eps, double lambda_max) {
  SolverConfig cfg;
  cfg.kind = SolverKind::DormandPrince853;
  cfg.eps_abs = eps;
  cfg.max_steps = 20000;  // rays into the hole: the coordinate fields diverge at the horizon
  cfg.lambda_max = lambda_max;
  cfg.separable = separable;
  return cfg;
}

Vec4 slot(const double* y, int i) { return Vec4{{y[i], y[i + 1], y[i + 2], y[i + 3]}}; }

struct Hole {
  const char* name;
  double a;
};

/// Rays from observers at several radii and inclinations, in directions of a random sample plus
/// directions that pass the photon sphere closely (near the edge of the shadow, seen from r = 12)
/// and the polar axis (observer at θ = 0.05, looking across the axis with a small φ component).
struct RaySample {
  Vec4 x;
  Vec3 d;
};
std::vector<RaySample> ray_sample() {
  std::vector<RaySample> rays;
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int n = 0; n < 16; ++n) {
    const Vec4 x{{0, 8 + 40 * U(rng), 0.3 + (kPi - 0.6) * U(rng), 2 * kPi * U(rng)}};
    rays.push_back({x, normalize(Vec3{2 * U(rng) - 1, 2 * U(rng) - 1, 2 * U(rng) - 1})});
  }
  // Seen from r = 12 by the static observer (d = (−1, 0, 0): straight inward), the shadow edge of
  // a = 0 is at sin α = b_c √(1 − 2M/r)/r with b_c = 3√3 M: ≈ 0.354; a = 0.9 shifts it by a few
  // per cent either side (the retrograde edge of a = 0.9 to ≈ 0.52). Just outside it the rays
  // circle the photon sphere before they escape.
  for (double s = 0.40; s <= 0.621; s += 0.02)
    for (double sign : {-1.0, 1.0}) {
      rays.push_back({Vec4{{0, 12, 1.3, 0}}, normalize(Vec3{-std::sqrt(1 - s * s), 0, sign * s})});
      rays.push_back({Vec4{{0, 12, 1.3, 0}}, normalize(Vec3{-std::sqrt(1 - s * s), sign * s, 0})});
    }
  for (double e : {1e-3, 1e-2, 0.05}) {
    rays.push_back({Vec4{{0, 20, 0.05, 0.3}}, normalize(Vec3{-1, -0.1, e})});
    rays.push_back({Vec4{{0, 20, 0.05, 0.3}}, normalize(Vec3{-1, 0.08, -e})});
  }
  return rays;
}

}  // namespace

TEST(KerrJacobi, WalkerPenroseScreenIsTheTransportedSachsBasis) {
  // The coordinate Jacobi system transports s_a numerically (s_a' = −Γ(k, s_a)); the
  // Walker–Penrose screen at the end of the ray, from the observer's s_a, must be the same up to a
  // multiple of k: g(s_a^WP, s_b) = δ_ab, g(s_a^WP, k) = 0. Tolerance: the transport runs at
  // eps_abs = 1e-12 over λ ≤ 60 (≲ 1e4 steps, local errors 1e-12 relative to |s| ~ 1): 1e-7.
  for (const Hole h : {Hole{"KerrBL", 0.9}, Hole{"KerrBL", 0.0}, Hole{"Schwarzschild", 0.0}}) {
    auto m = h.name == std::string("Schwarzschild") ? make_metric("Schwarzschild", {{"mass", 1.0}})
                                                    : make_metric("KerrBL", {{"mass", 1.0}, {"angmom", h.a}});
    int compared = 0;
    for (const RaySample& ray : ray_sample()) {
      const Tetrad e = m->natural_tetrad(ray.x);
      double y[kJacobiDim];
      GeodesicResult r;
      trace_jacobi(*m, config(false, 1e-12, 60.0), ray.x, e, ray.d, 60.0, y, &r);
      if (r.reason != StopReason::LambdaMax) continue;  // into the hole
      double y0[kJacobiDim];
      jacobi_initial_state(ray.x, e, ray.d, y0);
      const Vec4 s0[2] = {slot(y0, kJacobiS1), slot(y0, kJacobiS2)};
      const Vec4 x = slot(y, kJacobiX), k = slot(y, kJacobiK);
      Vec4 s[2];
      ASSERT_TRUE(kerr_transported_screen(1.0, h.a, slot(y0, kJacobiX), slot(y0, kJacobiK), s0, x, k, s));
      Mat4 g;
      m->metric_tensor(x, g);
      for (int a = 0; a < 2; ++a) {
        EXPECT_NEAR(dot(g, s[a], k), 0.0, 1e-7) << h.name << " a=" << h.a;
        for (int b = 0; b < 2; ++b)
          EXPECT_NEAR(dot(g, s[a], slot(y, kJacobiS1 + 4 * b)), a == b ? 1.0 : 0.0, 1e-7)
              << h.name << " a=" << h.a << " r_obs=" << ray.x[1] << " d=" << ray.d.x << "," << ray.d.y << ","
              << ray.d.z;
      }
      ++compared;
    }
    EXPECT_GT(compared, 25) << h.name;
  }
}

TEST(KerrJacobi, MinoFlowDerivativesGiveTheCoordinateJacobiMatrix) {
  // J_ab = g(s_a, Y_b) and the lensing parameters of the Mino path (separable) against the
  // coordinate Jacobi system, both at eps_abs = 1e-11 to the same λ. J grows like λ and its
  // integration error with it: compared relative to max(λ, |J|) at 1e-6 (the rays that pass the
  // photon sphere closely amplify initial-direction errors by e^{γ n} per orbit, γ = π for
  // Schwarzschild; the error budget of both integrations is ~1e-11 per step).
  for (const Hole h : {Hole{"KerrBL", 0.9}, Hole{"Schwarzschild", 0.0}}) {
    auto m = h.name == std::string("Schwarzschild") ? make_metric("Schwarzschild", {{"mass", 1.0}})
                                                    : make_metric("KerrBL", {{"mass", 1.0}, {"angmom", h.a}});
    int compared = 0;
    double worst = 0, worst_angle = 0;
    for (const RaySample& ray : ray_sample()) {
      const Tetrad e = m->natural_tetrad(ray.x);
      const double lam = 70.0;
      double yc[kJacobiDim], ym[kJacobiDim];
      GeodesicResult rc, rm;
      const JacobiParams pc = trace_jacobi(*m, config(false, 1e-11, lam), ray.x, e, ray.d, lam, yc, &rc);
      const JacobiParams pm = trace_jacobi(*m, config(true, 1e-11, lam), ray.x, e, ray.d, lam, ym, &rm);
      if (rc.reason != StopReason::LambdaMax) continue;
      EXPECT_EQ(rm.reason, StopReason::LambdaMax);
      double Jc[4], Jm[4];
      jacobi_matrix(*m, yc, Jc);
      jacobi_matrix(*m, ym, Jm);
      double scale = lam;
      for (double v : Jc) scale = std::max(scale, std::fabs(v));
      for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(Jm[i], Jc[i], 1e-6 * scale) << h.name << " J" << i << " r_obs=" << ray.x[1];
        worst = std::max(worst, std::fabs(Jm[i] - Jc[i]) / scale);
      }
      // The fields themselves (BL components) and their λ-derivatives, which the renderer's
      // Hermite interpolation inside the step that hits uses: the same affine Jacobi fields.
      double yscale = 1.0;
      for (int i = kJacobiY1; i < kJacobiDim; ++i) yscale = std::max(yscale, std::fabs(yc[i]));
      for (int i = kJacobiY1; i < kJacobiDim; ++i) EXPECT_NEAR(ym[i], yc[i], 1e-6 * yscale) << h.name << " slot " << i;
      EXPECT_NEAR(pm.d_plus, pc.d_plus, 1e-6 * scale);
      EXPECT_NEAR(pm.d_minus, pc.d_minus, 1e-6 * scale);
      EXPECT_NEAR(pm.mu, pc.mu, 1e-6 * scale * scale / (pc.d_plus * pc.d_minus) * pc.mu);
      // The angle of the major axis is defined only where the ellipse is not a circle.
      if (pc.d_plus - pc.d_minus > 1e-3 * scale) {
        EXPECT_NEAR(std::remainder(pm.angle - pc.angle, kPi), 0.0, 1e-4);
        worst_angle = std::max(worst_angle, std::fabs(std::remainder(pm.angle - pc.angle, kPi)));
      }
      ++compared;
    }
    EXPECT_GT(compared, 25) << h.name;
    std::printf("%s a=%g: %d rays, worst |ΔJ|/scale %.2e, worst Δangle %.2e\n", h.name, h.a, compared, worst,
                worst_angle);
  }
}

TEST(KerrJacobi, TheRayIsTheGeodesicsBitForBit) {
  // The value part of the Mino-Jacobi state is the ray's own Mino state, evaluated by the same
  // operations (kerr_mino_rhs on the value parts of dual numbers): with the same steps (fixed step
  // size here; adaptive steps also see the fields' error, kerr_jacobi.cpp) x and k at every step
  // are those of the geodesic integration bit for bit.
  auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 0.9}});
  const Vec4 x{{0, 30, 1.2, 0}};
  const Tetrad e = m->natural_tetrad(x);
  SolverConfig cfg;  // the renderer's CashKarp45
  cfg.step_ctrl = false;
  cfg.step_size = 0.25;
  cfg.lambda_max = 60;
  for (const Vec3& d : {Vec3{-1, 0.2, 0.15}, Vec3{-1, 0.05, -0.1}, Vec3{-1, 0.3, 0.3}}) {
    double yj[kJacobiDim];
    jacobi_initial_state(x, e, d, yj);
    double yg[8];
    std::copy(yj, yj + 8, yg);
    std::vector<double> pj, pg;
    auto record = [](std::vector<double>& v) {
      return [&v](const StepView& s) {
        v.insert(v.end(), s.y1, s.y1 + 8);
        return StepAction::Continue;
      };
    };
    auto cj = record(pj), cg = record(pg);
    const GeodesicResult rj = m->integrate(cfg, GeodesicSystem::Jacobi, yj, 0.0, cj);
    const GeodesicResult rg = m->integrate(cfg, GeodesicSystem::Geodesic, yg, 0.0, cg);
    EXPECT_EQ(rj.reason, rg.reason);
    EXPECT_EQ(rj.steps, rg.steps);
    EXPECT_GT(rj.steps, 20);
    ASSERT_EQ(pj.size(), pg.size());
    for (size_t i = 0; i < pj.size(); ++i) EXPECT_EQ(pj[i], pg[i]) << i;
  }
}

TEST(KerrJacobi, RaysThroughThePolarAxisKeepTheCoordinateSystem) {
  // L = 0 (Schwarzschild, a ray in a meridional plane): the Mino path declines, the metric
  // integrates the coordinate Jacobi system: the same result as with separable switched off.
  auto m = make_metric("Schwarzschild", {{"mass", 1.0}});
  const Vec4 x{{0, 20, 0.7, 0.4}};
  const Tetrad e = m->natural_tetrad(x);
  double y[kJacobiDim], yc[kJacobiDim];
  jacobi_initial_state(x, e, Vec3{-1, 0.3, 0}, y);
  std::copy(y, y + kJacobiDim, yc);
  SolverConfig cfg = config(true, 1e-9, 50.0);
  double y2[kJacobiDim];
  std::copy(y, y + kJacobiDim, y2);
  GeodesicResult r;
  EXPECT_FALSE(integrate_kerr_mino_jacobi(1.0, 0.0, 2.0, cfg, y2, 0.0, {}, r));
  m->integrate(cfg, GeodesicSystem::Jacobi, y, 0.0, {});
  cfg.separable = false;
  m->integrate(cfg, GeodesicSystem::Jacobi, yc, 0.0, {});
  for (int i = 0; i < kJacobiDim; ++i) EXPECT_EQ(y[i], yc[i]) << i;
}

TEST(KerrJacobi, AtTheRenderersToleranceJIsAsAccurateAsTheCoordinateSystems) {
  // The renderer's CashKarp45 at eps_abs = 1e-8 (the Kerr disk scene): the error of J against a
  // reference (coordinate system, DOP853 at 1e-11), Mino path and coordinate path side by side.
  // Each is held to eps_abs per step relative to the fields' size, so the global error of J
  // relative to max(λ, |J|) stays below steps · eps_abs (no ray here orbits the hole).
  auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 0.9}});
  double worst_m = 0, worst_c = 0;
  int n = 0;
  for (const RaySample& ray : ray_sample()) {
    const Tetrad e = m->natural_tetrad(ray.x);
    const double lam = 70.0;
    SolverConfig cr = config(false, 1e-8, lam), cm = config(true, 1e-8, lam);
    cr.kind = cm.kind = SolverKind::CashKarp45;
    double yref[kJacobiDim], yc[kJacobiDim], ym[kJacobiDim];
    GeodesicResult rref, rc, rm;
    trace_jacobi(*m, config(false, 1e-11, lam), ray.x, e, ray.d, lam, yref, &rref);
    trace_jacobi(*m, cr, ray.x, e, ray.d, lam, yc, &rc);
    trace_jacobi(*m, cm, ray.x, e, ray.d, lam, ym, &rm);
    if (rref.reason != StopReason::LambdaMax || rc.reason != StopReason::LambdaMax ||
        rm.reason != StopReason::LambdaMax)
      continue;
    double Jr[4], Jc[4], Jm[4];
    jacobi_matrix(*m, yref, Jr);
    jacobi_matrix(*m, yc, Jc);
    jacobi_matrix(*m, ym, Jm);
    double scale = lam;
    for (double v : Jr) scale = std::max(scale, std::fabs(v));
    double em = 0, ec = 0;
    for (int i = 0; i < 4; ++i) {
      em = std::max(em, std::fabs(Jm[i] - Jr[i]) / scale);
      ec = std::max(ec, std::fabs(Jc[i] - Jr[i]) / scale);
    }
    EXPECT_LT(em, rm.steps * 1e-8) << n;
    EXPECT_LT(ec, rc.steps * 1e-8) << n;
    worst_m = std::max(worst_m, em);
    worst_c = std::max(worst_c, ec);
    ++n;
  }
  EXPECT_GT(n, 20);
  std::printf("worst error of J: Mino path %.2e, coordinate path %.2e\n", worst_m, worst_c);
}
