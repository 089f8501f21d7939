// fast_sincos, fast_exp and fast_asin (spacetime/fast_math.h) against glibc's sin/cos and asin
// (correctly rounded) and exp (glibc 2.28+: < 1 ulp, correctly rounded in all but rare cases).
#include <gtest/gtest.h>

#include <algorithm>
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

// fast_exp within one ulp of glibc's exp: on the range of the scale factors e^{Ht} of the
// expanding metrics (|Ht| of order 1), the whole range of its polynomial path |x| < 708, tiny
// arguments, and about the reduction's interval edges (k + 1/2)·ln 2 and the multiples k·ln 2
// (where e^x is a power of two); exactly 1 at ±0.
TEST(FastMath, ExpWithinOneUlpOfLibm) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> moderate(-5.0, 5.0), wide(-707.9, 707.9), tiny(-1e-8, 1e-8);
  double worst = 0;
  auto check_exp = [&](double x) { worst = std::max(worst, ulps(fast_exp(x), std::exp(x))); };
  for (int i = 0; i < 300000; ++i) {
    check_exp(moderate(rng));
    check_exp(wide(rng));
    check_exp(tiny(rng));
  }
  for (int k = -1020; k <= 1020; ++k)
    for (int j = -20; j <= 20; ++j) {
      const double a = k * 0.6931471805599453, b = (k + 0.5) * 0.6931471805599453;
      check_exp(a + j * 1e-16 * std::max(1.0, std::fabs(a)));
      check_exp(b + j * 1e-16 * std::max(1.0, std::fabs(b)));
    }
  EXPECT_LE(worst, 1.0);
  RecordProperty("worst_ulps", std::to_string(worst));
  std::printf("fast_exp worst error: %.3f ulp\n", worst);
  EXPECT_EQ(fast_exp(0.0), 1.0);
  EXPECT_EQ(fast_exp(-0.0), 1.0);
}

TEST(FastMath, ExpOutsideThePolynomialRangeIsLibm) {
  for (double x : {708.0, 709.5, -708.0, -745.0, -800.0, 1e300, -1e300}) EXPECT_EQ(fast_exp(x), std::exp(x)) << x;
  EXPECT_EQ(fast_exp(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
  EXPECT_EQ(fast_exp(-std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_TRUE(std::isnan(fast_exp(std::numeric_limits<double>::quiet_NaN())));
}

// fast_asin within one ulp of glibc's asin (correctly rounded) over its whole domain [−1, 1]:
// uniformly, in every binade down to the subnormals (the small-argument range x + x·R(x²)), and
// about the edges of fdlibm's ranges |x| = 1/2 and 0.975 and the end points ±1; odd; exact at 0,
// ±1 gives ±π/2 rounded; NaN outside [−1, 1].
TEST(FastMath, AsinWithinOneUlpOfLibm) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> whole(-1.0, 1.0), mantissa(1.0, 2.0);
  double worst = 0;
  auto check_asin = [&](double x) {
    worst = std::max(worst, ulps(fast_asin(x), std::asin(x)));
    EXPECT_EQ(fast_asin(-x), -fast_asin(x)) << x;
  };
  for (int i = 0; i < 300000; ++i) check_asin(whole(rng));
  for (int e = -1074; e < 0; ++e)
    for (int j = 0; j < 200; ++j) check_asin(std::ldexp(mantissa(rng), e));
  for (const double edge : {0.5, 0.975, 1.0})
    for (int j = -20000; j <= 20000; ++j) {
      const double x = edge + j * 1e-16 * (j % 7 == 0 ? 1e6 : 1.0);
      if (x <= 1.0) check_asin(x);
    }
  EXPECT_LE(worst, 1.0);
  RecordProperty("worst_ulps", std::to_string(worst));
  std::printf("fast_asin worst error: %.3f ulp\n", worst);
  EXPECT_EQ(fast_asin(0.0), 0.0);
  EXPECT_TRUE(std::signbit(fast_asin(-0.0)));
  EXPECT_EQ(fast_asin(1.0), std::asin(1.0));
  EXPECT_EQ(fast_asin(-1.0), std::asin(-1.0));
  for (double x : {1.0000000000000002, -1.5, 1e300, std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN()})
    EXPECT_TRUE(std::isnan(fast_asin(x))) << x;
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
