// The physics stored per pixel (render/data_exr.h, the GeoViS data files) against independent
// expectations: the frequency shift of a Keplerian disk (paper eq. 15) from the conserved energy
// and angular momentum of the ray, hit positions on the surface, and the Jacobi magnification of
// a point source behind a Schwarzschild lens against the weak-field lens formula.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "render/data_files.h"
#include "render/pinhole_camera.h"
#include "render/renderer.h"
#include "render/shapes.h"
#include "render/tracer.h"
#include "spacetime/metric_registry.h"

namespace geovis {
namespace {

/// Static observer at (r, θ, φ = 0) in Schwarzschild (M = 1) with a thin Keplerian disk
/// 6 ≤ r ≤ 40 in the equatorial plane.
RenderJob disk_job(double r_obs, double theta_obs, bool keplerian = true) {
  RenderJob job;
  job.metric = make_metric("Schwarzschild");
  job.observer.pos = Vec4{{0, r_obs, theta_obs, 0}};
  job.observer.e = job.metric->natural_tetrad(job.observer.pos, TetradKind::Static);
  job.camera = std::make_shared<PinholeCamera>(Vec3{-1, 0, 0}, Vec3{0, 0, 1}, 10, 10, 8, 8);
  auto ring = std::make_shared<PlaneRing>(Vec3{0, 0, 0}, Vec3{0, 0, 1}, 6.0, 40.0);
  ring->object_id = 1;
  ring->keplerian_disk = keplerian;
  job.scene = ring;
  job.solver.eps_abs = 1e-12;
  job.solver.max_steps = 20000;
  job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
  job.solver.box_ur = Vec4{{1e300, 2 * r_obs, 1e300, 1e300}};
  return job;
}

TEST(DiskRedshift, FaceOnDiskSeenFromFarAway) {
  // Rays in the observer's meridional plane (local direction in the e_r, e_θ plane) have L_z = 0,
  // so 1+z = E u^t with E = √(1 − 2M/r_obs) (ω_obs = 1) and u^t = 1/√(1 − 3M/r): from r_obs = 1e7
  // the stored 1+z at radius r is 1/√(1 − 3M/r) to 1e-6 (the observer's own factor is 1 − 1e-7).
  const double r_obs = 1e7;
  const RenderJob job = disk_job(r_obs, 0.02);
  const Tracer tracer(job);
  TraceStats st;
  int hits = 0;
  for (double s : {0.8e-6, 1.2e-6, 2e-6, 3.5e-6}) {  // impact parameters 8 ... 35 M
    const TraceResult r = tracer.trace_direction(Vec3{-1, s, 0}, st);
    ASSERT_TRUE(r.hit) << s;
    ++hits;
    const double rh = r.pos[1];
    EXPECT_NEAR(r.freqshift, 1 / std::sqrt(1 - 3 / rh), 1e-6) << "r = " << rh;
  }
  EXPECT_EQ(hits, 4);
}

TEST(DiskRedshift, ApproachingAndRecedingSidesOfAnInclinedDisk) {
  // Inclination 80° (paper Fig. 9). For a ray with conserved E = −p_t and L = p_φ (p = −k, the
  // future-directed momentum) the emitter on the circular orbit sees ω_src = u^t (E − Ω L), with
  // u^t = 1/√(1 − 3M/r), Ω = √(M/r³) (Schwarzschild circular geodesics); at the static observer
  // ω_obs = 1, so 1+z = u^t (E − Ω L) with E = √(1 − 2M/r_obs) and L = −d_φ r_obs sin θ_obs for
  // the unit local direction d (paper eq. 7: k = −e_(0) + d^i e_(i)).
  const double r_obs = 1000, th = 80 * M_PI / 180;
  const RenderJob job = disk_job(r_obs, th);
  const Tracer tracer(job);
  TraceStats st;
  double shift[2];
  for (int side = 0; side < 2; ++side) {
    const Vec3 d = normalize(Vec3{-1, 0.002, side == 0 ? 0.012 : -0.012});
    const TraceResult r = tracer.trace_direction(d, st);
    ASSERT_TRUE(r.hit) << side;
    const double rh = r.pos[1];
    const double E = std::sqrt(1 - 2 / r_obs), L = -d.z * r_obs * std::sin(th);
    const double expected = (E - std::sqrt(1 / (rh * rh * rh)) * L) / std::sqrt(1 - 3 / rh);
    EXPECT_NEAR(r.freqshift, expected, 1e-8) << "side " << side << ", r = " << rh;
    shift[side] = r.freqshift;
  }
  // +φ-moving matter on the side with d_φ > 0 recedes from the observer (redshift, ω_src > ω_obs).
  EXPECT_GT(shift[0], 1.0);
  EXPECT_LT(shift[1], shift[0]);
  // At rest in the static frame instead: 1+z = E/√(1 − 2M/r) on both sides.
  const RenderJob rest = disk_job(r_obs, th, false);
  const Tracer rest_tracer(rest);
  const TraceResult r = rest_tracer.trace_direction(normalize(Vec3{-1, 0.002, 0.012}), st);
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.freqshift, std::sqrt(1 - 2 / r_obs) / std::sqrt(1 - 2 / r.pos[1]), 1e-8);
}

TEST(DiskRedshift, KerrProgradeDiskFromTheConservedQuantitiesOfTheRay) {
  // Kerr a = 0.9: the disk matter on prograde circular orbits has Ω = √M/(r^{3/2} + a√M) and
  // u^t = (r^{3/2} + a√M)/(r^{3/4}√(r^{3/2} − 3M√r + 2a√M)) (Bardeen, Press & Teukolsky 1972,
  // eqs. 2.16, 2.12), so ω_src = −p·u = u^t (E − Ω L) with the conserved E = −p_t, L = p_φ of the
  // photon, computed here from its momentum at the observer (ω_obs = 1).
  const double a = 0.9, r_obs = 500, th = 75 * M_PI / 180;
  RenderJob job = disk_job(r_obs, th);
  auto kerr = make_metric("KerrBL");
  kerr->set_params({{"mass", 1.0}, {"angmom", a}});
  job.metric = std::move(kerr);
  job.observer.e = job.metric->natural_tetrad(job.observer.pos, TetradKind::Default);
  const Tracer tracer(job);
  TraceStats st;
  Mat4 g;
  job.metric->metric_tensor(job.observer.pos, g);
  for (double side : {1.0, -1.0}) {
    const Vec3 d = normalize(Vec3{-1, 0.004, side * 0.025});
    const TraceResult r = tracer.trace_direction(d, st);
    ASSERT_TRUE(r.hit) << side;
    const Vec4 k0 = local_null_direction(job.observer.e, d, true);  // p = −k0
    double E = 0, L = 0;
    for (int n = 0; n < 4; ++n) {
      E += g[0][n] * k0[n];  // E = −p_t = g_tν k^ν
      L -= g[3][n] * k0[n];  // L = p_φ = −g_φν k^ν
    }
    const double rh = r.pos[1], sa = a, r32 = std::pow(rh, 1.5);
    const double omega = 1 / (r32 + sa);
    const double ut = (r32 + sa) / (std::pow(rh, 0.75) * std::sqrt(r32 - 3 * std::sqrt(rh) + 2 * sa));
    EXPECT_NEAR(r.freqshift, ut * (E - omega * L), 1e-7) << "side " << side << ", r = " << rh;
  }
}

TEST(StoredHitPositions, LieOnTheSurface) {
  // The .pdz file of a Schwarzschild render of a coordinate sphere r = 5 and the disk z = 0: every
  // stored hit event is on its surface to 1e-9 of the object's size.
  auto metric = std::shared_ptr<Metric>(make_metric("Schwarzschild"));
  RenderJob job = disk_job(60, 1.2, false);
  job.metric = metric;
  job.observer.e = metric->natural_tetrad(job.observer.pos, TetradKind::Static);
  job.camera = std::make_shared<PinholeCamera>(Vec3{-1, 0, 0}, Vec3{0, 0, 1}, 20, 20, 24, 24);
  auto sphere = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{5, 5, 5});
  sphere->object_id = 2;
  auto ring = std::dynamic_pointer_cast<PlaneRing>(job.scene);
  job.scene = nullptr;
  for (int which = 0; which < 2; ++which) {
    job.scene = which == 0 ? SceneObjectPtr(sphere) : SceneObjectPtr(ring);
    job.filter = Filter::RGBpdz;
    RenderOptions ro;
    ro.progress = false;
    const RenderResult res = render(job, ro);
    const std::string bytes = encode_filter_data(job.filter, res.image.width, res.image.height, res.data);
    int w = 0, h = 0;
    const auto stored = decode_filter_data(job.filter, bytes, w, h);
    int hits = 0;
    double worst = 0;
    for (const PixelData& p : stored) {
      if (p.object_id == 0) continue;
      ++hits;
      Vec3 q;
      metric->to_pseudo_cartesian(Vec4{{p.pos[0], p.pos[1], p.pos[2], p.pos[3]}}, q);
      const double residual = which == 0 ? std::fabs(norm(q) - 5.0) / 5.0 : std::fabs(q.z) / 40.0;
      worst = std::max(worst, residual);
    }
    EXPECT_GT(hits, 20) << which;
    EXPECT_LT(worst, 1e-9) << (which == 0 ? "sphere" : "disk");
  }
}

