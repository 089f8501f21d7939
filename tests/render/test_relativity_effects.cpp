// Relativistic visual effects measured from rendered images. Every expectation
// is an analytic formula evaluated here (aberration, Terrell-Penrose rotation, geodetic
// precession); the measurements come from the per-pixel data of small renders (RGBpt filter:
// hit position, texture coordinates and object id, catalogue §3; RGBpdz for hit/miss), never
// from an earlier image of ours.
//
// Texture coordinates of an ellipsoid (catalogue §4, GvsSolEllipsoid): for the unit normal n,
// u = acos(n_x / sin θ)/2π, u -> 1 − u for n_y < 0, i.e. 2π u is the longitude atan2(n_y, n_x)
// about the local z axis, in [0, 2π).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "render/local_object.h"
#include "render/pinhole_camera.h"
#include "render/renderer.h"
#include "render/shapes.h"
#include "spacetime/metric_registry.h"
#include "spacetime/motion_const_velocity.h"
#include "spacetime/motion_geodesic.h"
#include "spacetime/tetrad.h"

namespace geovis {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

struct FlatShader : Shader {
  Color shade(const Hit&, const ShadeContext&) const override { return {1, 1, 1}; }
};

/// Wraps an angle to (−180°, 180°].
double wrap_deg(double a) {
  a = std::fmod(a, 360.0);
  if (a <= -180.0) a += 360.0;
  if (a > 180.0) a -= 360.0;
  return a;
}

/// Longitude (degrees) of the texture coordinate u of an ellipsoid hit (see file comment).
double longitude_deg(const PixelData& d) { return 360.0 * d.uv[0]; }

std::shared_ptr<Ellipsoid> unit_sphere(double R, const Shader* shader) {
  auto s = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{R, R, R});
  s->shader = shader;
  s->object_id = 1;
  s->objtype = ObjType::Local;
  return s;
}

RenderResult render_quiet(const RenderJob& job) {
  RenderOptions opt;
  opt.threads = 1;
  opt.progress = false;
  return render(job, opt);
}

// ---- Terrell-Penrose rotation of a sphere moving across the line of sight ----------------------
//
// A sphere (radius R) moves with β along +y; its centre passes (x, y) = (0, 0) at t = 0. The
// observer sits at x = −D and looks along +x at t_obs = D, so the light reaching the image centre
// left the centre's event (0; 0, 0, 0): the sphere is seen exactly perpendicular to its motion.
// That photon, k = (1, −1, 0, 0) in the lab, has in the sphere's rest frame (boost along y,
// Jackson eq. 11.19) k' = (γ, −1, −γβ, 0): it leaves the sphere at the surface point with outward
// normal n = (−1/γ, −β, 0). At rest (β = 0) the point facing the observer is n = (−1, 0, 0),
// longitude 180°; moving, its longitude is 180° + arcsin β: the sphere appears rotated by
// arcsin β (Terrell, Phys. Rev. 116 (1959) 1041; Penrose 1959), 30° for β = 0.5.
RenderJob terrell_job(MotionPtr motion, const Shader* shader, double D, int N) {
  RenderJob job;
  auto m = std::shared_ptr<const Metric>(make_metric("Minkowski"));
  job.metric = m;
  job.observer.pos = Vec4{{D, -D, 0, 0}};
  job.observer.e = m->natural_tetrad(job.observer.pos, TetradKind::Default);
  job.camera = std::make_shared<PinholeCamera>(Vec3{1, 0, 0}, Vec3{0, 0, 1}, 20, 20, N, N);
  job.scene = std::make_shared<LocalObject>(unit_sphere(1.0, shader), LocalFrame(m, std::move(motion)));
  job.solver.box_ll = Vec4{{-1e300, -100, -100, -100}};
  job.solver.box_ur = Vec4{{1e300, 100, 100, 100}};
  job.filter = Filter::RGBpt;  // stores the texture coordinates
  return job;
}

