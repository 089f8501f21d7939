// Metric::pseudo_cartesian_jacobian is the derivative of Metric::to_pseudo_cartesian (paper §2.3)
// for every registered metric that has one: checked against central differences of the map at
// the metric's sample position, and the inverse map round-trips.
#include <gtest/gtest.h>

#include <cmath>

#include "spacetime/metric_registry.h"

namespace geovis {
namespace {

class PseudoCartesian : public ::testing::TestWithParam<std::string> {};

TEST_P(PseudoCartesian, JacobianIsTheDerivativeOfTheMap) {
  const auto m = make_metric(GetParam());
  const Vec4 x = m->info().sample_pos;
  double J[3][3];
  if (!m->pseudo_cartesian_jacobian(x, J))
    GTEST_SKIP() << m->name() << " has no closed-form Jacobian (custom coordinates)";
  for (int j = 0; j < 3; ++j) {
    // Central difference, step h: error O(h² |p'''|) ~ 1e-10 for the sample positions' scale.
    const double h = 1e-5 * std::max(1.0, std::fabs(x[j + 1]));
    Vec4 xp = x, xm = x;
    xp[j + 1] += h;
    xm[j + 1] -= h;
    Vec3 pp, pm;
    m->to_pseudo_cartesian(xp, pp);
    m->to_pseudo_cartesian(xm, pm);
    const double d[3] = {(pp.x - pm.x) / (2 * h), (pp.y - pm.y) / (2 * h), (pp.z - pm.z) / (2 * h)};
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(J[i][j], d[i], 1e-6 * std::max(1.0, std::fabs(d[i]))) << m->name() << " J[" << i << "][" << j << "]";
  }
}

TEST_P(PseudoCartesian, RadiusAndChartAreThoseOfTheMap) {
  // Metric::pseudo_cartesian_radius (the renderer's test of a step against the scene's empty
  // ball, render/segment_cull.h) stands for |p| and the chart of to_pseudo_cartesian: equal up to
  // the rounding of p (a few ulps; SegmentCull::kMargin allows 1e-6), at the sample position and
  // at others with the radial coordinate negated (the second chart of the wormholes) and the
  // other coordinates moved.
  const auto m = make_metric(GetParam());
  const Vec4 s = m->info().sample_pos;
  int checked = 0;
  for (const Vec4& x : {s, Vec4{{s[0], -s[1], s[2], s[3]}}, Vec4{{s[0], 3 * s[1], s[2] + 0.3, s[3] + 1.7}},
                        Vec4{{s[0], 0.5 * s[1], s[2] - 0.2, s[3] + 50.0}}}) {
    double radius;
    int chart;
    if (!m->pseudo_cartesian_radius(x, radius, chart)) GTEST_SKIP() << m->name() << " has no shortcut";
    Vec3 p;
    EXPECT_EQ(chart, m->to_pseudo_cartesian(x, p)) << m->name();
    EXPECT_NEAR(radius, norm(p), 1e-14 * norm(p)) << m->name();
    ++checked;
  }
  EXPECT_EQ(checked, 4);
}

TEST(PseudoCartesianRadius, GivenWhereTheMapIsKnownAndOnlyThere) {
  double radius;
  int chart;
  // Spherical coordinates with the default map: |r|; Morris–Thorne: |l|, chart 1 for l <= 0.
  EXPECT_TRUE(make_metric("Schwarzschild")->pseudo_cartesian_radius(Vec4{{0, 7, 1, 2}}, radius, chart));
  EXPECT_EQ(radius, 7.0);
  EXPECT_EQ(chart, 0);
  EXPECT_TRUE(make_metric("MorrisThorne")->pseudo_cartesian_radius(Vec4{{0, -4, 1, 2}}, radius, chart));
  EXPECT_EQ(radius, 4.0);
  EXPECT_EQ(chart, 1);
  // A metric with its own map and no radius of its own: none.
  EXPECT_FALSE(make_metric("Kruskal")->pseudo_cartesian_radius(Vec4{{0, 0.5, 0.1, 1}}, radius, chart));
}

std::string name_of(const ::testing::TestParamInfo<std::string>& info) {
  std::string n = info.param;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Registry, PseudoCartesian, ::testing::ValuesIn(metric_names()), name_of);

}  // namespace
}  // namespace geovis
