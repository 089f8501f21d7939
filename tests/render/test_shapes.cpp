// Segment–primitive intersections against analytic hit points, normals and fractions s.
#include <gtest/gtest.h>

#include <cmath>

#include "object_test_helpers.h"
#include "render/plugins.h"
#include "render/shapes.h"
#include "render/surface_shader.h"
#include "render/textures.h"

namespace geovis {
namespace {

using testing::make_segment;

constexpr double kTol = 1e-12;

void expect_vec(const Vec3& a, const Vec3& b, double tol = kTol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

Transform translate(double x, double y, double z) {
  Transform t = Transform::identity(3);
  t(0, 3) = x, t(1, 3) = y, t(2, 3) = z;
  return t;
}
Transform scale(double x, double y, double z) {
  Transform t = Transform::identity(3);
  t(0, 0) = x, t(1, 1) = y, t(2, 2) = z;
  return t;
}
Transform rotate_z(double deg) {
  const double a = deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
  Transform t = Transform::identity(3);
  t(0, 0) = c, t(0, 1) = -s, t(1, 0) = s, t(1, 1) = c;
  return t;
}

TEST(ShapesEllipsoid, SphereEntryHitPointNormalAndTime) {
  Ellipsoid e({1, 0, 0}, {2, 2, 2});
  e.object_id = 7;
  Hit hit;
  // x from −5 to 5 over coordinate time 10 -> 0: entry at x = −1, s = 0.4, t = 6.
  ASSERT_TRUE(e.intersect(make_segment({-5, 0, 0}, {5, 0, 0}, 10, 0), hit));
  EXPECT_NEAR(hit.s, 0.4, kTol);
  expect_vec(hit.point, {-1, 0, 0});
  expect_vec(hit.normal, {-1, 0, 0});
  expect_vec(hit.ray_dir, {1, 0, 0});
  EXPECT_NEAR(hit.time, 6.0, kTol);
  EXPECT_EQ(hit.object_id, 7);
}

TEST(ShapesEllipsoid, TriaxialNormalIsGradient) {
  // Semi-axes (1, 2, 3); the line y = 1 along +x meets x² + y²/4 = 1 at x = −√3/2.
  Ellipsoid e({0, 0, 0}, {1, 2, 3});
  Hit hit;
  ASSERT_TRUE(e.intersect(make_segment({-5, 1, 0}, {5, 1, 0}), hit));
  const double x = -std::sqrt(3.0) / 2;
  EXPECT_NEAR(hit.s, (x + 5) / 10, kTol);
  expect_vec(hit.normal, normalize(Vec3{x, 1.0 / 4.0, 0}));
}

TEST(ShapesEllipsoid, StartsInsideReportsExit) {
  Ellipsoid e({0, 0, 0}, {2, 2, 2});
  Hit hit;
  ASSERT_TRUE(e.intersect(make_segment({0, 0, 0}, {4, 0, 0}), hit));
  EXPECT_NEAR(hit.s, 0.5, kTol);
  expect_vec(hit.normal, {1, 0, 0});  // outward
}

TEST(ShapesEllipsoid, ShortSegmentAndCloserHitAreRespected) {
  Ellipsoid e({0, 0, 0}, {1, 1, 1});
  Hit hit;
  EXPECT_FALSE(e.intersect(make_segment({-5, 0, 0}, {-3, 0, 0}), hit));
  hit.s = 0.3;  // a closer hit exists already (sphere entry would be at s = 0.4)
  EXPECT_FALSE(e.intersect(make_segment({-5, 0, 0}, {5, 0, 0}), hit));
  EXPECT_EQ(hit.s, 0.3);
}

TEST(ShapesEllipsoid, GeoViSTextureCoordinates) {
  // Point on the unit sphere at polar angle θ, azimuth φ: v = acos(−cos θ)/π = 1 − θ/π and
  // u = φ/2π (acos(n_x/sin θ)/2π, mirrored to 1 − u for n_y < 0).
  Ellipsoid e({0, 0, 0}, {3, 3, 3});
  for (double th : {0.3, 1.0, 1.5707963, 2.5}) {
    for (double ph : {0.2, 1.4, 3.0, 3.5, 5.0, 6.1}) {
      const Vec3 n{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      Hit hit;
      ASSERT_TRUE(e.intersect(make_segment(10.0 * n, {0, 0, 0}), hit));
      EXPECT_NEAR(hit.u, ph / (2 * M_PI), 1e-9) << th << " " << ph;
      EXPECT_NEAR(hit.v, 1.0 - th / M_PI, 1e-9) << th << " " << ph;
    }
  }
}

TEST(ShapesBox, FacesNormalsPartsAndUV) {
  Box b({5, -9, -5}, {-5, 9, -2});  // corners in any order (minkWheel.scm)
  Hit hit;
  ASSERT_TRUE(b.intersect(make_segment({0, 0, 10}, {0, 0, -10}), hit));
  EXPECT_NEAR(hit.s, 0.6, kTol);
  expect_vec(hit.normal, {0, 0, 1});
  EXPECT_EQ(hit.part, 5);
  EXPECT_NEAR(hit.u, 0.5, kTol);
  EXPECT_NEAR(hit.v, 0.5, kTol);
  Hit side;
  ASSERT_TRUE(b.intersect(make_segment({-10, 0, -3}, {10, 0, -3}), side));
  EXPECT_NEAR(side.s, 0.25, kTol);
  expect_vec(side.normal, {-1, 0, 0});
  EXPECT_EQ(side.part, 0);
  EXPECT_NEAR(side.u, 0.5, kTol);        // 1 − q_y
  EXPECT_NEAR(side.v, 2.0 / 3.0, kTol);  // q_z = (−3 − (−5)) / 3
  Hit miss;
  EXPECT_FALSE(b.intersect(make_segment({-10, 10, -3}, {10, 10, -3}), miss));
}

TEST(ShapesCylinder, SideAndCapHits) {
  Cylinder c({0, 0, 0}, {0, 0, 2}, 1, 1);
  Hit side;
  ASSERT_TRUE(c.intersect(make_segment({-5, 0, 1}, {5, 0, 1}), side));
  EXPECT_NEAR(side.s, 0.4, kTol);
  expect_vec(side.normal, {-1, 0, 0});
  EXPECT_EQ(side.part, 0);
  EXPECT_NEAR(side.v, 0.5, kTol);
  Hit cap;
  ASSERT_TRUE(c.intersect(make_segment({0.5, 0, 5}, {0.5, 0, -5}), cap));
  EXPECT_NEAR(cap.s, 0.3, kTol);
  expect_vec(cap.normal, {0, 0, 1});
  EXPECT_EQ(cap.part, 2);
  Hit miss;
  EXPECT_FALSE(c.intersect(make_segment({-5, 0, 2.5}, {5, 0, 2.5}), miss));
}

TEST(ShapesCylinder, EllipticCrossSection) {
  // Axis z: radius 2 along x, 1 along y. The line x = 1 along +y meets x²/4 + y² = 1 at
  // y = −√3/2, normal ∝ (x/4, y, 0).
  Cylinder c({0, 0, -1}, {0, 0, 1}, 2, 1);
  Hit hit;
  ASSERT_TRUE(c.intersect(make_segment({1, -5, 0}, {1, 5, 0}), hit));
  const double y = -std::sqrt(3.0) / 2;
  EXPECT_NEAR(hit.s, (y + 5) / 10, kTol);
  expect_vec(hit.normal, normalize(Vec3{0.25, y, 0}));
}

TEST(ShapesRing, OuterInnerAndAnnulusHits) {
  Ring r({0, 0, 0}, {0, 0, 1}, 2, 2, 1, 1);
  Hit outer;
  ASSERT_TRUE(r.intersect(make_segment({-5, 0, 0.5}, {5, 0, 0.5}), outer));
  EXPECT_NEAR(outer.s, 0.3, kTol);
  expect_vec(outer.normal, {-1, 0, 0});
  Hit inner;  // from the hole outwards: the inner wall, normal towards the axis
  ASSERT_TRUE(r.intersect(make_segment({0, 0, 0.5}, {5, 0, 0.5}), inner));
  EXPECT_NEAR(inner.s, 0.2, kTol);
  expect_vec(inner.normal, {-1, 0, 0});
  EXPECT_EQ(inner.part, 3);
  Hit top;
  ASSERT_TRUE(r.intersect(make_segment({1.5, 0, 5}, {1.5, 0, -5}), top));
  EXPECT_NEAR(top.s, 0.4, kTol);
  expect_vec(top.normal, {0, 0, 1});
  EXPECT_NEAR(top.v, 0.75, kTol);  // GvsSolRing: √(x² + y²) in the outer unit frame, 1.5/2
  Hit hole;
  EXPECT_FALSE(r.intersect(make_segment({0.5, 0, 5}, {0.5, 0, -5}), hole));
}

TEST(ShapesTransform, TranslatedScaledSphere) {
  // Unit sphere, object-to-coordinates M = T(3,0,0)·S(2): a sphere of radius 2 at (3,0,0).
  Ellipsoid e({0, 0, 0}, {1, 1, 1});
  e.set_transform(translate(3, 0, 0) * scale(2, 2, 2));
  Hit hit;
  ASSERT_TRUE(e.intersect(make_segment({-5, 0, 0}, {5, 0, 0}), hit));
  EXPECT_NEAR(hit.s, 0.6, kTol);
  expect_vec(hit.point, {1, 0, 0});
  expect_vec(hit.normal, {-1, 0, 0});
  const Bounds3 b = e.bounds();
  expect_vec(b.lo, {1, -2, -2});
  expect_vec(b.hi, {5, 2, 2});
}

TEST(ShapesTransform, RotatedBoxAndNonUniformScaleNormal) {
  // Cube [−1,1]³ turned 45° about z: at y = 0.5 the ray along +x enters the rotated +y face
  // −x + y = √2 at x = 0.5 − √2, normal (−1, 1, 0)/√2.
  Box b({-1, -1, -1}, {1, 1, 1});
  b.set_transform(rotate_z(45));
  Hit hit;
  ASSERT_TRUE(b.intersect(make_segment({-5, 0.5, 0}, {5, 0.5, 0}), hit));
  EXPECT_NEAR(hit.s, (0.5 - std::sqrt(2.0) + 5) / 10, 1e-12);
  expect_vec(hit.normal, normalize(Vec3{-1, 1, 0}), 1e-12);
  // Unit sphere scaled to semi-axes (1, 2, 3) equals the ellipsoid with those axes (normals
  // transform with M⁻ᵀ).
  Ellipsoid s({0, 0, 0}, {1, 1, 1}), ref({0, 0, 0}, {1, 2, 3});
  s.set_transform(scale(1, 2, 3));
  Hit a, c;
  const Segment seg = make_segment({-4, 0.7, 1.1}, {4, 0.3, -0.2});
  ASSERT_TRUE(s.intersect(seg, a));
  ASSERT_TRUE(ref.intersect(seg, c));
  EXPECT_NEAR(a.s, c.s, 1e-12);
  expect_vec(a.normal, c.normal, 1e-12);
}

TEST(ShapesPlaneRing, AccretionDiskUVAndTwoSidedNormal) {
  PlaneRing disk({0, 0, 0}, {0, 0, 1}, 3, 15);
  Hit hit;
  ASSERT_TRUE(disk.intersect(make_segment({5, 0, 10}, {5, 0, -10}), hit));
  EXPECT_NEAR(hit.s, 0.5, kTol);
  expect_vec(hit.point, {5, 0, 0});
  expect_vec(hit.normal, {0, 0, 1});
  // GvsPlanarRing::calcTexUVParam: u = (r − rin)/(rout − rin), v = atan2(y, x)/2π + 1/2.
  EXPECT_NEAR(hit.u, (5.0 - 3.0) / 12.0, kTol);
  EXPECT_NEAR(hit.v, 0.5, kTol);
  Hit below;
  ASSERT_TRUE(disk.intersect(make_segment({0, -5, -10}, {0, -5, 10}), below));
  expect_vec(below.normal, {0, 0, -1});  // faces the ray coming from below
  EXPECT_NEAR(below.v, 0.25, kTol);      // atan2 = −π/2
  Hit side;
  ASSERT_TRUE(disk.intersect(make_segment({0, 9, 1}, {0, 9, -1}), side));
  EXPECT_NEAR(side.u, 0.5, kTol);
  EXPECT_NEAR(side.v, 0.75, kTol);  // atan2 = π/2
  Hit back;
  ASSERT_TRUE(disk.intersect(make_segment({-15, 0, 1}, {-15, 0, -1}), back));
  EXPECT_NEAR(back.u, 1.0, kTol);
  EXPECT_NEAR(back.v, 1.0, kTol);  // atan2(+0, −15) = π
  Hit miss;
  EXPECT_FALSE(disk.intersect(make_segment({2, 0, 1}, {2, 0, -1}), miss));    // in the hole
  EXPECT_FALSE(disk.intersect(make_segment({16, 0, 1}, {16, 0, -1}), miss));  // outside
}

TEST(ShapesPlanar, TriangleAndParallelogram) {
  Triangle t({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  Parallelogram p({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  Hit h;
  ASSERT_TRUE(t.intersect(make_segment({0.25, 0.5, 1}, {0.25, 0.5, -1}), h));
  EXPECT_NEAR(h.s, 0.5, kTol);
  EXPECT_NEAR(h.u, 0.25, kTol);
  EXPECT_NEAR(h.v, 0.5, kTol);
  expect_vec(h.normal, {0, 0, 1});
  Hit miss;
  EXPECT_FALSE(t.intersect(make_segment({0.75, 0.75, 1}, {0.75, 0.75, -1}), miss));
  Hit hp;
  ASSERT_TRUE(p.intersect(make_segment({0.75, 0.75, 1}, {0.75, 0.75, -1}), hp));
  EXPECT_NEAR(hp.u, 0.75, kTol);
  EXPECT_NEAR(hp.v, 0.75, kTol);
  EXPECT_FALSE(p.intersect(make_segment({1.1, 0.5, 1}, {1.1, 0.5, -1}), miss));
}

TEST(ShapesChart, ObjectOnlyInItsChart) {
  Ellipsoid e({0, 0, 0}, {1, 1, 1});
  e.chart = 1;
  Segment seg = make_segment({-5, 0, 0}, {5, 0, 0});
  Hit hit;
  EXPECT_FALSE(e.intersect(seg, hit));
  seg.chart0 = seg.chart1 = 1;
  EXPECT_TRUE(e.intersect(seg, hit));
}

// ---- factories ----------------------------------------------------------------------------------

ParamSet params(const std::string& cmd) { return ParamSet(cmd, SourceLoc{"scene.scm", 12}); }

TEST(ShapesFactory, PrimitivesGetObjectIdsShaderAndTransform) {
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  ctx.shaders["sh"] = std::make_shared<SurfaceShader>();
  ParamSet a = params("solid-ellipsoid");
  a.add("center", std::vector<double>{0, 0, 0});
  a.add("axlen", std::vector<double>{1, 1, 1});
  a.add("shader", "sh");
  a.add("transform", translate(0, 0, 3));
  a.add("id", "ball");
  auto ball = make_object(a, ctx);
  ParamSet b = params("solid-box");
  b.add("cornerll", std::vector<double>{-1, -1, -1});
  b.add("cornerur", std::vector<double>{1, 1, 1});
  auto box = make_object(b, ctx);
  Hit h1, h2;
  ASSERT_TRUE(ball->intersect(make_segment({0, 0, 10}, {0, 0, 0}), h1));
  EXPECT_NEAR(h1.s, 0.6, kTol);  // sphere top at z = 4
  EXPECT_EQ(h1.object_id, 1);
  EXPECT_EQ(h1.shader, ctx.shaders["sh"].get());
  ASSERT_TRUE(box->intersect(make_segment({0, 0, -10}, {0, 0, 0}), h2));
  EXPECT_EQ(h2.object_id, 2);
  EXPECT_TRUE(diag.warnings().empty());
}

TEST(ShapesFactory, ClearErrors) {
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  ctx.shaders["ballShader"] = std::make_shared<SurfaceShader>();
  ParamSet a = params("solid-ellipsoid");
  a.add("shader", "ballShadr");
  try {
    make_object(a, ctx);
    FAIL() << "expected an error";
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("scene.scm:12: solid-ellipsoid: shader:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("ballShader"), std::string::npos) << msg;  // did you mean
  }
  ParamSet b = params("solid-box");
  b.add("cornerll", std::vector<double>{0, 0});
  b.add("cornerur", std::vector<double>{1, 1, 1});
  EXPECT_THROW(make_object(b, ctx), SceneError);
  ParamSet c = params("plane-ring");
  c.add("rout", 2.0);
  c.add("rin", 3.0);
  EXPECT_THROW(make_object(c, ctx), SceneError);
  ParamSet d = params("solid-elipsoid");
  try {
    make_object(d, ctx);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("solid-ellipsoid"), std::string::npos) << e.what();
  }
  ParamSet w = params("solid-ellipsoid");
  w.add("axlenn", std::vector<double>{1, 1, 1});
  make_object(w, ctx);
  ASSERT_EQ(diag.warnings().size(), 1u);
  EXPECT_NE(diag.warnings()[0].find("axlen"), std::string::npos);
}

TEST(ShapesFactory, LocalObjectInPlainCompoundIsPlacedInCoordinates) {
  // GeoViS ignores objtype when intersecting (appViewMovBall.scm puts gpObjTypeLocal spheres in
  // a comp-object): the unit sphere at the origin is hit where it would be with InCoords.
  BuildContext ctx;
  ParamSet a = params("solid-ellipsoid");
  a.add("objtype", 0);
  ctx.objects["local"] = make_object(a, ctx);
  ParamSet c = params("comp-object");
  c.add("obj", "local");
  const SceneObjectPtr comp = make_object(c, ctx);
  Hit hit;
  ASSERT_TRUE(comp->intersect(make_segment({-5, 0, 0}, {5, 0, 0}), hit));
  EXPECT_NEAR(hit.s, 0.4, kTol);
}

// ---- GeoViS semantics: expected values from the GeoViS formulas by hand ------------

TEST(ShapesCylinder, GeoViSFrameAndTextureCoordinatesAxisZ) {
  // Axis along +z: α = atan2(0, 0) = 0, β = atan2(0, 2) = 0, so e1 = x̂, e2 = ŷ; the unit
  // cylinder point is (x, y, z/2). Side: u = acos(x)/2π (1 − that for y < 0), v = z/2.
  Cylinder c({0, 0, 0}, {0, 0, 2}, 1, 1);
  expect_vec(c.frame.e1, {1, 0, 0});
  expect_vec(c.frame.e2, {0, 1, 0});
  Hit a;  // enters the side at (0, 1, 0.5)
  ASSERT_TRUE(c.intersect(make_segment({0, 5, 0.5}, {0, -5, 0.5}), a));
  EXPECT_EQ(a.part, 0);
  EXPECT_NEAR(a.u, 0.25, kTol);  // acos(0)/2π
  EXPECT_NEAR(a.v, 0.25, kTol);
  Hit b;  // enters the side at (0, −1, 1.5): y < 0
  ASSERT_TRUE(c.intersect(make_segment({0, -5, 1.5}, {0, 5, 1.5}), b));
  EXPECT_NEAR(b.u, 0.75, kTol);
  EXPECT_NEAR(b.v, 0.75, kTol);
  Hit d;  // (−1, 0, 1): acos(−1)/2π
  ASSERT_TRUE(c.intersect(make_segment({-5, 0, 1}, {5, 0, 1}), d));
  EXPECT_NEAR(d.u, 0.5, kTol);
  // Caps: u = (atan2(y, x) + π)/2π, v = √(x² + y²).
  Hit top;  // (0.5, 0, 2)
  ASSERT_TRUE(c.intersect(make_segment({0.5, 0, 5}, {0.5, 0, -5}), top));
  EXPECT_EQ(top.part, 2);
  EXPECT_NEAR(top.u, 0.5, kTol);
  EXPECT_NEAR(top.v, 0.5, kTol);
  Hit bottom;  // (0, −0.8, 0): atan2 = −π/2
  ASSERT_TRUE(c.intersect(make_segment({0, -0.8, -5}, {0, -0.8, 5}), bottom));
  EXPECT_EQ(bottom.part, 1);
  EXPECT_NEAR(bottom.u, 0.25, kTol);
  EXPECT_NEAR(bottom.v, 0.8, kTol);
}

TEST(ShapesCylinder, GeoViSFrameAxisX) {
  // Axis along +x, length 2: α = 0, β = atan2(2, 0) = π/2, so e1 = (cos α cos β, sin α cos β,
  // −sin β) = (0, 0, −1), e2 = (−sin α, cos α, 0) = (0, 1, 0). Radii 1 (e1) and 0.5 (e2).
  Cylinder c({0, 0, 0}, {2, 0, 0}, 1, 0.5);
  expect_vec(c.frame.e1, {0, 0, -1});
  expect_vec(c.frame.e2, {0, 1, 0});
  expect_vec(c.frame.ez, {1, 0, 0});
  Hit a;  // (1, 0, −1): x_l = 1, y_l = 0 → u = acos(1)/2π = 0, v = 1/2
  ASSERT_TRUE(c.intersect(make_segment({1, 0, -5}, {1, 0, 5}), a));
  EXPECT_NEAR(a.u, 0.0, kTol);
  EXPECT_NEAR(a.v, 0.5, kTol);
  Hit b;  // (0.5, 0, 1): x_l = −1 → u = 1/2, v = 1/4
  ASSERT_TRUE(c.intersect(make_segment({0.5, 0, 5}, {0.5, 0, -5}), b));
  EXPECT_NEAR(b.u, 0.5, kTol);
  EXPECT_NEAR(b.v, 0.25, kTol);
  Hit e;  // (1.5, 0.5, 0): y_l = 0.5/0.5 = 1 → u = 1/4
  ASSERT_TRUE(c.intersect(make_segment({1.5, 5, 0}, {1.5, -5, 0}), e));
  EXPECT_NEAR(e.u, 0.25, kTol);
  EXPECT_NEAR(e.v, 0.75, kTol);
  Hit cap;  // top cap (2, 0.25, −0.5): x_l = 0.5, y_l = 0.5 → u = (π/4 + π)/2π = 5/8, v = √0.5
  ASSERT_TRUE(c.intersect(make_segment({5, 0.25, -0.5}, {-5, 0.25, -0.5}), cap));
  EXPECT_EQ(cap.part, 2);
  EXPECT_NEAR(cap.u, 0.625, kTol);
  EXPECT_NEAR(cap.v, std::sqrt(0.5), kTol);
}

TEST(ShapesRing, GeoViSTextureCoordinates) {
  // Axis z, outer radius 2, inner 1, height 1: caps and outer side in the outer unit frame
  // (coordinates / 2), the inner side in the inner unit frame (coordinates / 1).
  Ring r({0, 0, 0}, {0, 0, 1}, 2, 2, 1, 1);
  Hit top;  // (−1.5, 0, 1): (x, y) = (−0.75, 0) → u = (π + π)/2π = 1, v = 0.75
  ASSERT_TRUE(r.intersect(make_segment({-1.5, 0, 5}, {-1.5, 0, -5}), top));
  EXPECT_EQ(top.part, 2);
  EXPECT_NEAR(top.u, 1.0, kTol);
  EXPECT_NEAR(top.v, 0.75, kTol);
  Hit outer;  // (0, 2, 0.25): (0, 1) → u = 1/4, v = 1/4
  ASSERT_TRUE(r.intersect(make_segment({0, 5, 0.25}, {0, 1.5, 0.25}), outer));
  EXPECT_EQ(outer.part, 0);
  EXPECT_NEAR(outer.u, 0.25, kTol);
  EXPECT_NEAR(outer.v, 0.25, kTol);
  Hit inner;  // from the hole: (0, −1, 0.5), inner frame (0, −1) → u = 1 − 1/4
  ASSERT_TRUE(r.intersect(make_segment({0, 0, 0.5}, {0, -5, 0.5}), inner));
  EXPECT_EQ(inner.part, 3);
  EXPECT_NEAR(inner.u, 0.75, kTol);
  EXPECT_NEAR(inner.v, 0.5, kTol);
}

TEST(ShapesBox, DiffuseFrameIsTheUnitCube) {
  // Box [0,2]×[0,1]×[0,1] turned 90° about z. In the box's own frame the ray runs along
  // d = (−1, −1, 0) and enters the +y face (normal ŷ) at (1, 1, 0.5); GeoViS shades in the
  // unit cube, where d becomes (−1/2, −1, 0): cos = 1/√(1/4 + 1) = 2/√5 (the parent frame
  // would give 1/√2).
  Box b({0, 0, 0}, {2, 1, 1});
  b.set_transform(rotate_z(90));
  // Parent frame: R(90°) maps (1, 1, 0.5) to (−1, 1, 0.5) and d to (1, −1, 0).
  Hit hit;
  ASSERT_TRUE(b.intersect(make_segment({-1.5, 1.5, 0.5}, {-0.5, 0.5, 0.5}), hit));
  EXPECT_NEAR(hit.s, 0.5, kTol);
  EXPECT_EQ(hit.part, 3);
  expect_vec(hit.shade_normal, {0, 1, 0});
  expect_vec(hit.shade_dir, normalize(Vec3{-0.5, -1, 0}));
  SurfaceShader sh;
  sh.objcolor = std::make_shared<UniTexture>(Color{1, 1, 1});
  sh.ambient = 0.1;
  sh.diffuse = 0.5;
  const Color c = sh.shade(hit, ShadeContext{});
  EXPECT_NEAR(c.r, 0.1 + 0.5 * 2 / std::sqrt(5.0), 1e-12);
  // The −y face from inside the box frame's first quadrant: box-frame d = (1, 1, 0) entering at
  // (1, 0, 0.5), i.e. parent d = (−1, 1, 0) at (0, 1, 0.5); unit-cube d = (1/2, 1, 0)/√(5/4).
  Hit under;
  ASSERT_TRUE(b.intersect(make_segment({0.5, 0.5, 0.5}, {-0.5, 1.5, 0.5}), under));
  EXPECT_EQ(under.part, 2);
  EXPECT_NEAR(sh.shade(under, ShadeContext{}).r, 0.1 + 0.5 * 2 / std::sqrt(5.0), 1e-12);
  // A normal map replaces the normal in the same frame, n = −normalize(rgb): rgb (1, 0, 0) gives
  // n = −x̂ and cos = n·(−d) = (1/2)/√(5/4) = 1/√5.
  sh.normalmap = std::make_shared<UniTexture>(Color{1, 0, 0});
  EXPECT_NEAR(sh.shade(under, ShadeContext{}).r, 0.1 + 0.5 / std::sqrt(5.0), 1e-12);
  // Seen from the other side (the +y face hit above, d = (−1/2, −1, 0)/|…|) the same map gives
  // n·(−d) < 0: ambient only.
  EXPECT_NEAR(sh.shade(hit, ShadeContext{}).r, 0.1, 1e-12);
}

TEST(ShapesEllipsoid, DiffuseFrameIsTheUnitSphere) {
  // Ellipsoid with semi-axes (2, 1, 1): the ray along +x at y = 0.5 enters x²/4 + y² = 1 at
  // x = −√3. Unit sphere: n = (−√3/2, 0.5, 0), d = (1/2, 0, 0)/|…| =
  // x̂: cos = √3/2 (the parent-frame normal ∝ (x/4, y, 0) would give a different factor).
  Ellipsoid e({0, 0, 0}, {2, 1, 1});
  Hit hit;
  ASSERT_TRUE(e.intersect(make_segment({-5, 0.5, 0}, {5, 0.5, 0}), hit));
  expect_vec(hit.shade_normal, {-std::sqrt(3.0) / 2, 0.5, 0});
  expect_vec(hit.shade_dir, {1, 0, 0});
  SurfaceShader sh;
  sh.objcolor = std::make_shared<UniTexture>(Color{1, 1, 1});
  sh.ambient = 0;
  sh.diffuse = 1;
  EXPECT_NEAR(sh.shade(hit, ShadeContext{}).g, std::sqrt(3.0) / 2, 1e-12);
}

TEST(ObjectRegistry, HoldsEveryObjectCommand) {
  // Registered by static objects beside each class (shapes, mesh, csg, compound, local_object).
  EXPECT_EQ(object_commands(), (std::vector<std::string>{
                                   "comp-object", "comp-octree-object", "csg-object", "local-comp-object", "mesh-obj",
                                   "plane-parallelogram", "plane-ring", "plane-triangle", "solid-background",
                                   "solid-box", "solid-cylinder", "solid-ellipsoid", "solid-ring"}));
}

}  // namespace
}  // namespace geovis
