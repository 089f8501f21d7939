// Objects in local frames: static tetrads equal the same object in coordinates; a sphere moving
// uniformly is hit where the analytic Lorentz-contracted, light-delayed sphere is; a rotating
// frame shows the object at the light's arrival time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "object_test_helpers.h"
#include "render/compound.h"
#include "render/local_object.h"
#include "render/plugins.h"
#include "render/shapes.h"
#include "spacetime/metric_registry.h"
#include "spacetime/motion_const_velocity.h"
#include "spacetime/motion_factory.h"
#include "support/paper_orbit.h"

namespace geovis {
namespace {

using testing::make_segment;

std::shared_ptr<const Metric> minkowski() { return std::shared_ptr<const Metric>(make_metric("Minkowski")); }

/// minkWheel.scm's motion: boost v = 0.8 along −y, then rotation ω = 0.4 about +x.
std::shared_ptr<ConstVelocityMotion> minkwheel_motion() {
  ConstVelocityMotion::Op boost, rot;
  boost.v = {0, -0.8, 0};
  rot.is_boost = false;
  rot.omega = 0.4;
  rot.axis = {1, 0, 0};
  return std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{boost, rot});
}

/// Inertial motion in Minkowski: origin event x_start, 3-velocity v; tetrad = boosted
/// Cartesian axes (Jackson eq. 11.98): e_(0) = γ(1, v), e_(j) = (γ v_j, δ_jk + (γ−1) v_j v_k/v²).
class UniformMotion final : public Motion {
 public:
  UniformMotion(Vec3 v, double tau_lo, double tau_hi) : v_(v) {
    for (double tau = tau_lo; tau <= tau_hi + 1e-9; tau += 1.0) samples_.push_back(at_proper_time(tau));
  }
  MotionSample at_proper_time(double tau) const override {
    const double v2 = dot(v_, v_), g = 1.0 / std::sqrt(1.0 - v2);
    MotionSample s;
    s.tau = tau;
    s.e[0] = Vec4{{g, g * v_.x, g * v_.y, g * v_.z}};
    for (int j = 0; j < 3; ++j) {
      Vec4 e{{g * v_[j], 0, 0, 0}};
      for (int k = 0; k < 3; ++k) e[k + 1] = (j == k ? 1.0 : 0.0) + (v2 > 0 ? (g - 1) * v_[j] * v_[k] / v2 : 0.0);
      s.e[j + 1] = e;
    }
    s.u = s.e[0];
    s.x = tau * s.u;
    return s;
  }
  MotionSample at_coordinate_time(double t) const override { return at_proper_time(t * std::sqrt(1.0 - dot(v_, v_))); }
  const std::vector<MotionSample>& samples() const override { return samples_; }

 private:
  Vec3 v_;
  std::vector<MotionSample> samples_;
};

/// At rest at the origin, axes turning about z with angular velocity ω (defined for all τ, or
/// sampled every dtau on [tau_lo, tau_hi] like a Worldline motion).
class SpinningMotion final : public Motion {
 public:
  explicit SpinningMotion(double omega) : omega_(omega) { samples_.push_back(at_proper_time(0)); }
  SpinningMotion(double omega, double tau_lo, double tau_hi, double dtau) : omega_(omega), bounded_(true) {
    for (double tau = tau_lo; tau <= tau_hi + 1e-9; tau += dtau) samples_.push_back(at_proper_time(tau));
  }
  MotionSample at_proper_time(double tau) const override {
    MotionSample s;
    s.tau = tau;
    s.x = Vec4{{tau, 0, 0, 0}};
    const double c = std::cos(omega_ * tau), sn = std::sin(omega_ * tau);
    s.e[0] = Vec4{{1, 0, 0, 0}};
    s.e[1] = Vec4{{0, c, sn, 0}};
    s.e[2] = Vec4{{0, -sn, c, 0}};
    s.e[3] = Vec4{{0, 0, 0, 1}};
    s.u = s.e[0];
    return s;
  }
  MotionSample at_coordinate_time(double t) const override { return at_proper_time(t); }
  const std::vector<MotionSample>& samples() const override { return samples_; }
  bool unbounded() const override { return !bounded_; }

 private:
  double omega_;
  bool bounded_ = false;
  std::vector<MotionSample> samples_;
};

TEST(ObjLocal, StaticTetradEqualsObjectInCoordinates) {
  auto metric = minkowski();
  LocalTetrad lt;
  lt.pos = Vec4{{0, 1, 2, 3}};
  for (int a = 0; a < 4; ++a) {
    lt.e[a] = Vec4{{0, 0, 0, 0}};
    lt.e[a][a] = 1;
  }
  auto local_sphere = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0.5});
  LocalObject obj(local_sphere, LocalFrame(metric, lt));
  Ellipsoid world({1, 2, 3}, {0.5, 0.5, 0.5});
  // Rotated tetrad: local x -> world y, local y -> world −x; a local box vs the rotated world box.
  LocalTetrad rt = lt;
  rt.e[1] = Vec4{{0, 0, 1, 0}};
  rt.e[2] = Vec4{{0, -1, 0, 0}};
  LocalObject rbox(std::make_shared<Box>(Vec3{-1, -0.5, -0.2}, Vec3{1, 0.5, 0.2}), LocalFrame(metric, rt));
  Box wbox({0.5, 1, 2.8}, {1.5, 3, 3.2});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3, 6);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    // From anywhere towards the neighbourhood of the objects (most segments hit).
    const Vec3 target = Vec3{1, 2, 3} + 0.4 * Vec3{u(rng), u(rng), u(rng)};
    const Vec3 from{u(rng), u(rng), u(rng)};
    const Segment seg = make_segment(from, from + 2.0 * (target - from), 5, 0);
    Hit hl, hw;
    const bool fl = obj.intersect(seg, hl), fw = world.intersect(seg, hw);
    ASSERT_EQ(fl, fw) << k;
    if (fl) {
      ++hits;
      EXPECT_NEAR(hl.s, hw.s, 1e-12);
      EXPECT_NEAR(hl.point.x + 1, hw.point.x, 1e-12);  // local frame point
      EXPECT_NEAR(hl.normal.z, hw.normal.z, 1e-12);
      EXPECT_NEAR(hl.time, hw.time, 1e-12);
      EXPECT_NEAR(hl.emitter_u[0], 1.0, 1e-15);
    }
    Hit rl, rw;
    const bool gl = rbox.intersect(seg, rl), gw = wbox.intersect(seg, rw);
    ASSERT_EQ(gl, gw) << k;
    if (gl) {
      EXPECT_NEAR(rl.s, rw.s, 1e-12);
      // World normal = R · local normal: (x, y) -> (−y, x).
      EXPECT_NEAR(-rl.normal.y, rw.normal.x, 1e-12);
      EXPECT_NEAR(rl.normal.x, rw.normal.y, 1e-12);
    }
  }
  EXPECT_GT(hits, 50);
}

/// First root λ >= 0 of the lab-frame condition for a sphere of radius R moving with velocity
/// v x̂ (centre v t x̂): γ²(x − v t)² + y² + z² = R², on the backward ray x = p + λ n, t = t_o − λ.
bool analytic_moving_sphere(double v, double R, double t_o, const Vec3& p, const Vec3& n, double& lambda) {
  const double g2 = 1.0 / (1.0 - v * v);
  const double a = p.x - v * t_o, b = n.x + v;
  const double A = g2 * b * b + n.y * n.y + n.z * n.z;
  const double B = 2 * (g2 * a * b + p.y * n.y + p.z * n.z);
  const double C = g2 * a * a + p.y * p.y + p.z * p.z - R * R;
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return false;
  lambda = (-B - std::sqrt(disc)) / (2 * A);
  return lambda >= 0;
}

