// Motions against analytic results: the circular orbit of paper §4.1 (period 92.3436, geodetic
// precession 2π(1 − √(1 − 3M/r)) = 105.44° per orbit), radial free fall from rest (cycloid
// τ = √(r_i³/8M)(η + sin η), r = r_i(1 + cos η)/2; MTW §31.10), and the rolling wheel of paper
// §4.6 (top point moves with 2v/(1 + v²)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "spacetime/metric_registry.h"
#include "spacetime/motion_const_velocity.h"
#include "spacetime/motion_factory.h"
#include "spacetime/motion_geodesic.h"
#include "spacetime/motion_sampled.h"
#include "spacetime/tetrad.h"
#include "support/paper_orbit.h"

using namespace geovis;

namespace {

std::string error_of(auto&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

using testing_support::paper_orbit_params;
using testing_support::paper_solver;

/// Radial free fall from rest at r_i (M = 1): r(τ) from the cycloid, solving τ(η) by Newton.
double cycloid_r(double ri, double tau) {
  const double A = std::sqrt(ri * ri * ri / 8.0);
  double eta = 1.0;
  for (int i = 0; i < 100; ++i) eta -= (A * (eta + std::sin(eta)) - tau) / (A * (1 + std::cos(eta)));
  return 0.5 * ri * (1 + std::cos(eta));
}

}  // namespace

TEST(Motion, CircularOrbitPeriodAndGeodeticPrecession) {
  std::shared_ptr<const Metric> m = make_metric("Schwarzschild");
  const MotionPtr motion = make_motion(paper_orbit_params(), m, paper_solver());
  auto* geo = dynamic_cast<GeodesicMotion*>(motion.get());
  ASSERT_NE(geo, nullptr);
  EXPECT_EQ(geo->forward_stop(), StopReason::LambdaMax);
  EXPECT_EQ(geo->backward_stop(), StopReason::LambdaMax);
  EXPECT_NEAR(motion->tau_min(), -10.0, 1e-9);
  EXPECT_NEAR(motion->tau_max(), 70.0, 1e-9);
  // uniform proper-time sampling with step_size (step_ctrl #f)
  const auto& s = motion->samples();
  EXPECT_EQ(s.size(), 801u);
  EXPECT_NEAR(s[1].tau - s[0].tau, 0.1, 1e-12);
  double rdev = 0, ortho = 0;
  for (const MotionSample& x : s) {
    rdev = std::max(rdev, std::fabs(x.x[1] - 6.0));
    ortho = std::max(ortho, orthonormality_error(*m, x.x, x.e));
  }
  EXPECT_LT(rdev, 1e-8);
  EXPECT_LT(ortho, 1e-10);

  // Coordinate period t_2π = 2π/Ω, Ω = √(M/r³): 92.3436 (paper §4.1).
  const double period = 2 * M_PI * std::sqrt(216.0);
  EXPECT_NEAR(period, 92.3436, 1e-4);
  const MotionSample end = motion->at_coordinate_time(period);
  EXPECT_NEAR(end.x[0], period, 1e-9);
  EXPECT_NEAR(end.x[3], 2 * M_PI, 1e-7);
  EXPECT_NEAR(end.tau, period / std::sqrt(2.0), 1e-7);  // u^t = 1/√(1 − 3M/r) = √2
  EXPECT_LT(orthonormality_error(*m, end.x, end.e), 1e-12);

  // Geodetic precession: compare the transported e3 (initially ê_r) with the initial frame at the
  // same place and velocity (boosted natural tetrad; e3 = ê_r, e2 = −ê_φ').
  const Tetrad ref = boost_tetrad(m->natural_tetrad(end.x), Vec3{0, 0, 0.5});
  Mat4 g;
  m->metric_tensor(end.x, g);
  const double along_r = dot(g, end.e[3], ref[1]);
  const double along_phi = dot(g, end.e[3], ref[3]);
  const double angle = std::atan2(along_phi, along_r);
  const double expected = 2 * M_PI * (1 - std::sqrt(1 - 3.0 / 6.0));
  EXPECT_NEAR(expected * 180 / M_PI, 105.44, 0.01);
  EXPECT_NEAR(angle, expected, 1e-6);
  EXPECT_NEAR(dot(g, end.e[1], ref[2]), -1.0, 1e-10);  // e1 = −ê_θ is not rotated

  // interpolation between samples stays on the orbit and orthonormal
  const MotionSample mid = motion->at_proper_time(33.333);
  EXPECT_NEAR(mid.x[1], 6.0, 1e-9);
  EXPECT_NEAR(mid.x[3], 33.333 * std::sqrt(2.0) / std::sqrt(216.0), 1e-9);
  EXPECT_LT(orthonormality_error(*m, mid.x, mid.e), 1e-13);
  EXPECT_NE(error_of([&] { motion->at_proper_time(80.0); }).find("outside the computed range"), std::string::npos);
}

TEST(Motion, EventAtProperTimeIsTheFullSampleWithoutItsAxes) {
  // event_at_proper_time (simultaneity searches) must give exactly at_proper_time's x and e_(0):
  // on the orbit (u = e_(0) of the interpolated, orthonormalized frame) and at the nodes.
  std::shared_ptr<const Metric> m = make_metric("Schwarzschild");
  const MotionPtr motion = make_motion(paper_orbit_params(), m, paper_solver());
  for (double tau : {-10.0, -3.21, 0.0, 0.05, 17.777, motion->samples()[400].tau, 69.99, 70.0}) {
    const MotionSample full = motion->at_proper_time(tau);
    Vec4 x, u;
    motion->event_at_proper_time(tau, x, u);
    for (int mu = 0; mu < 4; ++mu) {
      EXPECT_EQ(x[mu], full.x[mu]) << tau;
      EXPECT_EQ(u[mu], full.e[0][mu]) << tau;
    }
    Mat4 g;
    m->metric_tensor(x, g);
    EXPECT_NEAR(dot(g, u, u), -1.0, 1e-13);
    Vec4 x2, u2;
    Mat4 g2;
    static_cast<const SampledMotion&>(*motion).event_at_proper_time(tau, x2, u2, g2);
    for (int mu = 0; mu < 4; ++mu) {
      EXPECT_EQ(x2[mu], x[mu]);
      EXPECT_EQ(u2[mu], u[mu]);
      for (int nu = 0; nu < 4; ++nu) EXPECT_EQ(g2[mu][nu], g[mu][nu]);
    }
    EXPECT_NEAR(x[1], 6.0, 1e-9);  // on the circular orbit
  }
  Vec4 x, u;
  EXPECT_NE(error_of([&] { motion->event_at_proper_time(80.0, x, u); }).find("outside the computed range"),
            std::string::npos);
}

TEST(Motion, FrameCompletedFromTheEventIsTheFullSample) {
  // A simultaneity search evaluates events (event_at) and completes the frame at the τ it finds
  // from the last one (frame_at): the tetrad must be at_proper_time's bit for bit, and the node
  // interval tried first (the hint) must not change the event, right or wrong.
  std::shared_ptr<const Metric> m = make_metric("Schwarzschild");
  const MotionPtr motion = make_motion(paper_orbit_params(), m, paper_solver());
  const auto& sampled = static_cast<const SampledMotion&>(*motion);
  const size_t last = sampled.nodes().size() - 1;
  // (Also τ inside the interval before a hint, and at that interval's first node: the look-up's
  // second shortcut, SampledMotion::interval.)
  const auto& s = motion->samples();
  for (double tau : {-10.0, -3.21, 0.0, 0.05, 17.777, s[400].tau, 69.99, 70.0, 0.5 * (s[399].tau + s[400].tau),
                     s[399].tau, 0.5 * (s[0].tau + s[1].tau), 0.5 * (s[last - 1].tau + s[last].tau)}) {
    const MotionSample full = motion->at_proper_time(tau);
    for (size_t hint : {size_t{0}, size_t{1}, size_t{399}, size_t{400}, last - 1, last, last + 5}) {
      WorldlineEvent ev;
      ev.interval = hint;
      sampled.event_at(tau, ev);
      EXPECT_EQ(ev.tau, tau);
      EXPECT_LE(sampled.nodes()[ev.interval].tau, tau);
      EXPECT_LE(tau, sampled.nodes()[ev.interval + 1].tau);
      Mat4 g;
      m->metric_tensor(ev.x, g);
      const Tetrad e = sampled.frame_at(ev);
      for (int mu = 0; mu < 4; ++mu) {
        EXPECT_EQ(ev.x[mu], full.x[mu]) << tau << " hint " << hint;
        EXPECT_EQ(ev.e0[mu], full.e[0][mu]) << tau << " hint " << hint;
        for (int nu = 0; nu < 4; ++nu) {
          EXPECT_EQ(ev.g[mu][nu], g[mu][nu]) << tau << " hint " << hint;  // a node's stored g too
          EXPECT_EQ(e[mu][nu], full.e[mu][nu]) << tau << " hint " << hint;
        }
      }
    }
  }
}

TEST(Motion, FrameDerivativeIsTheParallelTransportAlongTheOrbit) {
  // A Geodesic motion parallel-transports its tetrad: de_(a)^μ/dτ = −Γ^μ_{αβ} u^α e_(a)^β
  // (MTW eq. 10.2). frame_derivative_at (the derivative of frame_at's cubic Hermite polynomial)
  // must give it at the interpolated event within the interpolation error (samples every 0.1 of
  // τ on the circular orbit at r = 6M; the tetrad turns at ~0.07 per unit τ), and the stored de
  // itself at a node.
  std::shared_ptr<const Metric> m = make_metric("Schwarzschild");
  const MotionPtr motion = make_motion(paper_orbit_params(), m, paper_solver());
  const auto& sampled = static_cast<const SampledMotion&>(*motion);
  const size_t node = 400;
  const Tetrad at_node = sampled.frame_derivative_at(sampled.nodes()[node].tau);
  for (int a = 1; a < 4; ++a)
    for (int mu = 0; mu < 4; ++mu) EXPECT_EQ(at_node[a][mu], sampled.nodes()[node].de[a][mu]);
  double largest = 0;
  for (double tau : {-9.87, -3.21, 0.05, 17.777, 33.3333, sampled.nodes()[node].tau, 69.96}) {
    const MotionSample s = motion->at_proper_time(tau);
    Christoffel G;
    m->christoffel(s.x, G);
    const Tetrad de = sampled.frame_derivative_at(tau);
    for (int a = 1; a < 4; ++a)
      for (int mu = 0; mu < 4; ++mu) {
        double transport = 0;
        for (int al = 0; al < 4; ++al)
          for (int be = 0; be < 4; ++be) transport -= G.G[mu][al][be] * s.u[al] * s.e[a][be];
        EXPECT_NEAR(de[a][mu], transport, 1e-9) << tau << " e" << a << "^" << mu;
        largest = std::max(largest, std::fabs(transport));
      }
  }
  EXPECT_GT(largest, 1e-2);  // the frame does turn: the check above is not of zeros
}

TEST(Motion, RadialFreeFallSchwarzschild) {
  std::shared_ptr<const Metric> m = make_metric("Schwarzschild");
  const ParamSet ps = testing_support::radial_fall_params(8000, 100.0, SourceLoc{"fall.scm", 86});
  SolverConfig cfg;  // fallEddFinkIn.scm: GSL_RK_Fehlberg, step_ctrl #f, step_size 0.005
  cfg.step_ctrl = false;
  cfg.step_size = 0.005;
  const MotionPtr motion = make_motion(ps, m, cfg);
  const MotionSample s = motion->at_proper_time(32.395);
  EXPECT_NEAR(s.x[1], cycloid_r(10, 32.395), 1e-7);
  EXPECT_NEAR(s.x[1], 3.01, 0.005);
  // Schwarzschild coordinates end at the horizon r = 2M, reached at τ = 33.71 (η = acos(−0.6)).
  const double tau_h = std::sqrt(125.0) * (std::acos(-0.6) + 0.8);
  EXPECT_LT(motion->tau_max(), tau_h);
  EXPECT_GT(motion->tau_max(), 33.0);
}

TEST(Motion, RadialFreeFallEddingtonFinkelsteinReachesTheCentre) {
  std::shared_ptr<const Metric> m = make_metric("EddFinkIn");
  ParamSet ps("init-motion", SourceLoc{"fallEddFinkIn.scm", 86});
  ps.add("type", "Geodesic");
  ps.add("pos", std::vector<double>{0.0, 10.0, M_PI / 2, 0.0});
  ps.add("localvel", std::vector<double>{0, 0, 0});
  ps.add("localframe", "static");
  ps.add("maxnumpoints", 8000);
  ps.add("forward", 100.0);
  SolverConfig cfg;
  cfg.step_ctrl = false;
  cfg.step_size = 0.005;
  const MotionPtr motion = make_motion(ps, m, cfg);
  EXPECT_NEAR(motion->at_proper_time(32.395).x[1], cycloid_r(10, 32.395), 1e-7);
  const double r = motion->at_proper_time(35.09).x[1];
  EXPECT_NEAR(r, cycloid_r(10, 35.09), 1e-5);
  EXPECT_NEAR(r, 0.173, 0.002);
}

TEST(Motion, RollingWheel) {
  // minkWheel.scm: boost #(0 −0.8 0), rotation #(0.4 1 0 0); radius 2.
  std::shared_ptr<const Metric> m = make_metric("Minkowski");
  ParamSet ps("init-motion", SourceLoc{"minkWheel.scm", 100});
  ps.add("type", "ConstVelocity");
  ps.add("boost", std::vector<double>{0.0, -0.8, 0.0});
  ps.add("rotation", std::vector<double>{0.4, 1.0, 0.0, 0.0});
  const MotionPtr motion = make_motion(ps, m, SolverConfig{});
  auto* cv = dynamic_cast<ConstVelocityMotion*>(motion.get());
  ASSERT_NE(cv, nullptr);
  // centre moves with v = −0.8 ŷ and crosses the origin at t = 0 (paper Fig. 8)
  const MotionSample c = motion->at_coordinate_time(10.0);
  EXPECT_NEAR(c.x[2], -8.0, 1e-12);
  EXPECT_NEAR(c.tau, 10.0 * 0.6, 1e-12);
  Mat4 g;
  m->metric_tensor(c.x, g);
  EXPECT_LT(orthonormality_error(*m, c.x, c.e), 1e-13);
  // top point: 2v/(1 + v²) = 0.97561 along −y; contact point at rest (rolling without slipping)
  const Vec4 top = cv->material_four_velocity(Vec4{{3.0, 0, -2.4, 2.0}});
  EXPECT_NEAR(top[2] / top[0], -1.6 / 1.64, 1e-12);
  EXPECT_NEAR(top[1] / top[0], 0, 1e-12);
  EXPECT_NEAR(top[3] / top[0], 0, 1e-12);
  const Vec4 bottom = cv->material_four_velocity(Vec4{{3.0, 0, -2.4, -2.0}});
  EXPECT_NEAR(bottom[2] / bottom[0], 0, 1e-12);
  EXPECT_NEAR(bottom[0], 1, 1e-12);
  // the maps are inverse to each other
  const Vec4 ev{{1.3, 0.2, -0.7, 1.1}};
  const Vec4 back = cv->from_object_frame(cv->to_object_frame(ev));
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(back[i], ev[i], 1e-13);
  // differential = finite difference of the map (central, O(h²))
  const Vec4 dv{{0.3, -0.2, 0.5, 0.1}};
  const Vec4 jd = cv->vector_to_object_frame(ev, dv);
  const double h = 1e-5;
  const Vec4 fd = (1.0 / (2 * h)) * (cv->to_object_frame(ev + h * dv) - cv->to_object_frame(ev - h * dv));
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(jd[i], fd[i], 1e-8);
}

TEST(Motion, RestFrameAndRotationComposeToTheObjectFrame) {
  // A boosts-first motion (two boosts, two rotations about different axes): Λx, then the rotations
  // at the rest time (Rodrigues' formula), is to_object_frame's sequence of boost_event and rotation
  // matrices to rounding, for events and along a segment (Λ linear: Λ(x0 + sΔx) = Λx0 + sΛΔx).
  // Independently: the rest time of the lab event (t, 0) on the first boost alone is γt (time
  // dilation), and Λ preserves the Minkowski interval.
  ConstVelocityMotion cv;
  cv.add_boost({0.3, -0.5, 0.2});
  cv.add_boost({-0.1, 0.6, 0.4});
  cv.add_rotation(0.7, {1, 2, -0.5});
  cv.add_rotation(-1.3, {0, 0.3, 1});
  ASSERT_TRUE(cv.boosts_first());
  const Vec4 x0{{2.5, -1.2, 3.4, 0.8}}, dx{{-7.0, 3.1, -5.2, 4.4}};
  for (double s : {0.0, 0.125, 0.37, 0.5, 0.91, 1.0}) {
    const Vec4 x = x0 + s * dx;
    const Vec4 expected = cv.to_object_frame(x);
    const Vec4 y = cv.to_rest_frame(x0) + s * cv.to_rest_frame(dx);
    const Vec3 X = cv.rotate_to_object(y);
    EXPECT_NEAR(y[0], expected[0], 1e-13) << s;
    EXPECT_NEAR(X.x, expected[1], 1e-13) << s;
    EXPECT_NEAR(X.y, expected[2], 1e-13) << s;
    EXPECT_NEAR(X.z, expected[3], 1e-13) << s;
    const double interval_lab = -x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
    const Vec4 r = cv.to_rest_frame(x);
    EXPECT_NEAR(-r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3], interval_lab, 1e-12) << s;
  }
  ConstVelocityMotion one;
  one.add_boost({0, -0.8, 0});
  EXPECT_NEAR(one.to_rest_frame(Vec4{{3, 0, 0, 0}})[0], 3 / 0.6, 1e-14);
  // A rotation before a boost: the object frame is not a rotated inertial frame.
  ConstVelocityMotion mixed;
  mixed.add_rotation(0.4, {1, 0, 0});
  mixed.add_boost({0, 0.5, 0});
  EXPECT_FALSE(mixed.boosts_first());
}

