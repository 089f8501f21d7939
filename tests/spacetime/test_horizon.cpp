// The central surfaces of spacetime/horizon.h against the metrics themselves: at a horizon the
// static Killing vector becomes null (g_tt = 0 for the static metrics; Δ = 0, i.e. 1/g_rr = 0, for
// Kerr), and the coordinates' break condition (Metric::is_valid) lies at or just outside it.
#include <gtest/gtest.h>

#include <cmath>

#include "spacetime/horizon.h"
#include "spacetime/metric_registry.h"

namespace geovis {
namespace {

Mat4 g_at(const Metric& m, double r) {
  Mat4 g;
  m.metric_tensor(Vec4{{0, r, M_PI / 2, 0}}, g);
  return g;
}

TEST(CentralSurface, SchwarzschildHorizonWhereGttVanishes) {
  const auto m = make_metric("Schwarzschild", {{"mass", 1.5}});
  const auto s = central_surface(*m);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->kind, "horizon");
  EXPECT_DOUBLE_EQ(s->radius, 3.0);
  EXPECT_LT(g_at(*m, 3.0 * (1 + 1e-9))[0][0], 0);  // timelike outside
  EXPECT_GT(g_at(*m, 3.0 * (1 - 1e-9))[0][0], 0);  // spacelike inside
  EXPECT_FALSE(m->is_valid(Vec4{{0, 3.0 * (1 - 1e-6), M_PI / 2, 0}}));
  EXPECT_TRUE(m->is_valid(Vec4{{0, 3.0 * 1.1, M_PI / 2, 0}}));
}

TEST(CentralSurface, ReissnerNordstromOuterHorizon) {
  const auto m = make_metric("ReissnerNordstrom", {{"mass", 1.0}, {"charge", 0.6}});
  const auto s = central_surface(*m);
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->radius, 1.8);  // 1 + sqrt(1 - 0.36)
  EXPECT_LT(g_at(*m, 1.8 * (1 + 1e-9))[0][0], 0);
  EXPECT_GT(g_at(*m, 1.8 * (1 - 1e-9))[0][0], 0);
  EXPECT_FALSE(central_surface(*make_metric("ReissnerNordstrom", {{"mass", 1.0}, {"charge", 1.2}})));  // naked
}

TEST(CentralSurface, KerrOuterHorizonWhereDeltaVanishes) {
  const auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 0.8}});
  const auto s = central_surface(*m);
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->radius, 1.6);  // 1 + sqrt(1 - 0.64)
  // g_rr = Σ/Δ: 1/g_rr = Δ/Σ changes sign at r+.
  EXPECT_GT(1 / g_at(*m, 1.6 * (1 + 1e-9))[1][1], 0);
  EXPECT_LT(1 / g_at(*m, 1.6 * (1 - 1e-9))[1][1], 0);
  // Extreme Kerr: one horizon at r = M (naked singularities are refused by the metric itself).
  EXPECT_DOUBLE_EQ(central_surface(*make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 1.0}}))->radius, 1.0);
}

TEST(CentralSurface, IsotropicChartHorizonIsRhoHalfMass) {
  const auto m = make_metric("SchwarzschildIsotropic", {{"mass", 2.0}});
  const auto s = central_surface(*m);
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->radius, 1.0);
  // Areal radius r = ρ(1 + M/(2ρ))² is 2M there.
  EXPECT_DOUBLE_EQ(s->radius * std::pow(1 + 2.0 / (2 * s->radius), 2), 4.0);
  Mat4 g;
  m->metric_tensor(Vec4{{0, 1.0, 0, 0}}, g);  // Cartesian isotropic coordinates, |x| = ρ
  EXPECT_NEAR(g[0][0], 0.0, 1e-15);
}

TEST(CentralSurface, WormholeThroatAndMetricsWithoutOne) {
  const auto s = central_surface(*make_metric("MorrisThorne", {}));
  ASSERT_TRUE(s);
  EXPECT_EQ(s->kind, "throat");
  EXPECT_EQ(s->radius, 0.0);
  EXPECT_FALSE(central_surface(*make_metric("Minkowski", {})));
  EXPECT_FALSE(central_surface(*make_metric("Schwarzschild", {{"mass", 0.0}})));
}

}  // namespace
}  // namespace geovis