TEST(ObjLocal, MovingSphereIsContractedAndLightDelayed) {
  auto metric = minkowski();
  const double v = 0.6, R = 1.0;
  auto motion = std::make_shared<UniformMotion>(Vec3{v, 0, 0}, -40, 40);
  auto sphere = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{R, R, R});
  LocalObject obj(sphere, LocalFrame(metric, motion));
  const double L = 20, t_o = 10;
  const Vec3 p{0, -10, 0};
  int hits = 0;
  for (double ax = -0.2; ax <= 0.2; ax += 0.02) {
    for (double az = -0.12; az <= 0.12; az += 0.02) {
      const Vec3 n = normalize(Vec3{ax, 1.0, az});
      double lambda;
      const bool expect_hit = analytic_moving_sphere(v, R, t_o, p, n, lambda) && lambda < L;
      Hit hit;
      const bool found = obj.intersect(testing::light_segment(t_o, p, n, L), hit);
      ASSERT_EQ(found, expect_hit) << ax << " " << az;
      if (!found) continue;
      ++hits;
      EXPECT_NEAR(hit.s, lambda / L, 1e-11) << ax << " " << az;
      EXPECT_NEAR(hit.time, t_o - lambda, 1e-9);
      EXPECT_NEAR(norm(hit.point), R, 1e-9);  // on the sphere in its rest frame
      const double g = 1.0 / std::sqrt(1 - v * v);
      EXPECT_NEAR(hit.emitter_u[0], g, 1e-9);
      EXPECT_NEAR(hit.emitter_u[1], g * v, 1e-9);
    }
  }
  EXPECT_GT(hits, 50);
  // The worldline exists for τ in [−40, 40], i.e. t in [−50, 50]: at t ≈ −30 the sphere is at
  // x = −18 and is seen; at t ≈ −60 (x = −36) there is no object.
  Hit early, none;
  double lam;
  ASSERT_TRUE(analytic_moving_sphere(v, R, -20, Vec3{-18, -10, 0}, Vec3{0, 1, 0}, lam));
  ASSERT_TRUE(obj.intersect(testing::light_segment(-20, Vec3{-18, -10, 0}, Vec3{0, 1, 0}, 20), early));
  EXPECT_NEAR(early.s, lam / 20, 1e-11);
  EXPECT_FALSE(obj.intersect(testing::light_segment(-50, Vec3{-36, -10, 0}, Vec3{0, 1, 0}, 20), none));
}

TEST(ObjLocal, SpinningPaddleSeenAtLightArrivalTime) {
  // A thin paddle |X| <= 2, |Y| <= 0.1, |Z| <= 1 turning about z with ω = 0.2. The ray along +y
  // at x = 1 (from y = −5 at t_o = 5) hits the face Y = −0.1 where, at the ray's time
  // t = t_o − λ, −sin(ωt)·1 + cos(ωt)·(−5 + λ) = −0.1.
  auto metric = minkowski();
  const double omega = 0.2, t_o = 5;
  LocalObject paddle(std::make_shared<Box>(Vec3{-2, -0.1, -1}, Vec3{2, 0.1, 1}),
                     LocalFrame(metric, std::make_shared<SpinningMotion>(omega)));
  auto f = [&](double lam) {
    const double th = omega * (t_o - lam);
    return -std::sin(th) * 1.0 + std::cos(th) * (-5 + lam) + 0.1;
  };
  double lo = 0, hi = 10;
  for (double lam = 0; lam < 10; lam += 0.01)
    if (f(lam) < 0 && f(lam + 0.01) >= 0) {
      lo = lam, hi = lam + 0.01;
      break;
    }
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  Hit hit;
  ASSERT_TRUE(paddle.intersect(testing::light_segment(t_o, {1, -5, 0}, {0, 1, 0}, 10), hit));
  EXPECT_NEAR(hit.s, lo / 10, 1e-9);
  EXPECT_NEAR(hit.point.y, -0.1, 1e-9);
  // The paddle's material point moves with ω × r: |v| = ω |X| (slow here, γ ≈ 1).
  const double r = std::hypot(hit.point.x, hit.point.y);
  const double vmag = std::hypot(hit.emitter_u[1], hit.emitter_u[2]) / hit.emitter_u[0];
  EXPECT_NEAR(vmag, omega * r, 1e-6);
}

TEST(ObjLocal, PassesOutsideExactlyWhereTheMappedSegmentMissesTheBall) {
  // LocalFrame::passes_outside works from x_obj(τ) and e_(0) alone; the distance from the local
  // origin of the segment mapped with the whole frame (to_local) decides it up to its margin. A
  // geodesic of a sampled motion: the circular orbit at r = 6M of paper §3 in Schwarzschild.
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  const LocalFrame frame(m, make_motion(testing_support::paper_orbit_params(), m, testing_support::paper_solver()));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 500; ++k) {
    const double tau = k == 0 ? frame.motion()->samples()[150].tau : 10 + 9 * u(rng);  // k = 0: a node
    const LocalFrame::State st = frame.state(tau);
    Vec4 xa = st.x, xb = st.x;
    for (int mu = 0; mu < 4; ++mu) {
      xa[mu] += 0.5 * u(rng);
      xb[mu] += 0.5 * u(rng);
    }
    const Vec4 Xa = frame.to_local(st, xa), Xb = frame.to_local(st, xb);
    const Vec3 pa{Xa[1], Xa[2], Xa[3]}, d = Vec3{Xb[1], Xb[2], Xb[3]} - pa;
    const double s = std::clamp(-dot(pa, d) / dot(d, d), 0.0, 1.0);
    const Vec3 closest = pa + s * d;
    const double dist = std::sqrt(dot(closest, closest));
    WorldlineEvent ev;
    frame.event(tau, ev);
    EXPECT_TRUE(frame.passes_outside(xa, xb, ev, 0.999 * dist)) << k;
    EXPECT_FALSE(frame.passes_outside(xa, xb, ev, 1.001 * dist)) << k;
  }
}

TEST(ObjLocal, FrameFromTheSearchedEventIsTheFrameAtItsProperTime) {
  // intersect_piece completes the frame from the event the cull evaluated (state(ev)): it must be
  // state(τ) bit for bit, at nodes and between them.
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  const LocalFrame frame(m, make_motion(testing_support::paper_orbit_params(), m, testing_support::paper_solver()));
  for (double tau : {-3.21, 0.0, 0.05, 9.5, frame.motion()->samples()[150].tau}) {
    const LocalFrame::State direct = frame.state(tau);
    WorldlineEvent ev;
    frame.event(tau, ev);
    const LocalFrame::State from_event = frame.state(ev);
    EXPECT_EQ(from_event.tau, direct.tau);
    // to_local_spatial is to_local's spatial part bit for bit (an event 0.7 off the body).
    const Vec4 x = direct.x + 0.7 * direct.e[2] + 0.2 * direct.e[0];
    const Vec4 X = frame.to_local(direct, x);
    const Vec3 Xs = frame.to_local_spatial(direct, x);
    EXPECT_EQ(Xs.x, X[1]);
    EXPECT_EQ(Xs.y, X[2]);
    EXPECT_EQ(Xs.z, X[3]);
    for (int a = 0; a < 4; ++a) {
      EXPECT_EQ(from_event.x[a], direct.x[a]) << tau;
      for (int b = 0; b < 4; ++b) {
        EXPECT_EQ(from_event.e[a][b], direct.e[a][b]) << tau;
        EXPECT_EQ(from_event.g[a][b], direct.g[a][b]) << tau;
      }
    }
  }
}