/// Longitude seen at the centre pixel of an N x N (N odd) image: that pixel's ray is the optical
/// axis.
double centre_longitude(const RenderResult& r, int N) {
  const PixelData& d = r.data[size_t(N / 2) * N + N / 2];
  EXPECT_EQ(d.object_id, 1) << "the centre ray must hit the sphere";
  return longitude_deg(d);
}

TEST(RelativityEffects, SphereMovingAcrossLineOfSightAppearsRotatedByArcsinBeta) {
  const FlatShader shader;
  const double beta = 0.5, D = 10.0;
  const int N = 33;
  // Rest frame orientation: the same sphere at rest (ConstVelocity without operations).
  const double rest =
      centre_longitude(render_quiet(terrell_job(std::make_shared<ConstVelocityMotion>(), &shader, D, N)), N);
  EXPECT_NEAR(rest, 180.0, 1.5);

  ConstVelocityMotion::Op boost;
  boost.v = Vec3{0, beta, 0};
  auto moving = std::make_shared<ConstVelocityMotion>(std::vector<ConstVelocityMotion::Op>{boost});
  const double seen = centre_longitude(render_quiet(terrell_job(moving, &shader, D, N)), N);
  const double expected_rotation = std::asin(beta) / kDeg;  // 30°
  std::printf("Terrell rotation: rest longitude %.3f deg, moving %.3f deg, rotation %.3f deg (expected %.3f)\n", rest,
              seen, wrap_deg(seen - rest), expected_rotation);
  EXPECT_NEAR(wrap_deg(seen - rest), expected_rotation, 1.5);
  EXPECT_NEAR(seen, 180.0 + expected_rotation, 1.5);
}

TEST(RelativityEffects, SphereOnInertialGeodesicAppearsRotatedByArcsinBeta) {
  // The same as above with the sphere carried by a Geodesic motion (parallel-transported boosted
  // tetrad along a straight timelike geodesic) instead of the analytic ConstVelocity motion.
  const FlatShader shader;
  const double beta = 0.5, D = 10.0;
  const int N = 33;
  auto m = std::shared_ptr<const Metric>(make_metric("Minkowski"));
  SolverConfig timelike;
  timelike.type = GeodesicType::Timelike;
  timelike.step_ctrl = false;
  timelike.step_size = 0.05;
  const Vec4 origin{{0, 0, 0, 0}};
  const Tetrad e = boost_tetrad(m->natural_tetrad(origin, TetradKind::Default), Vec3{0, beta, 0});
  auto motion = std::make_shared<GeodesicMotion>(m, timelike, origin, e, 0.0, 30.0, 30.0, 2000);
  const double seen = centre_longitude(render_quiet(terrell_job(motion, &shader, D, N)), N);
  std::printf("Terrell rotation (Geodesic motion): longitude %.3f deg (expected 210)\n", seen);
  EXPECT_NEAR(seen, 180.0 + std::asin(beta) / kDeg, 1.5);
}

// ---- Geodetic precession on the last stable circular orbit (paper §4.1, Fig. 2) -----------------
//
// Schwarzschild, M = 1, circular geodesic at r = 6: local velocity β = sqrt(M/(r − 2M)) = 0.5
// relative to the static observer, angular velocity Ω = dφ/dt = sqrt(M/r³), one orbit takes
// t_2π = 2π sqrt(r³/M) = 92.3436. A parallel-transported spatial vector turns, relative to the
// co-rotating axes (ê_r, boosted ê_φ), by −2π sqrt(1 − 3M/r) per orbit, i.e. relative to fixed
// axes by the geodetic (de Sitter) angle 2π(1 − sqrt(1 − 3M/r)) = 105.44° in the sense of the
// orbit (Misner, Thorne & Wheeler, Gravitation, ex. 40.7; the paper's Fig. 2 value).
constexpr double kM = 1.0, kROrbit = 6.0;

double geodetic_angle_deg() { return 360.0 * (1.0 - std::sqrt(1.0 - 3.0 * kM / kROrbit)); }
double orbit_period_t() { return 2.0 * kPi * std::sqrt(kROrbit * kROrbit * kROrbit / kM); }