TEST(JacobiMagnification, PointSourceBehindASchwarzschildLens) {
  // Observer at D_L = 1e4 M from the lens, source plane D_LS = 1e4 M behind it (D_S = 2e4 M):
  // Einstein angle θ_E = √(4M D_LS/(D_L D_S)). The image of a source at u = β/θ_E = 1 is at
  // θ₊ = θ_E (u + √(u² + 4))/2, magnified by μ₊ = ½[(u² + 2)/(u√(u² + 4)) + 1] (weak field,
  // Schneider, Ehlers & Falco, Gravitational Lenses (1992), eq. 2.23). The stored Jacobi μ at the
  // hit must agree within 2 %, with u measured where the ray actually lands.
  const double DL = 1e4, DLS = 1e4, DS = DL + DLS;
  RenderJob job;
  job.metric = make_metric("Schwarzschild");
  job.observer.pos = Vec4{{0, DL, M_PI / 2, 0}};
  job.observer.e = job.metric->natural_tetrad(job.observer.pos, TetradKind::Static);
  job.camera = std::make_shared<PinholeCamera>(Vec3{-1, 0, 0}, Vec3{0, 0, 1}, 10, 10, 8, 8);
  auto plane = std::make_shared<PlaneRing>(Vec3{-DLS, 0, 0}, Vec3{1, 0, 0}, 0.0, 2000.0);
  plane->object_id = 1;
  job.scene = plane;
  job.filter = Filter::RGBjac;
  job.solver.eps_abs = 1e-10;
  job.solver.max_steps = 20000;
  job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
  job.solver.box_ur = Vec4{{1e300, 3 * DS, 1e300, 1e300}};
  const Tracer tracer(job);
  TraceStats st;
  const double thE = std::sqrt(4 * DLS / (DL * DS));
  const double th = thE * (1 + std::sqrt(5.0)) / 2;  // the image of u = 1
  // e_(3) = ê_φ = +y at φ = 0: the image lies at +y, the source too.
  const TraceResult r = tracer.trace_direction(Vec3{-std::cos(th), 0, std::sin(th)}, st);
  ASSERT_TRUE(r.hit);
  Vec3 q;
  job.metric->to_pseudo_cartesian(r.pos, q);
  const double u = q.y / (DS * thE);
  EXPECT_NEAR(u, 1.0, 0.05);  // the thin-lens image position is right to a few per cent
  const double mu_weak = 0.5 * ((u * u + 2) / (u * std::sqrt(u * u + 4)) + 1);
  EXPECT_NEAR(r.jacobi[2] / mu_weak, 1.0, 0.02) << "mu = " << r.jacobi[2] << ", weak field " << mu_weak;
  // The unlensed value would be 1: the test can tell.
  EXPECT_GT(mu_weak, 1.15);
}

}  // namespace
}  // namespace geovis