TEST(ObjLocal, SimultaneitySlopeOfASampledMotionIsTheDerivativeOfItsFunction) {
  // simultaneous_tau's Newton slope u_norm + e0_rate·(x − x_obj) must be df/dτ of
  // f(τ) = g(e_(0)(τ), x − x_obj(τ)) as event_at evaluates it: checked against a central difference
  // of f itself (independent of the dual-number derivative of g and of the stored du), at nodes
  // and between them, on the circular orbit at r = 6M of paper §3 and a radial fall (where
  // e_(0) and g change fastest). On the orbit the slope is what makes the first Newton step from
  // a node land within the search's tolerance (one interpolated event per search instead of two).
  // The orbit as sphereAroundBlackhole.scm computes it: paper §3's, over ±500.
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  const ParamSet circular = testing_support::paper_orbit_params(500.0, 500.0, 1.5707963);
  const ParamSet fall = testing_support::radial_fall_params(1000, 30.0);
  SolverConfig fall_solver;
  fall_solver.step_ctrl = false;
  fall_solver.step_size = 0.05;
  bool orbit = true;
  for (const MotionPtr& motion :
       {make_motion(circular, m, testing_support::paper_solver()), make_motion(fall, m, fall_solver)}) {
    const LocalFrame frame(m, motion);
    const auto& samples = motion->samples();
    for (size_t k : {size_t{20}, size_t{150}, samples.size() / 2, samples.size() - 20}) {
      for (double offset : {0.0, 0.37}) {  // a node, and between two nodes
        const double tau = samples[k].tau + offset * (samples[k + 1].tau - samples[k].tau);
        WorldlineEvent ev;
        frame.event(tau, ev);
        // An event 0.8 away from the body along e_(1) + e_(3), shifted in time by 0.3.
        Vec4 x = ev.x;
        const LocalFrame::State st = frame.state(tau);
        for (int mu = 0; mu < 4; ++mu) x[mu] += 0.8 * (st.e[1][mu] + st.e[3][mu]) + 0.3 * st.e[0][mu];
        auto f = [&](double t) {
          WorldlineEvent e;
          frame.event(t, e);
          return dot(e.g, e.e0, frame.delta(x, e.x));
        };
        const Vec4 dx = frame.delta(x, ev.x);
        const double slope = ev.u_norm + (ev.e0_rate[0] * dx[0] + ev.e0_rate[1] * dx[1]) +
                             (ev.e0_rate[2] * dx[2] + ev.e0_rate[3] * dx[3]);
        const double h = 1e-4;
        const double central = (f(tau + h) - f(tau - h)) / (2 * h);
        // Exact at a node (up to the difference's O(h²) ~ 1e-9); between nodes the rate is
        // interpolated linearly (O(h_node²) of its change).
        EXPECT_NEAR(slope, central, offset == 0 ? 1e-7 : 1e-4) << k << " " << offset;
        EXPECT_NEAR(ev.u_norm, 1.0, 1e-6);  // the integrator keeps u a unit vector
        if (orbit && offset == 0) {
          // One Newton step from the node, then the step the search takes at its event: below
          // simultaneous_tau's tolerance 1e-12 (1 + |τ|).
          const double tau1 = tau - dot(ev.g, ev.e0, dx) / slope;
          WorldlineEvent ev1;
          frame.event(tau1, ev1);
          const double f1 = dot(ev1.g, ev1.e0, frame.delta(x, ev1.x));
          EXPECT_LT(std::fabs(f1 / ev1.u_norm), 1e-12 * (1 + std::fabs(tau1))) << k;
          // With the slope 1 of a unit four-velocity alone the step would stay far above it: the
          // slope's correction matters.
          const double tau1_unit = tau - dot(ev.g, ev.e0, dx);
          frame.event(tau1_unit, ev1);
          EXPECT_GT(std::fabs(dot(ev1.g, ev1.e0, frame.delta(x, ev1.x))), 1e-12 * (1 + std::fabs(tau1)))
              << k << " tau " << tau;
        }
      }
    }
    orbit = false;
  }
}

TEST(ObjLocal, BodyVelocityOfASampledMotionFromTheStoredFrameDerivative) {
  // The four-velocity of a body point at local X, d/dτ [x_obj + X^i e_(i)] normalised, takes
  // de_(i)/dτ of a sampled motion from its nodes' derivatives (SampledMotion::frame_derivative_at);
  // it must agree with the central difference of the interpolated frames (its value before) to
  // that difference's own error, and be a unit timelike vector at the hit event.
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  const LocalFrame frame(m, make_motion(testing_support::paper_orbit_params(), m, testing_support::paper_solver()));
  const Motion& motion = *frame.motion();
  for (double tau : {-3.21, 0.05, 9.5, 41.234, motion.samples()[150].tau}) {
    const LocalFrame::State st = frame.state(tau);
    const Vec3 X{0.3, -0.2, 0.35};
    const Vec4 x_hit = st.x + X.x * st.e[1] + X.y * st.e[2] + X.z * st.e[3];
    const Vec4 w = frame.body_velocity(st, X, x_hit);
    const double h = 1e-4 * (1.0 + std::fabs(tau));
    const MotionSample a = motion.at_proper_time(tau - h), b = motion.at_proper_time(tau + h);
    Vec4 expected = st.e[0];
    for (int i = 1; i < 4; ++i)
      for (int mu = 0; mu < 4; ++mu) expected[mu] += X[i - 1] * (b.e[i][mu] - a.e[i][mu]) / (2 * h);
    Mat4 g;
    m->metric_tensor(x_hit, g);
    expected = (1.0 / std::sqrt(-dot(g, expected, expected))) * expected;
    for (int mu = 0; mu < 4; ++mu) EXPECT_NEAR(w[mu], expected[mu], 1e-9) << tau << " " << mu;
    EXPECT_NEAR(dot(g, w, w), -1.0, 1e-14) << tau;
  }
}

TEST(ObjLocal, DeltaWrapsTheAzimuthAsRemainder) {
  // LocalFrame::delta skips std::remainder for |Δφ| <= π, where it returns Δφ itself; across and
  // at the boundary the results must be remainder's bit for bit.
  constexpr double kPi = 3.14159265358979323846;
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  const LocalFrame frame(m, make_motion(testing_support::paper_orbit_params(), m, testing_support::paper_solver()));
  for (double dphi : {0.0, -0.0, 1e-300, 1.0, -2.5, kPi, -kPi, std::nextafter(kPi, 4.0), std::nextafter(-kPi, -4.0),
                      std::nextafter(kPi, 0.0), 3 * kPi, -3 * kPi, 4.0, -4.0, 7.0, 1e6, -1e6}) {
    const Vec4 x{{1.0, 7.0, 1.5, 0.25 + dphi}}, y{{0.5, 6.0, 1.4, 0.25}};
    const double expected = std::remainder(x[3] - y[3], 2 * kPi);
    const Vec4 d = frame.delta(x, y);
    EXPECT_EQ(d[3], expected) << dphi;
    EXPECT_EQ(std::signbit(d[3]), std::signbit(expected)) << dphi;
    EXPECT_EQ(d[0], x[0] - y[0]);
    EXPECT_EQ(d[1], x[1] - y[1]);
  }
}

