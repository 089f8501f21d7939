// Circular equatorial geodesics (spacetime/circular_orbit.h) against the closed forms: the
// Schwarzschild orbit as the paper's §5 writes it in the static frame, u = γ(e_t + β e_φ) with
// β = 1/√(2(r/r_s − 1)), and the prograde Kerr orbit of Bardeen, Press & Teukolsky, ApJ 178 (1972)
// 347, eqs. 2.16 and 2.12: Ω = √M/(r^{3/2} + a√M), u^t = (r^{3/2} + a√M)/(r^{3/4}√(r^{3/2} − 3M√r + 2a√M)).
#include <gtest/gtest.h>

#include <cmath>

#include "spacetime/circular_orbit.h"
#include "spacetime/metric_registry.h"

namespace geovis {
namespace {

TEST(CircularOrbit, SchwarzschildIsTheStaticFrameVelocityOfThePaper) {
  auto m = make_metric("Schwarzschild");
  m->set_param("mass", 1.5);
  const double M = 1.5, rs = 2 * M;
  for (double r : {3.1 * M, 6 * M, 10 * M, 47.5 * M}) {
    const Vec4 x{{3.0, r, M_PI / 2, 0.7}};
    Vec4 u;
    ASSERT_TRUE(circular_orbit_velocity(*m, x, u)) << r;
    const double beta = 1 / std::sqrt(2 * (r / rs - 1));
    const Vec4 expected = local_four_velocity(m->natural_tetrad(x, TetradKind::Static), Vec3{0, 0, beta});
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(u[i], expected[i], 1e-12 * std::fabs(expected[0])) << r << " " << i;
    EXPECT_NEAR(u[0], 1 / std::sqrt(1 - 3 * M / r), 1e-12);  // u^t = 1/√(1 − 3M/r)
  }
}

TEST(CircularOrbit, ThetaIsTakenInTheEquatorialPlane) {
  auto m = make_metric("Schwarzschild");
  Vec4 u, ue;
  ASSERT_TRUE(circular_orbit_velocity(*m, Vec4{{0, 8, M_PI / 2 + 1e-7, 0}}, u));
  ASSERT_TRUE(circular_orbit_velocity(*m, Vec4{{0, 8, M_PI / 2, 0}}, ue));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(u[i], ue[i]);
}

TEST(CircularOrbit, KerrProgradeOrbitOfBardeenPressTeukolsky) {
  auto m = make_metric("KerrBL");
  const double M = 1.0;
  for (double a : {0.0, 0.5, 0.9, -0.7}) {
    m->set_params({{"mass", M}, {"angmom", a}});
    for (double r : {4.0, 6.0, 12.0, 100.0}) {
      Vec4 u;
      ASSERT_TRUE(circular_orbit_velocity(*m, Vec4{{0, r, M_PI / 2, 1.0}}, u)) << a << " " << r;
      // For a < 0 the orbit turning in +φ is the retrograde one of BPT (their lower sign with |a|).
      const double sa = a * std::sqrt(M), r32 = std::pow(r, 1.5);
      const double omega = std::sqrt(M) / (r32 + sa);
      const double ut = (r32 + sa) / (std::pow(r, 0.75) * std::sqrt(r32 - 3 * M * std::sqrt(r) + 2 * sa));
      EXPECT_NEAR(u[3] / u[0], omega, 1e-12 * omega) << a << " " << r;
      EXPECT_NEAR(u[0], ut, 1e-11 * ut) << a << " " << r;
      EXPECT_EQ(u[1], 0);
      EXPECT_EQ(u[2], 0);
    }
  }
}

TEST(CircularOrbit, NoneInsideThePhotonOrbit) {
  auto m = make_metric("Schwarzschild");  // M = 1: photon orbit at r = 3
  Vec4 u;
  EXPECT_FALSE(circular_orbit_velocity(*m, Vec4{{0, 2.9, M_PI / 2, 0}}, u));
  EXPECT_FALSE(circular_orbit_velocity(*m, Vec4{{0, 1.5, M_PI / 2, 0}}, u));  // inside the horizon
  EXPECT_TRUE(circular_orbit_velocity(*m, Vec4{{0, 3.1, M_PI / 2, 0}}, u));
}

}  // namespace
}  // namespace geovis
