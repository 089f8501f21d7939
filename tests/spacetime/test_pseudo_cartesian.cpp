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

std::string name_of(const ::testing::TestParamInfo<std::string>& info) {
  std::string n = info.param;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Registry, PseudoCartesian, ::testing::ValuesIn(metric_names()), name_of);

}  // namespace
}  // namespace geovis