/// Static orthonormal frame of Schwarzschild (t, r, θ, φ) in the equatorial plane, written out
/// here so the test does not depend on the metric's natural tetrad: ê_t, ê_r, ê_θ, ê_φ.
Tetrad static_frame(double r) {
  const double f = 1.0 - 2.0 * kM / r;
  Tetrad e{};
  e[0] = Vec4{{1 / std::sqrt(f), 0, 0, 0}};
  e[1] = Vec4{{0, std::sqrt(f), 0, 0}};
  e[2] = Vec4{{0, 0, 1 / r, 0}};
  e[3] = Vec4{{0, 0, 0, 1 / r}};
  return e;
}

/// The orbiting frame at φ: e0 = u = γ(ê_t + β ê_φ), e1 = ê_r, e2 = γ(ê_φ + β ê_t) (the boosted
/// azimuthal axis), e3 = −ê_θ (= +z, so that e1, e2, e3 is right-handed).
Tetrad orbiting_frame(double beta) {
  const Tetrad s = static_frame(kROrbit);
  const double g = 1 / std::sqrt(1 - beta * beta);
  Tetrad e{};
  e[0] = g * (s[0] + beta * s[3]);
  e[1] = s[1];
  e[2] = g * (s[3] + beta * s[0]);
  e[3] = -1.0 * s[2];
  return e;
}

std::shared_ptr<GeodesicMotion> orbit_motion(const std::shared_ptr<const Metric>& m) {
  SolverConfig timelike;
  timelike.type = GeodesicType::Timelike;
  timelike.step_ctrl = false;
  timelike.step_size = 0.05;
  const double beta = std::sqrt(kM / (kROrbit - 2 * kM));
  return std::make_shared<GeodesicMotion>(m, timelike, Vec4{{0, kROrbit, kPi / 2, 0}}, orbiting_frame(beta), 0.0, 100.0,
                                          20.0, 5000);
}

TEST(RelativityEffects, TransportedFrameOnCircularOrbitPrecessesByGeodeticAngle) {
  auto m = std::shared_ptr<const Metric>(make_metric("Schwarzschild"));
  auto motion = orbit_motion(m);
  const MotionSample s = motion->at_coordinate_time(orbit_period_t());
  // The orbit is circular and closes after t_2π.
  EXPECT_NEAR(s.x[1], kROrbit, 1e-6);
  EXPECT_NEAR(s.x[3], 2 * kPi, 1e-6);
  // Components of the transported e_(1) (initially ê_r) along the co-rotating axes at φ = 2π.
  const Tetrad co = orbiting_frame(0.5);
  Mat4 g;
  m->metric_tensor(s.x, g);
  const double along_r = dot(g, s.e[1], co[1]);
  const double along_phi = dot(g, s.e[1], co[2]);
  EXPECT_NEAR(dot(g, s.e[1], co[0]), 0.0, 1e-6);  // stays orthogonal to u
  EXPECT_NEAR(dot(g, s.e[1], co[3]), 0.0, 1e-6);  // stays in the orbital plane
  const double angle = std::atan2(along_phi, along_r) / kDeg;
  std::printf("geodetic precession from the tetrad: %.4f deg (expected %.4f)\n", angle, geodetic_angle_deg());
  EXPECT_NEAR(wrap_deg(angle - geodetic_angle_deg()), 0.0, 0.05) << "measured " << angle;
}