TEST(ObjLocal, OuterRadiusHoldsTheObject) {
  // A local object's bounding sphere (the world tube's radius and the cull's) is its child's
  // outer_radius: an ellipsoid's own |c| + largest semi-axis, not its box's corner; a compound's
  // largest child's.
  const Ellipsoid e(Vec3{1, 2, 2}, Vec3{0.5, 2, 1});
  EXPECT_DOUBLE_EQ(e.outer_radius(), 3 + 2);
  const Ellipsoid along(Vec3{0, 4, 0}, Vec3{0.5, 2, 1});  // centre on the long axis: |p| reaches 6
  EXPECT_DOUBLE_EQ(along.outer_radius(), 4 + 2);
  std::mt19937 rng(3);
  std::normal_distribution<double> nd;
  for (const Ellipsoid* el : {&e, &along}) {
    double farthest = 0;
    for (int k = 0; k < 20000; ++k) {
      const Vec3 n = normalize(Vec3{nd(rng), nd(rng), nd(rng)});
      farthest = std::max(farthest, norm(el->center + Vec3{el->axlen.x * n.x, el->axlen.y * n.y, el->axlen.z * n.z}));
    }
    EXPECT_LE(farthest, el->outer_radius());
    if (el == &along) {
      EXPECT_GT(farthest, 0.999 * el->outer_radius());
    }
  }
  const Ellipsoid ball(Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0.5});
  EXPECT_DOUBLE_EQ(ball.outer_radius(), 0.5);  // its box's corner: 0.866
  const CompoundObject both({std::make_shared<Ellipsoid>(e), std::make_shared<Ellipsoid>(ball)});
  EXPECT_DOUBLE_EQ(both.outer_radius(), 5);
}

TEST(ObjLocal, EveryPointOfABodyOnAnOrbitIsFoundThroughItsWorldTube) {
  // The world tube (boxes of pseudo-Cartesian radius ‖J E‖·R about the sampled worldline, the
  // shell about them, the bounding-sphere cull) must hold the whole body: a short segment across
  // the surface of a ball of radius 0.5 at a random event of the orbit at r = 6M of paper §3,
  // from |X| = 0.45 to 0.55 along a random direction of the frame at τ, is hit on the surface.
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  const LocalFrame frame(m, make_motion(testing_support::paper_orbit_params(), m, testing_support::paper_solver()));
  const LocalObject obj(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0.5}), frame);
  EXPECT_DOUBLE_EQ(obj.local_radius(), 0.5);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ut(-9, 69);
  std::normal_distribution<double> nd;
  for (int k = 0; k < 400; ++k) {
    const LocalFrame::State st = frame.state(ut(rng));
    const Vec3 n = normalize(Vec3{nd(rng), nd(rng), nd(rng)});
    Segment seg;
    seg.x0 = st.x + 0.45 * (n.x * st.e[1] + n.y * st.e[2] + n.z * st.e[3]);
    seg.x1 = st.x + 0.55 * (n.x * st.e[1] + n.y * st.e[2] + n.z * st.e[3]);
    seg.chart0 = m->to_pseudo_cartesian(seg.x0, seg.p0);
    seg.chart1 = m->to_pseudo_cartesian(seg.x1, seg.p1);
    seg.metric = m.get();
    Hit hit;
    ASSERT_TRUE(obj.intersect(seg, hit)) << k << " tau " << st.tau;
    EXPECT_NEAR(norm(hit.point), 0.5, 1e-9) << k;
    EXPECT_NEAR(hit.s, 0.5, 1e-6) << k;
  }
}

TEST(ObjLocal, SubChordStartedInTheFrameOfTheHitItRefinesHitsWhereTheBodyIs) {
  // refine_hit tests each sub-chord with the hit it refines (Segment::refines): a body on a sampled
  // motion then starts its frozen-frame iteration in the frame that hit converged in, not in the
  // frame simultaneous with the sub-chord's middle. Independent answer: events x_obj(τ) + X^i e_(i)(τ)
  // are simultaneous with x_obj(τ) in the frame at τ (g(e_(0), e_(i)) = 0), so a segment of them
  // meets the ball of radius 0.5 where the straight line X(s) does. The parent chord crosses the
  // ball through its centre at τ_s; the sub-chord lies at τ_s + Δ, Δ from 1e-7 (a deep level) to
  // 0.2 (beyond a first-level quarter of a step), 0.1 off the centre: hit where |X(s)| = 0.5,
  // with and without the start frame, and a sub-chord 0.6 off the centre misses.
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  const LocalFrame frame(m, make_motion(testing_support::paper_orbit_params(), m, testing_support::paper_solver()));
  const LocalObject obj(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0.5}), frame);
  const LocalObject other(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0.5}), frame);
  auto segment = [&](const LocalFrame::State& st, const Vec3& a, const Vec3& b) {
    Segment seg;
    for (int mu = 0; mu < 4; ++mu) {
      seg.x0[mu] = st.x[mu] + a.x * st.e[1][mu] + a.y * st.e[2][mu] + a.z * st.e[3][mu];
      seg.x1[mu] = st.x[mu] + b.x * st.e[1][mu] + b.y * st.e[2][mu] + b.z * st.e[3][mu];
    }
    seg.chart0 = m->to_pseudo_cartesian(seg.x0, seg.p0);
    seg.chart1 = m->to_pseudo_cartesian(seg.x1, seg.p1);
    seg.metric = m.get();
    return seg;
  };
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> ut(-9, 66);  // (the orbit's range −10..70, `other` 3 later)
  std::normal_distribution<double> nd;
  const double deltas[] = {1e-7, 1e-5, 1e-3, 0.05, 0.2};
  double worst_s = 0;
  for (int k = 0; k < 200; ++k) {
    const double tau_s = ut(rng), delta = deltas[k % 5];
    const Vec3 n = normalize(Vec3{nd(rng), nd(rng), nd(rng)});
    const Vec3 o = normalize(cross(n, Vec3{nd(rng), nd(rng), nd(rng)}));  // ⟂ n
    const Segment parent_seg = segment(frame.state(tau_s), 1.2 * n, Vec3{0, 0, 0});
    Hit parent;
    ASSERT_TRUE(obj.intersect(parent_seg, parent)) << k;
    ASSERT_EQ(parent.frame_object, &obj);
    EXPECT_NEAR(parent.frame_tau, tau_s, 1e-9 * (1 + std::fabs(tau_s))) << k;
    EXPECT_NEAR(parent.s, 0.7 / 1.2, 1e-9) << k;
    const LocalFrame::State st = frame.state(tau_s + delta);
    Segment sub = segment(st, 0.6 * n + 0.1 * o, 0.4 * n + 0.1 * o);
    const double s_exact = (0.6 - std::sqrt(0.25 - 0.01)) / 0.2;
    Hit scratch, fresh;
    ASSERT_TRUE(obj.intersect(sub, scratch)) << k;
    sub.refines = &parent;
    ASSERT_TRUE(obj.intersect(sub, fresh)) << k << " delta " << delta;
    // 1e-8 of the sub-chord (0.2 long): 2e-9 in position, within Tracer::kRefineTolerance (1 + |p|)
    // (|p| ~ 6); the converged iteration reaches the line's crossing to rounding (~1e-13 here).
    for (const Hit* h : {&scratch, &fresh}) {
      EXPECT_NEAR(h->s, s_exact, 1e-8) << k << " delta " << delta;
      EXPECT_NEAR(norm(h->point), 0.5, 1e-9) << k;
      EXPECT_NEAR(h->frame_tau, tau_s + delta, 1e-9 * (1 + std::fabs(tau_s))) << k;
      worst_s = std::max(worst_s, std::fabs(h->s - s_exact));
    }
    // The start frame is rebuilt where the per-thread cache holds another (here `other`'s last
    // hit): the same hit to the bit.
    Hit elsewhere;
    ASSERT_TRUE(other.intersect(segment(frame.state(tau_s + 3), -1.2 * n, Vec3{0, 0, 0}), elsewhere));
    Hit rebuilt;
    ASSERT_TRUE(obj.intersect(sub, rebuilt)) << k;
    EXPECT_EQ(rebuilt.s, fresh.s) << k;
    EXPECT_EQ(rebuilt.point.x, fresh.point.x) << k;
    EXPECT_EQ(rebuilt.frame_tau, fresh.frame_tau) << k;
    // Another object's hit is no start frame: the test from scratch, bit for bit.
    sub.refines = &elsewhere;
    Hit not_ours;
    ASSERT_TRUE(obj.intersect(sub, not_ours)) << k;
    EXPECT_EQ(not_ours.s, scratch.s) << k;
    EXPECT_EQ(not_ours.frame_tau, scratch.frame_tau) << k;
    // A sub-chord that passes outside the ball misses, started in the parent's frame too.
    Segment miss = segment(st, 0.6 * n + 0.6 * o, 0.4 * n + 0.6 * o);
    miss.refines = &parent;
    Hit none;
    EXPECT_FALSE(obj.intersect(miss, none)) << k;
  }
  EXPECT_LT(worst_s, 1e-8);
}