TEST(Motion, WorldlineFromPointsAndWrite) {
  std::shared_ptr<const Metric> m = make_metric("Minkowski");
  ParamSet ps("init-motion", SourceLoc{"wl.scm", 5});
  ps.add("type", "file");
  ValueList pts;
  for (int i = 0; i < 5; ++i) pts.push_back(std::vector<double>{1.0 * i, 0.5 * i, 0, 0});
  ps.add("points", pts);
  const MotionPtr motion = make_motion(ps, m, SolverConfig{});
  const double gamma = 1 / std::sqrt(0.75);
  EXPECT_NEAR(motion->tau_max(), 4.0 / gamma, 1e-12);  // uniform motion with v = 0.5
  const MotionSample s = motion->at_proper_time(1.0);
  EXPECT_NEAR(s.u[0], gamma, 1e-12);
  EXPECT_NEAR(s.u[1], 0.5 * gamma, 1e-12);
  std::ostringstream os;
  motion->write(os);
  std::istringstream is(os.str());
  std::string line;
  int rows = 0;
  while (std::getline(is, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    int cols = 0;
    double v;
    while (ls >> v) ++cols;
    EXPECT_EQ(cols, 25);
    ++rows;
  }
  EXPECT_EQ(rows, 5);
}

TEST(Motion, FactoryErrors) {
  std::shared_ptr<const Metric> m = make_metric("Schwarzschild");
  const SolverConfig cfg = paper_solver();
  ParamSet bad_type = paper_orbit_params();
  bad_type.set("type", "Geodesik");
  EXPECT_NE(error_of([&] { make_motion(bad_type, m, cfg); }).find("did you mean \"Geodesic\""), std::string::npos);

  ParamSet fast = paper_orbit_params();
  fast.set("localvel", std::vector<double>{0, 0, 1.2});
  const std::string f = error_of([&] { make_motion(fast, m, cfg); });
  EXPECT_EQ(f.rfind("orbit.scm:20: init-motion: localvel:", 0), 0u) << f;

  ParamSet inside = paper_orbit_params();
  inside.set("pos", std::vector<double>{0, 1.0, M_PI / 2, 0});
  EXPECT_NE(error_of([&] { make_motion(inside, m, cfg); }).find("init-motion: pos:"), std::string::npos);

  ParamSet skew = paper_orbit_params();
  skew.set("e1", std::vector<double>{0, 0.2, -1, 0});
  EXPECT_NE(error_of([&] { make_motion(skew, m, cfg); }).find("init-motion: e0..e3:"), std::string::npos);

  ParamSet empty = paper_orbit_params();
  empty.erase("forward");
  empty.erase("backward");
  EXPECT_NE(error_of([&] { make_motion(empty, m, cfg); }).find("forward"), std::string::npos);

  ParamSet rot("init-motion", SourceLoc{"w.scm", 1});
  rot.add("type", "ConstVelocity");
  rot.add("rotation", std::vector<double>{0.4, 0, 0, 0});
  EXPECT_NE(error_of([&] { make_motion(rot, make_metric("Minkowski"), cfg); }).find("axis is missing"),
            std::string::npos);
  // In a curved metric the motion acts on pseudo-Cartesian points as in GeoViS (no longer refused),
  // so the same key error is reported there.
  EXPECT_NE(error_of([&] { make_motion(rot, m, cfg); }).find("axis is missing"), std::string::npos);

  ParamSet nowl("init-motion", SourceLoc{"w.scm", 2});
  nowl.add("type", "Worldline");
  EXPECT_NE(error_of([&] { make_motion(nowl, m, cfg); }).find("points"), std::string::npos);
}

TEST(Motion, WorldlineFromFileWithProperTimes) {
  // havetau #t: columns tau x0 x1 x2 x3. Uniform motion with v = 0.6 (γ = 1.25) in Minkowski.
  const std::string file = std::string(GEOVIS_BINARY_DIR) + "/test_motion_worldline.txt";
  {
    std::ofstream out(file);
    out << "# tau t x y z\n";
    for (int i = 0; i < 6; ++i) out << 0.8 * i << " " << 1.0 * i << " " << 0.6 * i << " 0 0\n";
  }
  std::shared_ptr<const Metric> m = make_metric("Minkowski");
  ParamSet ps("init-motion", SourceLoc{"wl.scm", 9});
  ps.add("type", "Worldline");
  ps.add("filename", file);
  ps.add("havetau", true);
  const MotionPtr motion = make_motion(ps, m, SolverConfig{});
  EXPECT_NEAR(motion->tau_min(), 0.0, 1e-14);
  EXPECT_NEAR(motion->tau_max(), 4.0, 1e-12);  // proper time recomputed from the metric: 5/γ
  const MotionSample s = motion->at_coordinate_time(2.5);
  EXPECT_NEAR(s.x[1], 1.5, 1e-12);
  EXPECT_NEAR(s.tau, 2.0, 1e-12);
  EXPECT_NEAR(s.e[1][0], 0.75, 1e-12);  // boosted x axis: γβ ê_t + γ ê_x
  std::remove(file.c_str());

  ParamSet missing("init-motion", SourceLoc{"wl.scm", 10});
  missing.add("type", "Worldline");
  missing.add("filename", "/nonexistent/geovis_events.txt");
  EXPECT_NE(error_of([&] { make_motion(missing, m, SolverConfig{}); }).find("cannot open"), std::string::npos);
}

TEST(Motion, Tau0ShiftsProperTime) {
  std::shared_ptr<const Metric> m = make_metric("Schwarzschild");
  ParamSet ps = paper_orbit_params();
  ps.add("tau0", 5.0);
  ps.set("forward", 2.0);
  ps.set("backward", 1.0);
  const MotionPtr motion = make_motion(ps, m, paper_solver());
  EXPECT_NEAR(motion->tau_min(), 4.0, 1e-12);
  EXPECT_NEAR(motion->tau_max(), 7.0, 1e-12);
  EXPECT_EQ(motion->at_proper_time(5.0).x[0], 0.0);  // the start event
}

TEST(Motion, ParamSpecsAcceptTheSharedScenes) {
  // The keys of paper §3 / sphereAroundBlackhole.scm and minkWheel.scm validate cleanly; an
  // unknown key is reported with the closest valid one.
  Diagnostics diag;
  ParamSet geo = paper_orbit_params();
  geo.add("id", "motion");
  geo.add("solver", "gsolver");
  geo.validate(motion_param_specs("Geodesic"), diag);
  EXPECT_TRUE(diag.warnings().empty()) << (diag.warnings().empty() ? "" : diag.warnings()[0]);
  ParamSet wheel("init-motion", SourceLoc{"minkWheel.scm", 100});
  wheel.add("type", "ConstVelocity");
  wheel.add("boost", std::vector<double>{0.0, -0.8, 0.0});
  wheel.add("rotation", std::vector<double>{0.4, 1.0, 0.0, 0.0});
  wheel.add("id", "cm");
  wheel.validate(motion_param_specs("ConstVelocity"), diag);
  EXPECT_TRUE(diag.warnings().empty());
  geo.add("maxnumpoint", 10);
  geo.validate(motion_param_specs("Geodesic"), diag);
  ASSERT_EQ(diag.warnings().size(), 1u);
  EXPECT_NE(diag.warnings()[0].find("maxnumpoints"), std::string::npos) << diag.warnings()[0];
}
