// The paper's example scenes rendered through the whole pipeline (Scheme scene -> SceneBuilder ->
// render) and measured against analytic physics: the light travel time of the
// orbiting sphere (paper eq. 9) and the shadow of a black hole seen by a freely falling observer
// (paper eq. 14). Renders are tiny (64x64, 720x1) and the expectations are computed here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "render/camera.h"
#include "render/renderer.h"
#include "scene/builder.h"
#include "scene/scheme.h"

namespace geovis {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

RenderResult render_quiet(const RenderJob& job) {
  RenderOptions opt;
  opt.threads = 1;
  opt.progress = false;
  return render(job, opt);
}

SceneBuilder build_scene(const std::string& path, std::pair<int, int> res) {
  BuildOptions opts;
  opts.resolution = res;
  opts.search_paths = {path.substr(0, path.find_last_of('/'))};
  return SceneBuilder(evaluate_scene_file(path), opts);
}

TEST(PaperScenes, OrbitingSphereFirstFrameIsCentredAtLightTravelTime) {
  // sphereAroundBlackhole.scm (paper §4.1): static observer at r = 30, sphere (radius 0.5) on the
  // circular orbit r = 6 passing φ = 0 at t = 0. Paper eq. (9): the light travel time from r = 6
  // to r = 30 along the radial null ray is t_0 = [r + r_s ln(r − r_s)] from 6 to 30
  // = 24 + 2 ln 7 = 27.8918, so at t_obs = t_0 the light reaching the image centre left the
  // sphere's centre event and the sphere's image is centred on the image centre.
  const double t0 = (30.0 + 2.0 * std::log(28.0)) - (6.0 + 2.0 * std::log(4.0));
  const int N = 64;
  SceneBuilder b = build_scene(std::string(GEOVIS_TEST_DATA_DIR) + "/geovis/scenes/sphereAroundBlackhole.scm", {N, N});
  ASSERT_EQ(b.device_count(), 301);
  std::vector<FrameJob> frames = b.build(0);
  ASSERT_EQ(frames.size(), 1u);
  RenderJob job = frames[0].job;
  EXPECT_NEAR(job.observer.pos[0], t0, 1e-4);  // the scene's t_start = 27.89182
  job.filter = Filter::RGBpdz;
  const RenderResult r = render_quiet(job);
  // Centroid and extent of the pixels that hit the sphere.
  double sx = 0, sy = 0;
  int n = 0, imin = N, imax = -1, jmin = N, jmax = -1;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      if (r.data[size_t(j) * N + i].object_id == 0) continue;
      sx += i + 0.5;
      sy += j + 0.5;
      ++n;
      imin = std::min(imin, i), imax = std::max(imax, i), jmin = std::min(jmin, j), jmax = std::max(jmax, j);
    }
  // The whole sphere is inside the frame (otherwise the centroid would prove nothing).
  ASSERT_GT(n, 100);
  EXPECT_GT(imin, 0);
  EXPECT_LT(imax, N - 1);
  EXPECT_GT(jmin, 0);
  EXPECT_LT(jmax, N - 1);
  EXPECT_NEAR(sx / n, N / 2.0, 1.0);
  EXPECT_NEAR(sy / n, N / 2.0, 1.0);
  EXPECT_NEAR(0.5 * (imin + imax + 1), N / 2.0, 1.0);
  EXPECT_NEAR(0.5 * (jmin + jmax + 1), N / 2.0, 1.0);
  // The sphere sits straight between observer and hole: the rays of the four central pixels leave
  // the observer (r = 30, phi = 0, theta = pi/2) towards the hole (camera dir = e1 = -e_r), stay
  // (nearly) radial, and hit the sphere's observer-facing half, 6 <= r <= 6.5 (orbit r = 6, radius
  // 0.5), on the line phi = 0, theta = pi/2 between observer and hole.
  for (int j = N / 2 - 1; j <= N / 2; ++j)
    for (int i = N / 2 - 1; i <= N / 2; ++i) {
      const PixelData& p = r.data[size_t(j) * N + i];
      ASSERT_NE(p.object_id, 0) << i << "," << j;
      EXPECT_GE(p.pos[1], 6.0);
      EXPECT_LE(p.pos[1], 6.5 + 1e-3);
      EXPECT_NEAR(p.pos[2], kPi / 2, 0.02);  // a pixel is 2.5/64 deg; 0.02 rad at r = 6 is 0.12
      EXPECT_NEAR(p.pos[3], 0.0, 0.02);
    }
  std::printf("sphere image: %d pixels, centroid (%.3f, %.3f), columns %d..%d, rows %d..%d, image centre %.1f\n", n,
              sx / n, sy / n, imin, imax, jmin, jmax, N / 2.0);
}