TEST(ObjLocal, InnerRadiusOfASampledTubeHoldsNoPointOfTheBody) {
  // The tracer captures the rays that fall below the scene's inner radius and skips the steps
  // inside it (spacetime/capture.h, render/segment_cull.h). A ball of radius 0.5 on the circular
  // orbit at r = 6M of paper §3: its tube's bounds hold the origin (distance 0), its inner radius
  // is the shell's; no point of the body's surface, at any time, may lie below it (its innermost
  // point, along −e_(3) = −r̂, at r ≈ 6 − 0.5·√(1 − 2M/r) ≈ 5.59).
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  const LocalFrame frame(m, make_motion(testing_support::paper_orbit_params(), m, testing_support::paper_solver()));
  const LocalObject obj(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0.5}), frame);
  EXPECT_EQ(obj.bounds().distance_from_origin(), 0.0);
  const double inner = obj.inner_radius();
  EXPECT_GT(inner, 4.5);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ut(-10, 70);
  std::normal_distribution<double> nd;
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2000; ++k) {
    const LocalFrame::State st = frame.state(ut(rng));
    const Vec3 n = k % 2 == 0 ? Vec3{0, 0, -1} : normalize(Vec3{nd(rng), nd(rng), nd(rng)});
    Vec3 p;
    m->to_pseudo_cartesian(st.x + 0.5 * (n.x * st.e[1] + n.y * st.e[2] + n.z * st.e[3]), p);
    EXPECT_GE(norm(p), inner) << k << " tau " << st.tau;
    nearest = std::min(nearest, norm(p));
  }
  EXPECT_NEAR(nearest, 6 - 0.5 * std::sqrt(1 - 2.0 / 6), 1e-3);
  EXPECT_LT(nearest - inner, 1.0);  // the shell's margins: ‖J E‖ and 25 % on the radius, box corners
}

TEST(ObjLocal, AcceptRadiusIsBelowTheRadiusAlongTheMotion) {
  // intersect_piece accepts a hit within accept_radius() of its worldline event without the
  // pseudo-Cartesian radius at the hit's frame: that must never exceed the radius anywhere along
  // the motion, between the samples too. The circular orbit at r = 6M (radius constant) and a
  // radial fall from r = 10M to near the horizon (‖J E‖ changing fastest at the end).
  std::shared_ptr<const Metric> m(make_metric("Schwarzschild"));
  ParamSet fall("init-motion", SourceLoc{"fall.scm", 1});
  fall.add("type", "Geodesic");
  fall.add("pos", std::vector<double>{0.0, 10.0, M_PI / 2, 0.0});
  fall.add("localvel", std::vector<double>{0, 0, 0});
  fall.add("maxnumpoints", 1000);
  fall.add("forward", 33.5);  // the horizon at τ = 33.71
  SolverConfig fall_solver;
  fall_solver.step_ctrl = false;
  fall_solver.step_size = 0.05;
  for (const MotionPtr& motion : {make_motion(testing_support::paper_orbit_params(), m, testing_support::paper_solver()),
                                  make_motion(fall, m, fall_solver)}) {
    const LocalFrame frame(m, motion);
    const LocalObject obj(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0.5}), frame);
    const double accept = obj.accept_radius();
    EXPECT_GT(accept, 0.0);
    double closest = std::numeric_limits<double>::infinity();
    const double lo = motion->tau_min(), hi = motion->tau_max();
    for (int k = 0; k <= 20000; ++k) {
      const double r = obj.pseudo_cartesian_radius(frame.state(lo + (hi - lo) * k / 20000));
      closest = std::min(closest, r / accept);
    }
    EXPECT_GT(closest, 1.0);
    EXPECT_LT(closest, 1.2);  // the fraction 0.9 of the samples' smallest radius
  }
}

TEST(ObjLocal, FactoryLocalCompObjectAndMovingPrimitive) {
  BuildContext ctx;
  ctx.metric = minkowski();
  ctx.motions["m"] = std::make_shared<UniformMotion>(Vec3{0.6, 0, 0}, -40, 40);
  LocalTetrad lt;
  lt.pos = Vec4{{0, 1, 2, 3}};
  for (int a = 0; a < 4; ++a) {
    lt.e[a] = Vec4{{0, 0, 0, 0}};
    lt.e[a][a] = 1;
  }
  ctx.tetrads["lt"] = lt;
  ParamSet s("solid-ellipsoid", {});
  s.add("objtype", 0);
  s.add("axlen", std::vector<double>{0.5, 0.5, 0.5});
  ctx.objects["sphere"] = make_object(s, ctx);
  ParamSet l("local-comp-object", {});
  l.add("obj", "sphere");
  l.add("localtetrad", "lt");
  auto lco = make_object(l, ctx);
  Hit h;
  ASSERT_TRUE(lco->intersect(make_segment({1, 2, 10}, {1, 2, 0}), h));
  EXPECT_NEAR(h.s, (10 - 3.5) / 10, 1e-12);
  EXPECT_EQ(h.object_id, 1);
  // The local-comp-object may be placed in a compound.
  ctx.objects["lco"] = lco;
  ParamSet c("comp-object", {});
  c.add("obj", "lco");
  EXPECT_NO_THROW(make_object(c, ctx));
  // A primitive with a motion = the same object in the motion's frame.
  ParamSet mv("solid-ellipsoid", {});
  mv.add("motion", "m");
  auto moving = make_object(mv, ctx);
  double lambda;
  const Vec3 n = normalize(Vec3{0.1, 1, 0});
  ASSERT_TRUE(analytic_moving_sphere(0.6, 1.0, 10, {0, -10, 0}, n, lambda));
  Hit hm;
  ASSERT_TRUE(moving->intersect(testing::light_segment(10, {0, -10, 0}, n, 20), hm));
  EXPECT_NEAR(hm.s, lambda / 20, 1e-11);
  ParamSet both("local-comp-object", {});
  both.add("obj", "sphere");
  both.add("localtetrad", "lt");
  both.add("motion", "m");
  EXPECT_THROW(make_object(both, ctx), SceneError);
}

