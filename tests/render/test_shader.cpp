// SurfShader formula (catalogue §6, paper §2.4) and the light factories.
#include <gtest/gtest.h>

#include <cmath>

#include "render/plugins.h"
#include "render/surface_shader.h"
#include "render/textures.h"

namespace geovis {
namespace {

void expect_color(const Color& a, const Color& b, double tol = 1e-12) {
  EXPECT_NEAR(a.r, b.r, tol);
  EXPECT_NEAR(a.g, b.g, tol);
  EXPECT_NEAR(a.b, b.b, tol);
}

struct ObjShader : ::testing::Test {
  SurfaceShader sh;
  LightManager lm;
  Hit hit;
  ObjShader() {
    sh.objcolor = std::make_shared<UniTexture>(Color{0.5, 0.4, 0.2});
    sh.ambient = 0.2;
    sh.diffuse = 0.8;
    set_geometry({0, 0, 1}, normalize(Vec3{1, 0, -1}));  // 45° incidence
    hit.point = {0, 0, 0};
  }
  /// The same normal and direction in the parent frame and in the primitive's local frame.
  void set_geometry(const Vec3& n, const Vec3& d) {
    hit.normal = hit.shade_normal = n;
    hit.ray_dir = hit.shade_dir = d;
  }
};

TEST_F(ObjShader, AmbientPlusDiffuseFromTheObserver) {
  ShadeContext ctx;
  ctx.lights = &lm;
  // C = P (ka + kd cos 45°) with white ambient/diffuse light.
  const double f = 0.2 + 0.8 / std::sqrt(2.0);
  expect_color(sh.shade(hit, ctx), {0.5 * f, 0.4 * f, 0.2 * f});
  // The normal is turned towards the viewer first: the back side looks the same.
  set_geometry({0, 0, -1}, hit.ray_dir);
  expect_color(sh.shade(hit, ctx), {0.5 * f, 0.4 * f, 0.2 * f});
  // Grazing view: only ambient.
  set_geometry(hit.normal, {1, 0, 0});
  expect_color(sh.shade(hit, ctx), {0.1, 0.08, 0.04});
  // Light colours scale their terms.
  lm.ambient = {0.5, 0.5, 0.5};
  lm.diffuse = {0, 0, 0};
  expect_color(sh.shade(hit, ctx), {0.05, 0.04, 0.02});
}

TEST_F(ObjShader, PointLightsWithVisibilityAndAttenuation) {
  PointLight l;
  l.pos = Vec4{{0, 0, 0, 4}};
  l.color = {1, 1, 1};
  l.atten = {1, 0, 0.5};
  lm.lights.push_back(l);
  lm.shadows = true;
  bool visible = true;
  auto vis = [&](const Vec3&, const PointLight&) { return visible; };
  ShadeContext ctx;
  ctx.lights = &lm;
  ctx.light_visible = vis;
  const double f = 0.2 + 0.8 / std::sqrt(2.0);
  const double att = 1.0 / (1.0 + 0.5 * 16.0);  // 1 / (c + l d + q d²), d = 4
  expect_color(sh.shade(hit, ctx), {0.5 * (f + att), 0.4 * (f + att), 0.2 * (f + att)});
  visible = false;  // in shadow
  expect_color(sh.shade(hit, ctx), {0.5 * f, 0.4 * f, 0.2 * f});
  visible = true;
  lm.lights[0].pos = Vec4{{0, 0, 0, -4}};  // below the lit side
  expect_color(sh.shade(hit, ctx), {0.5 * f, 0.4 * f, 0.2 * f});
  EXPECT_EQ(light_attenuation({0, 0, 0}, 10.0), 1.0);
  // Clamped to [0, 1].
  sh.ambient = 5;
  expect_color(sh.shade(hit, ctx), {1, 1, 1});
}

TEST_F(ObjShader, NormalMapReplacesTheDiffuseNormal) {
  // n = −normalize(rgb) (GeoViS: no 2c − 1 remap): rgb (0, 0, 1) gives n = −z; seen along
  // d = (1, 0, −1)/√2, n·(−d) = −1/√2 < 0, so no diffuse light.
  sh.normalmap = std::make_shared<UniTexture>(Color{0, 0, 1});
  ShadeContext ctx;
  ctx.lights = &lm;
  expect_color(sh.shade(hit, ctx), {0.1, 0.08, 0.04});
  sh.normalmap = std::make_shared<UniTexture>(Color{1, 0, 0});  // n = −x: cos = 1/√2
  const double f = 0.2 + 0.8 / std::sqrt(2.0);
  expect_color(sh.shade(hit, ctx), {0.5 * f, 0.4 * f, 0.2 * f});
}

TEST(ObjShaderFactory, ShaderLightAndLightManager) {
  BuildContext ctx;
  ctx.textures["tex"] = std::make_shared<UniTexture>(Color{1, 1, 1});
  ParamSet s("init-shader", {});
  s.add("type", "SurfShader");
  s.add("objcolor", "tex");
  s.add("ambient", 0.3);
  auto sh = std::dynamic_pointer_cast<SurfaceShader>(make_shader(s, ctx));
  ASSERT_TRUE(sh);
  EXPECT_EQ(sh->ambient, 0.3);
  EXPECT_EQ(sh->diffuse, 0.0);  // GeoViS default
  ParamSet l("init-light", {});
  l.add("type", "PointLight");
  l.add("pos", std::vector<double>{0, 20, 0, 25});
  l.add("atten", std::vector<double>{0, 0, 0});
  const PointLight pl = make_point_light(l, ctx);
  EXPECT_EQ(pl.pos[1], 20);
  EXPECT_EQ(pl.pos[3], 25);
  ctx.lights["pl1"] = pl;
  ParamSet m("init-light-mgr", {});
  m.add("ambient", std::vector<double>{1, 1, 1});
  m.add("light", "pl1");
  m.add("shadows", true);
  const LightManager lm = make_light_manager(m, ctx);
  ASSERT_EQ(lm.lights.size(), 1u);
  EXPECT_TRUE(lm.shadows);
  ParamSet bad("init-light", SourceLoc{"x.scm", 9});
  bad.add("type", "PointLigt");
  bad.add("pos", std::vector<double>{0, 0, 0, 0});
  try {
    make_point_light(bad, ctx);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("PointLight"), std::string::npos) << e.what();
  }
  ParamSet badref("init-light-mgr", {});
  badref.add("light", "pl2");
  EXPECT_THROW(make_light_manager(badref, ctx), SceneError);
}

}  // namespace
}  // namespace geovis
