// Parallel and Fermi-Walker transport against analytic results: orthonormality is conserved by
// parallel transport; Thomas precession 2π(γ − 1) per orbit of a circular orbit in Minkowski
// (Jackson, Classical Electrodynamics, §11.8; MTW exercise 6.9).
#include <gtest/gtest.h>

#include <cmath>

#include "spacetime/metric_registry.h"
#include "spacetime/motion_worldline.h"
#include "spacetime/tetrad.h"
#include "spacetime/transport.h"

using namespace geovis;

TEST(Transport, ParallelTransportKeepsTetradOrthonormalOverOneOrbit) {
  // Circular geodesic at r = 6M (Schwarzschild, M = 1): local velocity 1/√(2(r/r_s − 1)) = 0.5
  // along ê_φ (paper §4.2).
  auto m = make_metric("Schwarzschild");
  Vec4 x{{0, 6, M_PI / 2, 0}};
  Tetrad e = boost_tetrad(m->natural_tetrad(x), Vec3{0, 0, 0.5});
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  cfg.max_steps = 100000;
  cfg.lambda_max = 2 * M_PI * std::sqrt(216.0) / std::sqrt(2.0);  // one orbit in proper time
  double worst = 0, rdev = 0;
  auto cb = [&](const StepView& st) {
    Vec4 xs, us;
    Tetrad es;
    unpack_transport_state(st.y1, xs, us, es);
    worst = std::max(worst, orthonormality_error(*m, xs, es));
    rdev = std::max(rdev, std::fabs(xs[1] - 6.0));
    return StepAction::Continue;
  };
  const GeodesicResult r = parallel_transport(*m, cfg, x, e, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::LambdaMax);
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(rdev, 1e-8);
  EXPECT_NEAR(x[3], 2 * M_PI, 1e-7);  // φ after one orbit (dφ/dτ = Ω u^t)
}

namespace {

// Circular orbit of radius R with speed v in Minkowski, parametrized by proper time:
// x = (γτ, R cos φ, R sin φ, 0), φ = Ωγτ, Ω = v/R; u = γ(1, −v sin φ, v cos φ, 0);
// a = du/dτ = −γ²vΩ (0, cos φ, sin φ, 0).
struct CircularOrbit {
  double R, v, gamma, Omega;
  CircularOrbit(double R_, double v_) : R(R_), v(v_), gamma(1 / std::sqrt(1 - v_ * v_)), Omega(v_ / R_) {}
  WorldlineState operator()(double tau) const {
    const double phi = Omega * gamma * tau, c = std::cos(phi), s = std::sin(phi);
    WorldlineState w;
    w.x = Vec4{{gamma * tau, R * c, R * s, 0}};
    w.u = Vec4{{gamma, -gamma * v * s, gamma * v * c, 0}};
    w.a = Vec4{{0, -gamma * gamma * v * Omega * c, -gamma * gamma * v * Omega * s, 0}};
    return w;
  }
  double period_tau() const { return 2 * M_PI / (Omega * gamma); }
};

}  // namespace

TEST(Transport, ThomasPrecessionOfACircularOrbit) {
  auto m = make_metric("Minkowski");
  const CircularOrbit orbit(2.0, 0.6);
  const WorldlineState w0 = orbit(0);
  Tetrad id{};
  for (int a = 0; a < 4; ++a) id[a][a] = 1;
  const Tetrad e0 = tetrad_for_four_velocity(*m, w0.x, id, w0.u);
  auto wl = [&](double tau) { return orbit(tau); };
  double worst = 0;
  auto cb = [&](double tau, const Tetrad& e) {
    const WorldlineState w = orbit(tau);
    worst = std::max(worst, orthonormality_error(*m, w.x, e));
    for (int mu = 0; mu < 4; ++mu) worst = std::max(worst, std::fabs(e[0][mu] - w.u[mu]));  // e0 stays u
  };
  const Tetrad e1 = fermi_walker_transport(*m, wl, 0.0, orbit.period_tau(), e0, {}, cb);
  EXPECT_LT(worst, 1e-9);
  // After one orbit u is the same again; the Fermi-Walker frame has turned by the Thomas angle
  // 2π(γ − 1) about the orbit normal, opposite to the orbital sense.
  Mat4 g;
  m->metric_tensor(w0.x, g);
  const double angle = std::atan2(dot(g, e1[1], e0[2]), dot(g, e1[1], e0[1]));
  const double expected = -2 * M_PI * (orbit.gamma - 1);  // −1.5708 for v = 0.6 (γ = 1.25)
  EXPECT_NEAR(angle, expected, 1e-8);
  EXPECT_NEAR(dot(g, e1[3], e0[3]), 1.0, 1e-10);  // the axis normal to the orbit is not rotated
}

TEST(Transport, FermiWalkerBackwardUndoesForward) {
  auto m = make_metric("Minkowski");
  const CircularOrbit orbit(1.0, 0.4);
  Tetrad id{};
  for (int a = 0; a < 4; ++a) id[a][a] = 1;
  const Tetrad e0 = tetrad_for_four_velocity(*m, orbit(0).x, id, orbit(0).u);
  auto wl = [&](double tau) { return orbit(tau); };
  const Tetrad e1 = fermi_walker_transport(*m, wl, 0.0, 3.0, e0);
  const Tetrad back = fermi_walker_transport(*m, wl, 3.0, 0.0, e1);
  for (int a = 0; a < 4; ++a)
    for (int mu = 0; mu < 4; ++mu) EXPECT_NEAR(back[a][mu], e0[a][mu], 1e-9);
}

TEST(Transport, WorldlineMotionFromSampledEventsGivesThomasPrecession) {
  // The same circular orbit given only as events (coordinate time as curve parameter): the
  // spline reconstruction of u and a is O(h²), so the precession is checked to 1e-4.
  std::shared_ptr<const Metric> m = make_metric("Minkowski");
  const CircularOrbit orbit(2.0, 0.6);
  const int n = 400;
  std::vector<Vec4> events;
  for (int i = 0; i <= n + 20; ++i) events.push_back(orbit(orbit.period_tau() * (i - 10) / n).x);
  Tetrad id{};
  for (int a = 0; a < 4; ++a) id[a][a] = 1;
  const double tau_first = orbit.period_tau() * (-10.0) / n;
  WorldlineMotion wl(m, events, {}, id, tau_first);
  // proper time is recovered from the metric
  EXPECT_NEAR(wl.tau_max() - wl.tau_min(), orbit.period_tau() * (n + 20.0) / n, 1e-6);
  const MotionSample a = wl.at_proper_time(0.0);
  const MotionSample b = wl.at_proper_time(orbit.period_tau());
  EXPECT_NEAR(a.x[1], 2.0, 1e-6);
  EXPECT_NEAR(b.x[1], 2.0, 1e-5);
  EXPECT_LT(orthonormality_error(*m, b.x, b.e), 1e-12);
  Mat4 g;
  m->metric_tensor(a.x, g);
  const double angle = std::atan2(dot(g, b.e[1], a.e[2]), dot(g, b.e[1], a.e[1]));
  EXPECT_NEAR(angle, -2 * M_PI * (orbit.gamma - 1), 1e-4);
  // at_coordinate_time finds the event with x^0 = t
  const MotionSample c = wl.at_coordinate_time(5.0);
  EXPECT_NEAR(c.x[0], 5.0, 1e-12);
}