TEST(ObjLocal, CompoundGroupsObjectsSharingAMotion) {
  // Two spheres on one motion inside a compound are tested through one shared local frame; the
  // result equals testing each moving sphere on its own.
  auto metric = minkowski();
  auto motion = std::make_shared<UniformMotion>(Vec3{0.6, 0, 0}, -40, 40);
  auto a = std::make_shared<Ellipsoid>(Vec3{-1.5, 0, 0}, Vec3{1, 1, 1});
  auto b = std::make_shared<Ellipsoid>(Vec3{1.5, 0, 0}, Vec3{1, 1, 1});
  a->object_id = 1;
  b->object_id = 2;
  auto la = std::make_shared<LocalObject>(a, LocalFrame(metric, motion));
  auto lb = std::make_shared<LocalObject>(b, LocalFrame(metric, motion));
  CompoundObject both({la, lb});
  int hits = 0;
  for (double ax = -0.4; ax <= 0.4; ax += 0.02) {
    const Segment seg = testing::light_segment(10, {0, -10, 0}, normalize(Vec3{ax, 1, 0.02}), 20);
    Hit h1, h2;
    la->intersect(seg, h1);
    lb->intersect(seg, h2);
    const Hit& ref = h1.s <= h2.s ? h1 : h2;
    Hit h;
    ASSERT_EQ(both.intersect(seg, h), ref.valid());
    if (!ref.valid()) continue;
    ++hits;
    EXPECT_NEAR(h.s, ref.s, 1e-12);
    EXPECT_EQ(h.object_id, ref.object_id);
  }
  EXPECT_GT(hits, 10);
}

TEST(ObjLocal, ConstVelocityBoostedSphereMatchesAnalytic) {
  // The GeoViS ConstVelocity motion (boost only) moves a sphere exactly like the analytic
  // Lorentz-contracted, light-delayed sphere.
  auto metric = minkowski();
  ConstVelocityMotion::Op boost;
  boost.v = {0.6, 0, 0};
  auto motion = std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{boost});
  LocalObject obj(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 1, 1}), LocalFrame(metric, motion));
  int hits = 0;
  for (double ax = -0.2; ax <= 0.2; ax += 0.04) {
    const Vec3 n = normalize(Vec3{ax, 1.0, 0.03});
    double lambda;
    const bool expect_hit = analytic_moving_sphere(0.6, 1.0, 10, {0, -10, 0}, n, lambda) && lambda < 20;
    Hit hit;
    ASSERT_EQ(obj.intersect(testing::light_segment(10, {0, -10, 0}, n, 20), hit), expect_hit) << ax;
    if (!expect_hit) continue;
    ++hits;
    EXPECT_NEAR(hit.s, lambda / 20, 1e-11);
  }
  EXPECT_GT(hits, 3);
}

TEST(ObjLocal, OneSegmentAcrossTheWholeSceneHitsAsAnalytic) {
  // A straight light ray in Minkowski is one segment (render/straight_ray.h): segments of length
  // 400, far longer than the body and its motion's time scales, must find the analytic first hit
  // of the moving sphere (v = 0.6, sampled worldline τ in [−40, 40] and ConstVelocity boost) and of
  // the rotating paddle, as the short steps of the tests above do.
  auto metric = minkowski();
  auto sphere = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 1, 1});
  LocalObject sampled(sphere, LocalFrame(metric, std::make_shared<UniformMotion>(Vec3{0.6, 0, 0}, -40, 40)));
  ConstVelocityMotion::Op boost;
  boost.v = {0.6, 0, 0};
  LocalObject boosted(
      sphere, LocalFrame(metric, std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{boost})));
  const double L = 400, t_o = 10;
  const Vec3 p{0, -10, 0};
  int hits = 0;
  for (double ax = -0.2; ax <= 0.2; ax += 0.02) {
    const Vec3 n = normalize(Vec3{ax, 1.0, 0.03});
    double lambda;
    const bool expect_hit = analytic_moving_sphere(0.6, 1.0, t_o, p, n, lambda);
    for (const LocalObject* obj : {&sampled, &boosted}) {
      Hit hit;
      ASSERT_EQ(obj->intersect(testing::light_segment(t_o, p, n, L), hit), expect_hit) << ax;
      if (!expect_hit) continue;
      ++hits;
      EXPECT_NEAR(hit.s * L, lambda, 1e-9) << ax;
      EXPECT_NEAR(norm(hit.point), 1.0, 1e-9);
    }
  }
  EXPECT_GT(hits, 10);  // 9 directions hit, both objects
  // The paddle of RotatingThinPaddleIsNotMissedOnALongStep on one segment 20 times as long: the
  // same first event (found there to 1e-6 of a 20-long step: λ = 13.58...).
  ConstVelocityMotion::Op rot;
  rot.is_boost = false;
  rot.omega = 0.4;
  rot.axis = {0, 0, 1};
  LocalObject paddle(
      std::make_shared<Box>(Vec3{-2, -0.05, -1}, Vec3{2, 0.05, 1}),
      LocalFrame(metric, std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{rot})));
  Hit h20, h400;
  ASSERT_TRUE(paddle.intersect(testing::light_segment(14, {1.8, -14, 0}, {0, 1, 0}, 20), h20));
  ASSERT_TRUE(paddle.intersect(testing::light_segment(14, {1.8, -14, 0}, {0, 1, 0}, 400), h400));
  EXPECT_NEAR(h400.s * 400, h20.s * 20, 1e-8);
}

/// Relativistic addition: lab velocity of a body moving with u' in a frame that moves with V
/// (Jackson eq. 11.31): u = [u'_∥ + V + u'_⊥ / γ_V] / (1 + V·u').
Vec3 add_velocities(const Vec3& V, const Vec3& up) {
  const double V2 = dot(V, V), gV = 1.0 / std::sqrt(1 - V2);
  const Vec3 par = (dot(up, V) / V2) * V, perp = up - par;
  return (1.0 / (1.0 + dot(V, up))) * (par + V + (1.0 / gV) * perp);
}

TEST(ObjLocal, RollingWheelMaterialVelocity) {
  // minkWheel.scm: boost v = 0.8 along −y, then rotation ω = 0.4 about +x; a wheel (cylinder of
  // radius 2 about the x axis, |x| <= 0.15) rolls on the plane z = −2 (paper §4.6): the material
  // point at local X moves with ω × X in the rest frame, so the contact point is at rest in the
  // lab and the top moves with 2v/(1 + v²).
  auto metric = minkowski();
  auto motion = minkwheel_motion();
  LocalObject wheel(std::make_shared<Cylinder>(Vec3{-0.15, 0, 0}, Vec3{0.15, 0, 0}, 2, 2), LocalFrame(metric, motion));
  int hits = 0;
  for (double y0 : {-1.5, -0.5, 0.0, 0.7}) {
    for (double z0 : {-1.9, -1.0, 0.5, 1.9}) {
      // Backward ray along −x through (y0, z0), passing the wheel's face near t = 0.
      Hit hit;
      const Segment seg = testing::light_segment(5, {5, y0, z0}, {-1, 0, 0}, 10);
      if (!wheel.intersect(seg, hit)) continue;
      ++hits;
      const Vec3 X = hit.point;      // rest-frame point
      EXPECT_NEAR(X.x, 0.15, 1e-9);  // on the face turned to the ray
      // Cross-check of the frame mapping with the motion's own lab -> object transformation.
      const Vec4 xe = seg.x0 + hit.s * (seg.x1 - seg.x0);
      const Vec4 xo = motion->to_object_frame(xe);
      EXPECT_NEAR(xo[1], X.x, 1e-9);
      EXPECT_NEAR(xo[2], X.y, 1e-9);
      EXPECT_NEAR(xo[3], X.z, 1e-9);
      // The object axes turn by ω t' (t' = rest-frame time = γ(t − V·x), Lorentz): in the
      // non-rotating rest frame the point sits at R(ω t') X and moves with ω × R(ω t') X.
      const double g = 1.0 / std::sqrt(1 - 0.64);
      const double tr = g * (xe[0] - (-0.8) * xe[2]);
      const double c = std::cos(0.4 * tr), sn = std::sin(0.4 * tr);
      const Vec3 Xr{X.x, c * X.y - sn * X.z, sn * X.y + c * X.z};
      const Vec3 u_rest = cross(Vec3{0.4, 0, 0}, Xr);
      const Vec3 u_lab = add_velocities({0, -0.8, 0}, u_rest);
      const Vec3 got{hit.emitter_u[1] / hit.emitter_u[0], hit.emitter_u[2] / hit.emitter_u[0],
                     hit.emitter_u[3] / hit.emitter_u[0]};
      EXPECT_NEAR(got.x, u_lab.x, 1e-6);
      EXPECT_NEAR(got.y, u_lab.y, 1e-6);
      EXPECT_NEAR(got.z, u_lab.z, 1e-6);
    }
  }
  EXPECT_GE(hits, 8);  // (the Lorentz-contracted wheel spans only part of the y0 grid)
  // Analytic special cases of the formula above: contact point at rest, top at 2v/(1+v²).
  EXPECT_NEAR(add_velocities({0, -0.8, 0}, cross(Vec3{0.4, 0, 0}, Vec3{0, 0, -2})).y, 0.0, 1e-15);
  EXPECT_NEAR(add_velocities({0, -0.8, 0}, cross(Vec3{0.4, 0, 0}, Vec3{0, 0, 2})).y, -1.6 / 1.64, 1e-15);
}