// Free fall from rest at r_i (M = 1): proper time to reach r, cycloid solution
//   τ(r) = sqrt(r_i³ / 2M) [ sqrt(x(1 − x)) + arccos(sqrt(x)) ],  x = r / r_i
// (Misner, Thorne & Wheeler eq. 31.10; Müller, GRG 40 (2008) 2185).
double fall_proper_time(double r, double ri) {
  const double x = r / ri;
  return std::sqrt(ri * ri * ri / 2.0) * (std::sqrt(x * (1 - x)) + std::acos(std::sqrt(x)));
}

double fall_radius(double tau, double ri) {
  double lo = 0, hi = ri;  // τ(r) decreases with r
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (fall_proper_time(mid, ri) > tau ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Paper eq. (14): apex angle ξ_crit of the shadow (measured from the direction towards the hole,
// i.e. the direction of the fall) for an observer falling from rest at r_i, now at r_obs:
//   cos ξ = [x² sqrt(1 − x_i) sqrt(x − x_i) ± sqrt(p (x³ − x² + p))] / (x³ − x_i x² + p),
// x = r_s/r_obs, x_i = r_s/r_i, p = 4/27. The radicand is p (x − 2/3)² (x + 1/3): it has a double
// root at the photon sphere x = 2/3 (r = 3M), so the solution that is smooth along the fall is
// cos ξ = [x² sqrt(1 − x_i) sqrt(x − x_i) + sqrt(p) (2/3 − x) sqrt(x + 1/3)] / (...):
// the '+' branch outside the photon sphere (at r = r_i it gives the static shadow
// sin²ξ = (27/4) x² (1 − x), 27.7° at r = 10, whereas '−' gives its supplement), the '−' branch
// inside it. r = 3.01 is just outside (x = 0.6645 < 2/3): '+'; r = 0.173 is inside: '−'.
double shadow_apex_deg(double r_obs, double ri) {
  const double x = 2.0 / r_obs, xi = 2.0 / ri, p = 4.0 / 27.0;
  const double a = x * x * std::sqrt(1 - xi) * std::sqrt(x - xi);
  const double b = std::sqrt(p * (x * x * x - x * x + p));
  const double sign = x < 2.0 / 3.0 ? 1.0 : -1.0;
  return std::acos((a + sign * b) / (x * x * x - xi * x * x + p)) / kDeg;
}

TEST(PaperScenes, Fig7ExampleHasEightFramesAlongTheAnalyticFall) {
  // examples/fig7_fall_into_blackhole.scm documents eight frames at proper times
  // tau = 0, 15, 25, 30, 32.395, 34, 34.8, 35.09 of the fall from rest at r_i = 10 (the paper's
  // Fig. 7 shows 0, 32.395, 35.09). Each frame's observer sits at the radius of the analytic fall
  // (MTW eq. 31.10) at that proper time.
  const double ri = 10.0;
  SceneBuilder b = build_scene(std::string(GEOVIS_SOURCE_DIR) + "/examples/fig7_fall_into_blackhole.scm", {8, 2});
  ASSERT_EQ(b.device_count(), 8);
  const double taus[8] = {0.0, 15.0, 25.0, 30.0, 32.395, 34.0, 34.8, 35.09};
  for (int k = 0; k < 8; ++k) {
    SCOPED_TRACE(k);
    const auto jobs = b.build(k);
    ASSERT_EQ(jobs.size(), 1u);
    const double r = jobs[0].job.observer.pos[1];
    EXPECT_NEAR(r, taus[k] == 0.0 ? ri : fall_radius(taus[k], ri), 1e-3);
  }
}

TEST(PaperScenes, FallingObserverSeesShadowApexAngleOfEq14) {
  // examples/fig7_fall_into_blackhole.scm (as fallEddFinkIn.scm): EddFinkIn, fall from rest at
  // r_i = 10, panorama camera 360° x 60° looking towards the hole (local x = −e_r). Rendered at
  // 720x1: the single row is the horizon plane, 0.5° per column.
  const double ri = 10.0;
  const int W = 720;
  SceneBuilder b = build_scene(std::string(GEOVIS_SOURCE_DIR) + "/examples/fig7_fall_into_blackhole.scm", {W, 1});
  // The paper's proper times 32.395 and 35.09 are among the example's frames; the frame of each
  // is the one whose observer sits at the analytic radius of the fall.
  const double taus[2] = {32.395, 35.09};
  const double r_paper[2] = {3.01, 0.173};  // paper Fig. 7 caption
  for (int f = 0; f < 2; ++f) {
    SCOPED_TRACE(taus[f]);
    const double r_expected = fall_radius(taus[f], ri);
    EXPECT_NEAR(r_expected, r_paper[f], 0.005);
    int device = -1;
    for (int k = 0; k < b.device_count() && device < 0; ++k)
      if (std::abs(b.build(k)[0].job.observer.pos[1] - r_expected) < 1e-3) device = k;
    ASSERT_GE(device, 0) << "no frame has the observer at r = " << r_expected;
    RenderJob job = b.build(device)[0].job;
    job.filter = Filter::RGBpdz;
    const RenderResult res = render_quiet(job);
    // Shadow: the rays that do not reach the celestial sphere. Its half-width on each side of the
    // direction towards the hole, from the angle of the outermost shadow pixel and of the first
    // sky pixel next to it.
    double edge[2] = {0, 0};
    int shadow_pixels = 0;
    for (int side = 0; side < 2; ++side) {
      double last_shadow = -1, first_sky = -1;
      for (int k = 0; k < W / 2; ++k) {
        const int i = side == 0 ? W / 2 + k : W / 2 - 1 - k;
        Vec3 d;
        ASSERT_TRUE(job.camera->direction(i + 0.5, 0.5, d));
        const double ang = std::acos(std::clamp(d.x / norm(d), -1.0, 1.0)) / kDeg;
        if (res.data[i].object_id == 0) {
          ++shadow_pixels;
          if (first_sky >= 0) {
            // Known solver limitation (reported): inside the horizon the rays within a few
            // degrees of the exact backward direction run out along v ~ const, where every term
            // of g(k,k) is O(L²/r²), and the relative constraint check stops them before the
            // sky. They are not part of the shadow; only that cone is exempt.
            if (ang < 170.0) ADD_FAILURE() << "shadow pixel " << i << " at " << ang << " deg outside the sky edge";
            continue;
          }
          last_shadow = ang;
        } else if (first_sky < 0) {
          first_sky = ang;
        }
      }
      ASSERT_GE(last_shadow, 0);
      ASSERT_GE(first_sky, 0);
      edge[side] = 0.5 * (last_shadow + first_sky);
    }
    const double xi = shadow_apex_deg(r_expected, ri);
    std::printf("tau %.3f: r %.4f (observer %.4f), shadow edges %.2f / %.2f deg, eq. 14: %.2f deg\n", taus[f],
                r_expected, job.observer.pos[1], edge[0], edge[1], xi);
    EXPECT_NEAR(edge[0], xi, 1.0) << "shadow pixels " << shadow_pixels;
    EXPECT_NEAR(edge[1], xi, 1.0);
  }
}

}  // namespace
}  // namespace geovis
