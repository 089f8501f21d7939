// Camera models against their defining equations (paper eqs. 3-6, appendix A.1, catalogue §2),
// the factory (keys, defaults, errors) and setparam/--res behaviour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/camera_factory.h"
#include "render/dome_camera.h"
#include "render/fullsky_camera.h"
#include "render/panorama_camera.h"
#include "render/pinhole_camera.h"
#include "render/stereo_camera.h"

namespace geovis {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

void expect_vec(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Cameras, PinholeMatchesEquation3) {
  // dir = e1, vup = e3: ĥ = dir × vup = −e2, v̂ = ĥ × dir = e3. Eq. (3): k ∝ (1, k_r, k_u) with
  // k_r = (2 sx − 1) tan(fov_h/2) along ĥ and k_u = (1 − 2 sy) tan(fov_v/2) along v̂.
  const int W = 40, H = 30;
  const double fh = 70, fv = 50;
  PinholeCamera cam({1, 0, 0}, {0, 0, 1}, fh, fv, W, H);
  for (int j : {0, 7, 15, 29})
    for (int i : {0, 13, 20, 39}) {
      Vec3 d;
      ASSERT_TRUE(cam.direction(i + 0.5, j + 0.5, d));
      const double kr = (2 * (i + 0.5) / W - 1) * std::tan(fh * kDeg / 2);
      const double ku = (1 - 2 * (j + 0.5) / H) * std::tan(fv * kDeg / 2);
      expect_vec(d, normalize(Vec3{1, -kr, ku}));
    }
  // The image edges span exactly the field of view.
  Vec3 l, r, t, b;
  cam.direction(0, H / 2.0, l);
  cam.direction(W, H / 2.0, r);
  cam.direction(W / 2.0, 0, t);
  cam.direction(W / 2.0, H, b);
  EXPECT_NEAR(std::acos(dot(l, r)), fh * kDeg, 1e-12);
  EXPECT_NEAR(std::acos(dot(t, b)), fv * kDeg, 1e-12);
  EXPECT_GT(t.z, 0);  // row 0 is the top
}

TEST(Cameras, PinholeGeoViSDefaultOrientation) {
  // GeoViS default dir #(-1 0 0), vup #(0 0 1): ĥ = (−1,0,0) × (0,0,1) = (0,1,0): the right image
  // edge looks along +e2.
  PinholeCamera cam({-1, 0, 0}, {0, 0, 1}, 60, 48, 720, 576);
  Vec3 c, r;
  cam.direction(360, 288, c);
  cam.direction(720, 288, r);
  expect_vec(c, {-1, 0, 0});
  EXPECT_GT(r.y, 0);
  EXPECT_NEAR(r.z, 0, 1e-15);
}

TEST(Cameras, PanoramaMatchesEquation5) {
  const int W = 36, H = 12;
  const double fh = 360, fv = 60;
  PanoramaCamera cam({1, 0, 0}, {0, 0, 1}, fh, fv, W, H);
  for (int j : {0, 5, 11})
    for (int i : {0, 9, 18, 35}) {
      Vec3 d;
      ASSERT_TRUE(cam.direction(i + 0.5, j + 0.5, d));
      // GeoViS: λ = (sx − 1/2) fov_h, φ = arcsin(1/2 − sy) fov_v; d = (cos φ cos λ, cos φ sin λ,
      // sin φ) in (f̂, ĥ, v̂) with ĥ = −e2, v̂ = e3.
      const double lam = ((i + 0.5) / W - 0.5) * fh * kDeg;
      const double phi = std::asin(0.5 - (j + 0.5) / H) * fv * kDeg;
      expect_vec(d, {std::cos(phi) * std::cos(lam), -std::cos(phi) * std::sin(lam), std::sin(phi)});
    }
}

TEST(Cameras, FullSkyMatchesEquation4) {
  const int W = 64, H = 32;
  for (double angle : {0.0, 25.0}) {
    FullSkyCamera cam(angle, W, H);
    for (int j = 0; j < H; j += 5)
      for (int i = 0; i < W; i += 7) {
        Vec3 d;
        ASSERT_TRUE(cam.direction(i + 0.5, j + 0.5, d));
        const double th = (j + 0.5) / H * kPi, ph = (1 - 2 * (i + 0.5) / W) * kPi + angle * kDeg;
        expect_vec(d, {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
      }
  }
  // Top row looks up (+e3), bottom row down; the image centre looks along +e1 for angle 0.
  FullSkyCamera cam(0, W, H);
  Vec3 d;
  cam.direction(W / 2.0, H / 2.0, d);
  expect_vec(d, {1, 0, 0});
}

/// Right-handed rotation matrices (Motion4D RotateMat3D) applied to v.
Vec3 rz(double a, const Vec3& v) {
  return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y, v.z};
}
Vec3 ry(double a, const Vec3& v) {
  return {std::cos(a) * v.x + std::sin(a) * v.z, v.y, -std::sin(a) * v.x + std::cos(a) * v.z};
}

TEST(Cameras, DomeMatchesGeoViS2PICam) {
  const int N = 50;
  for (auto [h, p] : {std::pair{0.0, 0.0}, std::pair{-90.0, 90.0}, std::pair{30.0, 20.0}}) {
    DomeCamera cam(h, p, N);
    const Vec3 centre = rz(-h * kDeg, ry(-p * kDeg, Vec3{0, 0, 1}));
    int traced = 0;
    for (int j = 0; j < N; j += 3)
      for (int i = 0; i < N; i += 3) {
        const double sx = 2 * (0.5 - (i + 0.5) / N), sy = 2 * (0.5 - (j + 0.5) / N);
        const double r2 = sx * sx + sy * sy;
        Vec3 d;
        const bool ok = cam.direction(i + 0.5, j + 0.5, d);
        EXPECT_EQ(ok, r2 <= 1.0);
        if (!ok) continue;
        ++traced;
        const Vec3 s{sx, sy, std::sqrt(1 - r2)};
        expect_vec(d, rz(-h * kDeg, ry(-p * kDeg, rz(1.5 * kPi, s))));
        // Orthographic fisheye: the angle from the dome centre is arcsin r.
        EXPECT_NEAR(std::acos(std::clamp(dot(d, centre), -1.0, 1.0)), std::asin(std::sqrt(r2)), 1e-9);
      }
    EXPECT_GT(traced, 100);
  }
  // Corners are outside the disk.
  DomeCamera cam(0, 0, N);
  Vec3 d;
  EXPECT_FALSE(cam.direction(0.5, 0.5, d));
  // Square: the height follows the width.
  cam.set_resolution(80, 20);
  EXPECT_EQ(cam.width(), 80);
  EXPECT_EQ(cam.height(), 80);
}

TEST(Cameras, StereoEyesAreSeparatedAlongTheHorizontalAxis) {
  PinholeStereoCamera cam({1, 0, 0}, {0, 0, 1}, 60, 48, 64, 48, 0.2);
  EXPECT_TRUE(cam.is_stereo());
  expect_vec(cam.eye_offset(Eye::Left), {0, 0.1, 0});  // ĥ = −e2
  expect_vec(cam.eye_offset(Eye::Right), {0, -0.1, 0});
  EXPECT_NEAR(norm(cam.eye_offset(Eye::Right) - cam.eye_offset(Eye::Left)), 0.2, 1e-15);
  // Same mapping as the pinhole camera.
  PinholeCamera mono({1, 0, 0}, {0, 0, 1}, 60, 48, 64, 48);
  Vec3 a, b;
  cam.direction(3.5, 17.5, a);
  mono.direction(3.5, 17.5, b);
  expect_vec(a, b, 0);
  cam.set_param("eyesep", Value(0.0));
  EXPECT_FALSE(cam.is_stereo());
  // The displaced observer: pos + offset^i e_(i).
  Observer o;
  for (int a2 = 0; a2 < 4; ++a2)
    for (int m = 0; m < 4; ++m) o.e[a2][m] = a2 == m ? 2.0 : 0.0;
  const Observer l = offset_observer(o, Vec3{0, 0.1, 0});
  EXPECT_DOUBLE_EQ(l.pos[2], 0.2);
  EXPECT_DOUBLE_EQ(l.pos[1], 0.0);
}

TEST(Cameras, ResolutionOverrideKeepsFieldOfView) {
  PinholeCamera cam({1, 0, 0}, {0, 0, 1}, 60, 48, 720, 576);
  Vec3 before, after;
  cam.direction(720, 0, before);  // top-right corner
  cam.set_resolution(90, 72);
  cam.direction(90, 0, after);
  expect_vec(before, after);
  EXPECT_THROW(cam.set_resolution(0, 10), Error);
}

TEST(Cameras, SetParamChangesMappingAndRejectsUnknownNames) {
  PinholeCamera cam({1, 0, 0}, {0, 0, 1}, 60, 48, 10, 10);
  cam.set_param("dir", Value(std::vector<double>{0, 1, 0}));
  Vec3 d;
  cam.direction(5, 5, d);
  expect_vec(d, {0, 1, 0});
  cam.set_param("fov", Value(std::vector<double>{90, 90}));
  cam.direction(10, 5, d);
  EXPECT_NEAR(std::acos(d.y), 45 * kDeg, 1e-12);
  try {
    cam.set_param("fv", Value(1.0));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean \"fov\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(cam.set_param("dir", Value(std::vector<double>{0, 0, 0})), Error);
  cam.direction(5, 5, d);  // unchanged after the failed update
  expect_vec(d, {0, 1, 0});
  EXPECT_THROW(cam.set_param("vup", Value(std::vector<double>{0, 2, 0})), Error);  // parallel to dir
  FullSkyCamera sky(0, 8, 4);
  sky.set_param("angle", Value(90.0));
  EXPECT_DOUBLE_EQ(sky.angle_deg(), 90.0);
  EXPECT_THROW(sky.set_param("angle", Value("x")), Error);
  DomeCamera dome(0, 0, 10);
  dome.set_param("pitch", Value(90.0));
  EXPECT_TRUE(dome.direction(5, 5, d));
  expect_vec(d, ry(-90 * kDeg, Vec3{0, 0, 1}));
}

// ---- factory -------------------------------------------------------------------------------------

ParamSet camera_ps(const std::string& type) {
  ParamSet ps("init-camera", SourceLoc{"scene.scm", 12});
  ps.add("type", type);
  return ps;
}

TEST(CameraFactory, GeoViSDefaults) {
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  auto cam = make_camera(camera_ps("PinHoleCam"), ctx);
  EXPECT_STREQ(cam->type_name(), "PinHoleCam");
  EXPECT_EQ(cam->width(), 720);
  EXPECT_EQ(cam->height(), 576);
  EXPECT_EQ(cam->filter, Filter::RGB);
  auto* ph = dynamic_cast<PinholeCamera*>(cam.get());
  ASSERT_NE(ph, nullptr);
  EXPECT_EQ(ph->fov_h_deg(), 60);
  EXPECT_EQ(ph->fov_v_deg(), 48);
  expect_vec(ph->frame().fwd, {-1, 0, 0});
  auto dome = make_camera(camera_ps("2PICam"), ctx);
  EXPECT_EQ(dome->width(), 100);
  EXPECT_EQ(dome->height(), 100);
  auto st = make_camera(camera_ps("PinHoleStereoCam"), ctx);
  EXPECT_DOUBLE_EQ(dynamic_cast<PinholeStereoCamera*>(st.get())->eye_separation(), 0.1);
  EXPECT_TRUE(st->is_stereo());
  EXPECT_TRUE(diag.warnings().empty());
}

TEST(CameraFactory, EveryGeoViSCameraAndFilterIsRegistered) {
  // Registered by static objects in each camera's file; a link that dropped a file would lose it.
  EXPECT_EQ(camera_type_names(),
            (std::vector<std::string>{"2PICam", "4PICam", "PanoramaCam", "PinHoleCam", "PinHoleStereoCam"}));
  EXPECT_EQ(filter_names(),
            (std::vector<std::string>{"FilterIntersec", "FilterRGB", "FilterRGBjac", "FilterRGBpdz", "FilterRGBpt"}));
  // The defaults make_camera uses are the spec's (GeoViS Parser/parse_camera.cpp).
  const auto keys = camera_param_specs("PinHoleCam");
  const auto fov = std::find_if(keys.begin(), keys.end(), [](const ParamSpec& k) { return k.key == "fov"; });
  ASSERT_NE(fov, keys.end());
  EXPECT_EQ(std::get<std::vector<double>>(fov->def->v), (std::vector<double>{60, 48}));
}

TEST(CameraFactory, KeysAndFilters) {
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  ParamSet ps = camera_ps("4PICam");
  ps.add("res", std::vector<double>{200, 100});
  ps.add("angle", 45.0);
  ps.add("filter", "FilterRGBpdz");
  auto cam = make_camera(ps, ctx);
  EXPECT_EQ(cam->width(), 200);
  EXPECT_EQ(cam->filter, Filter::RGBpdz);
  EXPECT_DOUBLE_EQ(dynamic_cast<FullSkyCamera*>(cam.get())->angle_deg(), 45);
  EXPECT_EQ(parse_filter("FilterIntersec"), Filter::RGBIntersec);
  EXPECT_EQ(parse_filter("FilterRGBIntersec"), Filter::RGBIntersec);
  EXPECT_EQ(parse_filter("FilterRGBjac"), Filter::RGBjac);
  EXPECT_EQ(parse_filter("FilterRGBpt"), Filter::RGBpt);
  EXPECT_STREQ(filter_name(Filter::RGBpdz), "FilterRGBpdz");
}

TEST(CameraFactory, UnknownKeyWarnsWithClosestName) {
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  ParamSet ps = camera_ps("PinHoleCam");
  ps.add("fvo", std::vector<double>{30, 30});
  make_camera(ps, ctx);
  ASSERT_EQ(diag.warnings().size(), 1u);
  EXPECT_NE(diag.warnings()[0].find("fov"), std::string::npos) << diag.warnings()[0];
  diag.strict = true;
  EXPECT_THROW(make_camera(ps, ctx), Error);
}

TEST(CameraFactory, ErrorsNameFileLineKeyAndSuggest) {
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  try {
    make_camera(camera_ps("PinholeCamm"), ctx);
    FAIL();
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("scene.scm:12"), std::string::npos) << m;
    EXPECT_NE(m.find("init-camera"), std::string::npos) << m;
    EXPECT_NE(m.find("PinHoleCam"), std::string::npos) << m;
  }
  ParamSet ps = camera_ps("PinHoleCam");
  ps.add("filter", "FilterRGBpd");
  try {
    make_camera(ps, ctx);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("FilterRGBpdz"), std::string::npos) << e.what();
  }
  ParamSet bad_fov = camera_ps("PinHoleCam");
  bad_fov.add("fov", std::vector<double>{0, 30});
  try {
    make_camera(bad_fov, ctx);
    FAIL();
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("scene.scm:12: init-camera: fov:"), std::string::npos) << m;
  }
  ParamSet bad_res = camera_ps("PinHoleCam");
  bad_res.add("res", std::vector<double>{-5, 30});
  EXPECT_THROW(make_camera(bad_res, ctx), SceneError);
  ParamSet bad_dir = camera_ps("PanoramaCam");
  bad_dir.add("dir", std::vector<double>{1, 2});
  EXPECT_THROW(make_camera(bad_dir, ctx), SceneError);
  ParamSet no_type("init-camera", SourceLoc{"scene.scm", 3});
  EXPECT_THROW(make_camera(no_type, ctx), SceneError);
}

}  // namespace
}  // namespace geovis