TEST(ObjLocal, RotatingThinPaddleIsNotMissedOnALongStep) {
  // A paddle |X| <= 2, |Y| <= 0.05, |Z| <= 1 turning about z with ω = 0.4 (ConstVelocity
  // rotation: object coordinates X = R(−ωt) x). One light-ray step of length 20 along +y at
  // x = 1.8 from y = −14 at t_o = 14 reaches y ≈ 0 at t ≈ 0, when the paddle lies along x; at the
  // step's middle (t = 4) it has turned by 1.6 rad and is nowhere near the ray, so a chord taken
  // with the frame of one time misses it (the holes near the tip of movClock's hand). Expected:
  // the first event of the ray inside the paddle, X(λ) = R(−ω(t_o − λ)) (1.8, −14 + λ, 0).
  auto metric = minkowski();
  ConstVelocityMotion::Op rot;
  rot.is_boost = false;
  rot.omega = 0.4;
  rot.axis = {0, 0, 1};
  auto motion = std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{rot});
  LocalObject paddle(std::make_shared<Box>(Vec3{-2, -0.05, -1}, Vec3{2, 0.05, 1}), LocalFrame(metric, motion));
  const double t_o = 14, omega = 0.4;
  auto inside = [&](double lam) {
    const double th = omega * (t_o - lam), x = 1.8, y = -14 + lam;
    const double X = std::cos(th) * x + std::sin(th) * y, Y = -std::sin(th) * x + std::cos(th) * y;
    return std::fabs(X) <= 2 && std::fabs(Y) <= 0.05;
  };
  double lo = 0, hi = 20;
  for (double lam = 0; lam < 20; lam += 1e-3)
    if (inside(lam + 1e-3)) {
      lo = lam, hi = lam + 1e-3;
      break;
    }
  ASSERT_LT(hi, 20) << "the ray should enter the paddle";
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (inside(mid) ? hi : lo) = mid;
  }
  Hit hit;
  ASSERT_TRUE(paddle.intersect(testing::light_segment(t_o, {1.8, -14, 0}, {0, 1, 0}, 20), hit));
  // The point of the test is the hit itself; its place is checked to 2e-5 in λ, far below the
  // paddle's thickness (measured: 8e-7 with pieces of 1/16 rad).
  EXPECT_NEAR(hit.s, hi / 20, 1e-6);
  // The same turning frame as a sampled worldline (no polyline there: one frozen frame per piece,
  // and the pieces of the tube boxes are merged only while the frame has not turned,
  // LocalObject::intersect_per_box), on segments of 20 and of 400 (a straight ray).
  LocalObject sampled(std::make_shared<Box>(Vec3{-2, -0.05, -1}, Vec3{2, 0.05, 1}),
                      LocalFrame(metric, std::make_shared<SpinningMotion>(omega, -400, 20, 0.05)));
  // One frozen frame per piece places the hit on a chord of the turning path: 8e-5 from the exact
  // event (measured), well inside the paddle's thickness 0.1.
  Hit h20s, h400s;
  ASSERT_TRUE(sampled.intersect(testing::light_segment(t_o, {1.8, -14, 0}, {0, 1, 0}, 20), h20s));
  ASSERT_TRUE(sampled.intersect(testing::light_segment(t_o, {1.8, -14, 0}, {0, 1, 0}, 400), h400s));
  EXPECT_NEAR(h20s.s * 20, hi, 2e-4);
  EXPECT_NEAR(h400s.s * 400, h20s.s * 20, 1e-9);
}

TEST(ObjLocal, RigidFrozenFrameIsTheRotatedRestFrame) {
  // LocalObject::intersect_piece maps an event x into the frozen frame at τ of a boosts-first
  // ConstVelocity motion as X = R(τ)(Λx) (ConstVelocityMotion::rotate_to_object of the rest-frame
  // event with its time replaced by τ) instead of LocalFrame::to_local with the motion's tetrad at
  // τ; and the simultaneous τ of x as its rest-frame time (Λx)^0. Both equal the general ones.
  auto metric = minkowski();
  ConstVelocityMotion::Op b1, b2, r1, r2;
  b1.v = {0, -0.8, 0};
  b2.v = {0.3, 0.1, -0.2};
  r1.is_boost = r2.is_boost = false;
  r1.omega = 0.4;
  r1.axis = {1, 0, 0};
  r2.omega = -0.7;
  r2.axis = normalize(Vec3{0.2, 1, 0.5});
  auto motion = std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{b1, b2, r1, r2});
  const LocalFrame frame(metric, motion);
  for (const Vec4& x : {Vec4{{3.0, 0.5, -2.4, 1.9}}, Vec4{{-1.2, 7.0, 0.3, -0.8}}}) {
    double tau = 0;
    ASSERT_TRUE(frame.simultaneous_tau(x, tau));
    EXPECT_NEAR(tau, motion->to_rest_frame(x)[0], 1e-11);
    for (double t_frame : {tau, tau - 0.6, tau + 2.3}) {
      const Vec4 X = frame.to_local(frame.state(t_frame), x);
      Vec4 y = motion->to_rest_frame(x);
      y[0] = t_frame;
      const Vec3 Xr = motion->rotate_to_object(y);
      EXPECT_NEAR(Xr.x, X[1], 1e-11);
      EXPECT_NEAR(Xr.y, X[2], 1e-11);
      EXPECT_NEAR(Xr.z, X[3], 1e-11);
    }
  }
}

