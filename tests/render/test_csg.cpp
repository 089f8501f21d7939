// CSG by interval arithmetic: difference/union/intersection spans and the reported surfaces.
#include <gtest/gtest.h>

#include <memory>

#include "object_test_helpers.h"
#include "render/csg.h"
#include "render/plugins.h"

namespace geovis {
namespace {

using testing::make_segment;
constexpr double kTol = 1e-12;

std::shared_ptr<Ellipsoid> sphere(double cx, double r, int id) {
  auto e = std::make_shared<Ellipsoid>(Vec3{cx, 0, 0}, Vec3{r, r, r});
  e->object_id = id;
  return e;
}

// Two unit spheres A at x = 0 and B at x = 1 along the x axis: A = [−1, 1], B = [0, 2].
struct TwoSpheres : ::testing::Test {
  std::shared_ptr<Ellipsoid> a = sphere(0, 1, 1), b = sphere(1, 1, 2);
  // x = −5 + 10 t
  static double t_of(double x) { return (x + 5) / 10; }
  SpanList spans(const Solid& s) const {
    SpanList l;
    s.spans({-5, 0, 0}, {10, 0, 0}, l);
    return l;
  }
};

TEST_F(TwoSpheres, UnionIsOneInterval) {
  CsgObject u(CsgOp::Union, a, b);
  const SpanList l = spans(u);
  ASSERT_EQ(l.n, 1);
  EXPECT_NEAR(l.s[0].in.t, t_of(-1), kTol);
  EXPECT_NEAR(l.s[0].out.t, t_of(2), kTol);
}

TEST_F(TwoSpheres, IntersectionIsTheLens) {
  CsgObject i(CsgOp::Intersection, a, b);
  const SpanList l = spans(i);
  ASSERT_EQ(l.n, 1);
  EXPECT_NEAR(l.s[0].in.t, t_of(0), kTol);
  EXPECT_NEAR(l.s[0].out.t, t_of(1), kTol);
  Hit hit;
  ASSERT_TRUE(i.intersect(make_segment({-5, 0, 0}, {5, 0, 0}), hit));
  EXPECT_NEAR(hit.s, 0.5, kTol);
  EXPECT_EQ(hit.object_id, 2);  // the entry surface belongs to B
  EXPECT_NEAR(hit.normal.x, -1, kTol);
}

TEST_F(TwoSpheres, DifferenceFlipsTheSubtractedSurface) {
  CsgObject d(CsgOp::Difference, a, b);  // A − B = [−1, 0]
  const SpanList l = spans(d);
  ASSERT_EQ(l.n, 1);
  EXPECT_NEAR(l.s[0].in.t, t_of(-1), kTol);
  EXPECT_NEAR(l.s[0].out.t, t_of(0), kTol);
  EXPECT_TRUE(l.s[0].out.flip);
  // Seen from +x the first surface is B's, at x = 0, with the normal pointing out of A − B (+x).
  Hit hit;
  ASSERT_TRUE(d.intersect(make_segment({5, 0, 0}, {-5, 0, 0}), hit));
  EXPECT_NEAR(hit.s, 0.5, kTol);
  EXPECT_EQ(hit.object_id, 2);
  EXPECT_NEAR(hit.normal.x, 1, kTol);
  // B − A = [1, 2]: entry at x = 1 is A's exit surface, normal −x.
  CsgObject d2(CsgOp::Difference, b, a);
  Hit h2;
  ASSERT_TRUE(d2.intersect(make_segment({-5, 0, 0}, {5, 0, 0}), h2));
  EXPECT_NEAR(h2.s, t_of(1), kTol);
  EXPECT_EQ(h2.object_id, 1);
  EXPECT_NEAR(h2.normal.x, -1, kTol);
  // A segment starting in the removed part first meets the surface at x = 0.
  Hit h3;
  ASSERT_TRUE(d.intersect(make_segment({0.5, 0, 0}, {-5.5, 0, 0}), h3));
  EXPECT_NEAR(h3.s, 0.5 / 6.0, kTol);
}

TEST(CsgSpans, DifferenceWithTwoHoles) {
  // [0, 10] minus [2, 3] and [5, 6] = [0, 2], [3, 5], [6, 10].
  auto span = [](double a, double b) {
    Span s;
    s.in.t = a;
    s.out.t = b;
    return s;
  };
  SpanList A, B, out;
  A.push(span(0, 10));
  B.push(span(2, 3));
  B.push(span(5, 6));
  csg_difference(A, B, out);
  ASSERT_EQ(out.n, 3);
  const double expect[3][2] = {{0, 2}, {3, 5}, {6, 10}};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(out.s[i].in.t, expect[i][0]);
    EXPECT_EQ(out.s[i].out.t, expect[i][1]);
  }
  EXPECT_FALSE(out.s[0].in.flip);
  EXPECT_TRUE(out.s[0].out.flip);
  EXPECT_TRUE(out.s[1].in.flip);
  SpanList u;
  csg_union(A, B, u);
  ASSERT_EQ(u.n, 1);
  EXPECT_EQ(u.s[0].out.t, 10);
  SpanList i;
  csg_intersection(A, B, i);
  ASSERT_EQ(i.n, 2);
  EXPECT_EQ(i.s[1].in.t, 5);
}

TEST(CsgFactory, WheelRimFromTwoCylinders) {
  // minkWheel.scm's rim: cylinder radius 2 (|x| <= 0.15) minus cylinder radius 1.8 (|x| <= 0.152).
  BuildContext ctx;
  ParamSet o("solid-cylinder", {});
  o.add("base", std::vector<double>{-0.15, 0, 0});
  o.add("top", std::vector<double>{0.15, 0, 0});
  o.add("radii", std::vector<double>{2, 2});
  ctx.objects["outer"] = make_object(o, ctx);
  ParamSet in("solid-cylinder", {});
  in.add("base", std::vector<double>{-0.152, 0, 0});
  in.add("top", std::vector<double>{0.152, 0, 0});
  in.add("radii", std::vector<double>{1.8, 1.8});
  ctx.objects["inner"] = make_object(in, ctx);
  ParamSet c("csg-object", {});
  c.add("csgtype", 1);
  c.add("obj1", "outer");
  c.add("obj2", "inner");
  auto rim = make_object(c, ctx);
  Hit axis;  // along the axis through the hole: nothing
  EXPECT_FALSE(rim->intersect(make_segment({-5, 0, 0}, {5, 0, 0}), axis));
  Hit through;  // along y through the rim: enters at y = −2
  ASSERT_TRUE(rim->intersect(make_segment({0, -5, 0}, {0, 5, 0}), through));
  EXPECT_NEAR(through.s, 0.3, kTol);
  EXPECT_NEAR(through.normal.y, -1, kTol);
  Hit inside;  // from inside the rim material: leaves through the inner surface y = −1.8
  ASSERT_TRUE(rim->intersect(make_segment({0, -1.9, 0}, {0, 0.1, 0}), inside));
  EXPECT_NEAR(inside.s, 0.05, kTol);
  EXPECT_NEAR(inside.normal.y, 1, kTol);  // out of the rim, towards the axis
  EXPECT_EQ(inside.object_id, 2);
  Hit face;  // parallel to the axis at radius 1.9: the rim's side face at x = −0.15
  ASSERT_TRUE(rim->intersect(make_segment({-5, 1.9, 0}, {5, 1.9, 0}), face));
  EXPECT_NEAR(face.s, (5 - 0.15) / 10, kTol);
  EXPECT_NEAR(face.normal.x, -1, kTol);
  ParamSet bad("csg-object", {});
  bad.add("csgtype", 4);
  bad.add("obj1", "outer");
  bad.add("obj2", "inner");
  EXPECT_THROW(make_object(bad, ctx), SceneError);
}

}  // namespace
}  // namespace geovis
