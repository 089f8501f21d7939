// Smoke test of the foundation: AD Christoffels equal the closed form, and the photon sphere.
#include <gtest/gtest.h>

#include <cmath>

#include "spacetime/metric_registry.h"

using namespace geovis;

TEST(SchwarzschildBasic, ClosedFormChristoffelMatchesAD) {
  auto m = make_metric("Schwarzschild", {{"mass", 1.3}});
  const Vec4 x{{0.3, 7.1, 1.1, 0.4}};
  Christoffel a, b;
  m->christoffel(x, a);
  m->christoffel_ad(x, b);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) EXPECT_NEAR(a.G[i][j][k], b.G[i][j][k], 1e-12) << i << j << k;
}

TEST(SchwarzschildBasic, CircularPhotonOrbitStaysAtThreeM) {
  auto m = make_metric("Schwarzschild");
  const Vec4 x{{0, 3.0, M_PI / 2, 0}};
  const Tetrad e = m->natural_tetrad(x);
  const Vec4 k = local_null_direction(e, Vec3{0, 0, 1}, false);
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 100000;
  double rmax = 0;
  auto cb = [&](const StepView& s) {
    rmax = std::max(rmax, std::fabs(s.y1[1] - 3.0));
    return s.y1[3] > 2 * M_PI ? StepAction::Stop : StepAction::Continue;
  };
  const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::Callback);
  EXPECT_LT(rmax, 1e-8);
}
