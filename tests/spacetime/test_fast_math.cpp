// fast_sincos (spacetime/fast_math.h) against glibc's correctly rounded sin/cos.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <cstdio>
#include <random>
#include <string>

#include "spacetime/fast_math.h"
#include "spacetime/integrators.h"

using namespace geovis;

namespace {

double ulps(double got, double want) {
  if (got == want) return 0;
  const double a = std::fabs(want);
  const double ulp = std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
  return std::fabs(got - want) / ulp;
}

void check(double x, double& worst) {
  double s, c;
  fast_sincos(x, s, c);
  worst = std::max({worst, ulps(s, std::sin(x)), ulps(c, std::cos(x))});
}

}  // namespace

TEST(FastMath, SinCosWithinTwoUlpsOnThePolarRangeAndBeyond) {
  std::mt19937_64 rng(7);
  double worst = 0;
  std::uniform_real_distribution<double> polar(-0.5, 3.7), wide(-2e4, 2e4), tiny(-1e-3, 1e-3);
  for (int i = 0; i < 300000; ++i) {
    check(polar(rng), worst);
    check(wide(rng), worst);
    check(tiny(rng), worst);
  }
  // Around the multiples of π/2 (where one of the results is tiny) and at the edges of the
  // reduction intervals π/4 + kπ/2.
  for (int k = -400; k <= 400; ++k)
    for (int j = -50; j <= 50; ++j) {
      const double a = k * 1.5707963267948966, b = 0.7853981633974483 + k * 1.5707963267948966;
      check(a + j * 1e-17 * std::max(1.0, std::fabs(a)), worst);
      check(std::nextafter(a, j < 0 ? -10.0 : 10.0) + j * 1e-12, worst);
      check(b + j * 1e-16 * std::max(1.0, std::fabs(b)), worst);
    }
  EXPECT_LE(worst, 2.0);
  RecordProperty("worst_ulps", std::to_string(worst));
  std::printf("worst error: %.3f ulp\n", worst);
  double s, c;
  fast_sincos(0.0, s, c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
  fast_sincos(-0.0, s, c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
}

TEST(FastMath, LargeAndNonFiniteArgumentsFallBackToLibm) {
  for (double x : {1e5, -3e7, 1e300}) {
    double s, c;
    fast_sincos(x, s, c);
    EXPECT_EQ(s, std::sin(x));
    EXPECT_EQ(c, std::cos(x));
  }
  double s, c;
  fast_sincos(std::numeric_limits<double>::quiet_NaN(), s, c);
  EXPECT_TRUE(std::isnan(s) && std::isnan(c));
  fast_sincos(std::numeric_limits<double>::infinity(), s, c);
  EXPECT_TRUE(std::isnan(s) && std::isnan(c));
}

TEST(FastMath, StepControllerRootsMatchPow) {
  double worst5 = 0, worst8 = 0;
  for (double e = -40; e <= 40; e += 0.01) {
    const double x = std::pow(10.0, e);
    worst5 = std::max(worst5, std::fabs(root_q<5>(x) / std::pow(x, 0.2) - 1));
    worst8 = std::max(worst8, std::fabs(root_q<8>(x) / std::pow(x, 0.125) - 1));
  }
  EXPECT_LT(worst5, 1e-9);
  EXPECT_LT(worst8, 1e-15);
}