TEST(RelativityEffects, OrbitingSphereImagePrecessesByGeodeticAngleAfterOneOrbit) {
  // Fig. 2 set-up (examples/fig2_orbiting_sphere.scm): static observer at r = 30 looking at the
  // hole, sphere of radius 1 on the orbit. At t_obs = t_0 and t_0 + t_2π the light reaching the
  // image centre left the sphere at the same place (φ = 0 mod 2π) with the same four-velocity, so
  // aberration and light deflection are identical; only the sphere's own axes differ, by the
  // precession about the orbit normal (its local z axis). The longitude seen at the image centre
  // therefore changes by −105.44° (mod 360°): the axes turn forward, the fixed viewing direction
  // moves backward in the sphere's longitude.
  const FlatShader shader;
  auto m = std::shared_ptr<const Metric>(make_metric("Schwarzschild"));
  auto motion = orbit_motion(m);
  const double r_obs = 30.0;
  // Light travel time from r = 6 to r_obs along a radial null ray, paper eq. (9):
  // t_0 = [r + 2M ln(r − 2M)] from 6 to 30.
  const double t0 = (r_obs + 2 * kM * std::log(r_obs - 2 * kM)) - (kROrbit + 2 * kM * std::log(kROrbit - 2 * kM));
  // 3x3 pixels of 1° each: only the centre ray is measured (the moving-object test of a curved
  // ray is the expensive part of this render).
  const int N = 3;
  double lon[2];
  for (int k = 0; k < 2; ++k) {
    RenderJob job;
    job.metric = m;
    job.observer.pos = Vec4{{t0 + k * orbit_period_t(), r_obs, kPi / 2, 0}};
    const Tetrad st = static_frame(r_obs);
    // e1 = −ê_r (towards the hole), e2 = −ê_φ, e3 = −ê_θ (up).
    job.observer.e = Tetrad{{st[0], -1.0 * st[1], -1.0 * st[3], -1.0 * st[2]}};
    job.camera = std::make_shared<PinholeCamera>(Vec3{1, 0, 0}, Vec3{0, 0, 1}, 3, 3, N, N);
    job.scene = std::make_shared<LocalObject>(unit_sphere(1.0, &shader), LocalFrame(m, motion));
    job.solver.eps_abs = 1e-8;
    job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
    job.solver.box_ur = Vec4{{1e300, 50, 1e300, 1e300}};
    job.filter = Filter::RGBpt;  // stores the texture coordinates
    lon[k] = centre_longitude(render_quiet(job), N);
  }
  std::printf("geodetic precession from the image: longitude %.4f -> %.4f deg, change %.4f (expected %.4f)\n", lon[0],
              lon[1], wrap_deg(lon[1] - lon[0]), -geodetic_angle_deg());
  EXPECT_NEAR(wrap_deg(lon[1] - lon[0] + geodetic_angle_deg()), 0.0, 0.25)
      << "longitudes " << lon[0] << " and " << lon[1];
}

// ---- Aberration seen by a moving observer (Minkowski) -------------------------------------------
//
// A sphere of radius R at rest at distance L on the x axis; the observer at the origin moves with
// β along +y (GeoViS `localvel`: the natural tetrad boosted, tetrad.h build_tetrad). In the rest
// frame of the sphere its rim lies at angles θ = 90° ± α, α = arcsin(R/L), from the +y axis. The
// moving observer sees a direction at angle θ from its velocity at θ' with
//   cos θ' = (cos θ + β) / (1 + β cos θ)
// (the inverse of the form cos θ = (cos θ' − β)/(1 − β cos θ'); Rindler §2.14, Jackson §11.4).
// Aberration maps circles on the sky to circles (Penrose 1959), so the image is the circle on
// the sky through the aberrated rim points θ'_±, centred at their midpoint (θ'_+ + θ'_−)/2 in the
// plane of velocity and sphere, with angular radius (θ'_− − θ'_+)/2.
struct ApparentCircle {
  Vec3 centre;    ///< unit direction in the observer's frame
  double radius;  ///< angular radius (radians)
};

ApparentCircle aberrated_circle(double beta, double R, double L) {
  const double alpha = std::asin(R / L);
  auto aberrate = [beta](double theta) { return std::acos((std::cos(theta) + beta) / (1 + beta * std::cos(theta))); };
  const double th_near = aberrate(kPi / 2 - alpha), th_far = aberrate(kPi / 2 + alpha);
  const double th_c = 0.5 * (th_near + th_far);
  return {Vec3{std::sin(th_c), std::cos(th_c), 0.0}, 0.5 * (th_far - th_near)};
}