TEST(ObjLocal, RollingPlankOnWholeRaysHitsWhereItsObjectCoordinatesEnterIt) {
  // minkWheel.scm's motion (boost v = 0.8 along −y, then rotation ω = 0.4 about x) carrying a plank
  // |X| <= 0.15, |Y| <= 2, |Z| <= 0.05 that turns about x, tested on whole straight rays of length
  // 60 (one segment each, as the renderer's Minkowski rays): the segment is narrowed in the rest
  // frame to the sphere and the slab |a·X| <= 0.15 of the rotation axis, then cut into pieces.
  // Expected, independently of the pieces: the first event of the ray whose object coordinates
  // (ConstVelocityMotion::to_object_frame, the sequence of boost and rotation) lie in the plank,
  // found by scanning the ray where it crosses the plank's slab and bisecting. Every ray that
  // enters must hit and no other. Where the frozen-frame iteration converges the hit is that
  // event; where the plank's side sweeps across the ray it may not (the frozen chord misses at the
  // refined τ) and the hit is a chord's estimate on a recheck piece (kRecheckPieces): its event
  // lies within R·θ of the plank, θ the turn of that piece (measured: 1.7e-4, 1.2e-4 in λ).
  auto metric = minkowski();
  auto motion = minkwheel_motion();
  const Vec3 lo_corner{-0.15, -2, -0.05}, hi_corner{0.15, 2, 0.05};
  LocalObject plank(std::make_shared<Box>(lo_corner, hi_corner), LocalFrame(metric, motion));
  const double estimate_bound =
      plank.local_radius() * LocalObject::kMaxTurnPerPiece / LocalObject::kRecheckPieces;
  const double t0 = 25, L = 60;
  int entering = 0, exact = 0;
  for (double y0 = -3.0; y0 <= 3.0; y0 += 0.25)
    for (double z0 : {-1.5, -0.6, -0.02, 0.3, 1.1, 1.9}) {
      for (double tilt : {0.0, 0.04}) {
        const Vec3 p0{-25, y0, z0};
        const Vec3 n = normalize(Vec3{1, tilt, -0.5 * tilt});
        const Segment seg = testing::light_segment(t0, p0, n, L);
        auto object_point = [&](double lam) {
          const Vec4 o = motion->to_object_frame(seg.x0 + (lam / L) * (seg.x1 - seg.x0));
          return Vec3{o[1], o[2], o[3]};
        };
        auto inside = [&](double lam) {
          const Vec3 X = object_point(lam);
          return std::fabs(X.x) <= 0.15 && std::fabs(X.y) <= 2 && std::fabs(X.z) <= 0.05;
        };
        // The plank's points have |x| <= 0.15 in the lab too (the boost is along y).
        const double lo = (-0.2 - p0.x) / n.x, hi = (0.2 - p0.x) / n.x;
        double entry = -1;
        for (double lam = lo; lam <= hi && entry < 0; lam += 1e-5)
          if (inside(lam)) {
            double a = lam - 1e-5, b = lam;
            for (int i = 0; i < 60; ++i) {
              const double mid = 0.5 * (a + b);
              (inside(mid) ? b : a) = mid;
            }
            entry = b;
          }
        Hit hit;
        const bool got = plank.intersect(seg, hit);
        const std::string where = "y0 = " + std::to_string(y0) + ", z0 = " + std::to_string(z0) +
                                  ", tilt = " + std::to_string(tilt);
        EXPECT_EQ(got, entry >= 0) << where;
        if (entry < 0 || !got) continue;
        ++entering;
        exact += std::fabs(hit.s * L - entry) <= 1e-6;
        const Vec3 X = object_point(hit.s * L);
        Vec3 outside{0, 0, 0};  // distance of X beyond each face pair
        for (int i = 0; i < 3; ++i) outside[i] = std::max({0.0, lo_corner[i] - X[i], X[i] - hi_corner[i]});
        EXPECT_LE(norm(outside), estimate_bound) << where;
        EXPECT_NEAR(hit.s * L, entry, 1e-3) << where;
      }
    }
  EXPECT_GE(entering, 10);
  EXPECT_GE(exact, 1);  // the face-on entries
}

TEST(ObjLocal, RotatingClockHandHasNoHolesNearItsTip) {
  // movClock.scm's hand: a cylinder of radius 0.1 from the origin to (0, 0, 1.8) turning about x
  // (ConstVelocity rotation ω = 0.5: object coordinates X = R(−ωt) x, the tip at 0.9 c), seen by
  // light rays along −x from x = 10 at t_o = 4.5 in steps of 0.01. A ray enters the hand where
  // its own path, mapped with the frame of each event's time, does: x² + Y² <= 0.01,
  // 0 <= Z <= 1.8 with (Y, Z) = R(−ωt)(y, z), t = t_o − λ, x = 10 − λ. Every ray near the tip that
  // does so must hit (with one frozen frame per step the local path jumps by the frame's turn
  // between steps and rays crossing a sliver near the tip were lost).
  auto metric = minkowski();
  const double omega = 0.5, t_o = 4.5, L = 0.01;
  ConstVelocityMotion::Op rot;
  rot.is_boost = false;
  rot.omega = omega;
  rot.axis = {1, 0, 0};
  auto motion = std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{rot});
  LocalObject hand(std::make_shared<Cylinder>(Vec3{0, 0, 0}, Vec3{0, 0, 1.8}, 0.1, 0.1), LocalFrame(metric, motion));
  int expected = 0, hit_count = 0;
  for (double y = 0.4; y <= 0.9; y += 0.025)
    for (double z = -1.8; z <= -1.2; z += 0.025) {
      auto inside = [&](double lam) {
        const double th = omega * (t_o - lam), x = 10 - lam;
        const double Y = std::cos(th) * y + std::sin(th) * z, Z = -std::sin(th) * y + std::cos(th) * z;
        return Z >= 0 && Z <= 1.8 && x * x + Y * Y <= 0.01;
      };
      bool enters = false;
      for (double lam = 9.85; lam <= 10.15 && !enters; lam += 1e-5) enters = inside(lam);
      bool got = false;
      for (int i = 0; i < 40 && !got; ++i) {
        const double l0 = 9.8 + i * L;
        Hit h;
        got = hand.intersect(testing::light_segment(t_o - l0, {10 - l0, y, z}, {-1, 0, 0}, L), h);
      }
      if (!enters) continue;
      ++expected;
      EXPECT_TRUE(got) << "y = " << y << ", z = " << z;
      hit_count += got;
    }
  EXPECT_GT(expected, 20);
  EXPECT_EQ(hit_count, expected);
}

TEST(ObjLocal, ConstVelocityInCurvedMetricActsOnPseudoCartesianPoints) {
  // GeoViS applies a ConstVelocity motion to the pseudo-Cartesian points of the rays in any
  // metric (mtContactRings.scm, Morris-Thorne): a boosted sphere in Schwarzschild is hit where the
  // Minkowski sphere with the same motion is hit by the same pseudo-Cartesian segment.
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  ctx.metric = std::shared_ptr<const Metric>(make_metric("Schwarzschild"));
  ConstVelocityMotion::Op boost;
  boost.v = {0.6, 0, 0};
  ctx.motions["cv"] = std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{boost});
  ParamSet ps("solid-ellipsoid", {});
  ps.add("motion", "cv");
  const SceneObjectPtr obj = make_object(ps, ctx);
  ASSERT_NE(std::dynamic_pointer_cast<PseudoCartesianMotionObject>(obj), nullptr);
  ASSERT_EQ(diag.warnings().size(), 1u);
  EXPECT_NE(diag.warnings()[0].find("pseudo-Cartesian"), std::string::npos) << diag.warnings()[0];
  const Vec3 n = normalize(Vec3{0.1, 1, 0});
  double lambda;
  ASSERT_TRUE(analytic_moving_sphere(0.6, 1.0, 10, {0, -10, 0}, n, lambda));
  Segment seg = testing::light_segment(10, {0, -10, 0}, n, 20);
  // The events in Schwarzschild coordinates (t, r, θ, φ) of the same pseudo-Cartesian points.
  for (Vec4* x : {&seg.x0, &seg.x1}) {
    const Vec3 p{(*x)[1], (*x)[2], (*x)[3]};
    *x = Vec4{{(*x)[0], norm(p), std::acos(p.z / norm(p)), std::atan2(p.y, p.x)}};
  }
  Hit hit;
  ASSERT_TRUE(obj->intersect(seg, hit));
  EXPECT_NEAR(hit.s, lambda / 20, 1e-11);
}

}  // namespace
}  // namespace geovis