TEST(RelativityEffects, MovingObserverSeesAberratedSphere) {
  const double R = 2.0, L = 10.0;
  const int N = 121;
  const double fov = 90.0;
  // Largest angular size of a pixel (the centre pixel of a pinhole image): the tolerance "to the
  // pixel" for the rim.
  const double pixel = 2 * std::atan(std::tan(fov / 2 * kDeg) / (N / 2.0)) / 2;
  auto m = std::shared_ptr<const Metric>(make_metric("Minkowski"));
  FlatShader shader;
  for (const double beta : {0.0, 0.5}) {
    SCOPED_TRACE(beta);
    RenderJob job;
    job.metric = m;
    TetradSpec spec;
    spec.pos = Vec4{{0, 0, 0, 0}};
    spec.localvel = Vec3{0, beta, 0};
    job.observer.pos = spec.pos;
    job.observer.e = build_tetrad(*m, spec);
    auto camera = std::make_shared<PinholeCamera>(Vec3{1, 0, 0}, Vec3{0, 0, 1}, fov, fov, N, N);
    job.camera = camera;
    auto sphere = std::make_shared<Ellipsoid>(Vec3{L, 0, 0}, Vec3{R, R, R});
    sphere->shader = &shader;
    sphere->object_id = 1;
    job.scene = sphere;
    job.solver.box_ll = Vec4{{-1e300, -100, -100, -100}};
    job.solver.box_ur = Vec4{{1e300, 100, 100, 100}};
    job.filter = Filter::RGBpdz;
    const RenderResult r = render_quiet(job);
    const ApparentCircle c = aberrated_circle(beta, R, L);

    // 1. Every pixel: hit exactly when its direction lies inside the predicted circle, except
    //    pixels whose centre is within one pixel of the rim.
    int hits = 0, checked = 0;
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) {
        Vec3 d;
        ASSERT_TRUE(camera->direction(i + 0.5, j + 0.5, d));
        const double ang = std::acos(std::clamp(dot(normalize(d), c.centre), -1.0, 1.0));
        const bool hit = r.data[size_t(j) * N + i].object_id == 1;
        hits += hit;
        if (std::abs(ang - c.radius) < pixel) continue;
        ++checked;
        EXPECT_EQ(hit, ang < c.radius) << "pixel " << i << "," << j << " at " << ang / kDeg << " deg from the centre";
      }
    EXPECT_GT(hits, 300);
    EXPECT_GT(checked, N * N - 400);

    // 2. Along the middle row (the plane of velocity and sphere): the rim positions give the
    //    apparent centre and angular radius to within a pixel.
    const int j = N / 2;
    double first = 0, last = 0;
    bool seen = false;
    for (int i = 0; i < N; ++i) {
      if (r.data[size_t(j) * N + i].object_id != 1) continue;
      Vec3 d;
      camera->direction(i + 0.5, j + 0.5, d);
      d = normalize(d);
      const double az = std::atan2(d.y, d.x);  // angle from the line of sight towards +y
      if (!seen) first = last = az;
      first = std::min(first, az);
      last = std::max(last, az);
      seen = true;
    }
    ASSERT_TRUE(seen);
    const double centre_az = std::atan2(c.centre.y, c.centre.x);
    std::printf(
        "aberration beta=%.1f: centre %.3f deg (expected %.3f), radius %.3f deg (expected %.3f), pixel %.3f deg\n",
        beta, 0.5 * (first + last) / kDeg, centre_az / kDeg, 0.5 * (last - first) / kDeg, c.radius / kDeg,
        pixel / kDeg);
    EXPECT_NEAR(0.5 * (first + last), centre_az, pixel) << "apparent centre (deg) " << centre_az / kDeg;
    // The outermost hit pixels lie at most one pixel inside the rim.
    EXPECT_NEAR(0.5 * (last - first), c.radius - pixel / 2, pixel) << "apparent radius (deg) " << c.radius / kDeg;
  }
}

}  // namespace
}  // namespace geovis
