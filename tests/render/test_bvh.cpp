// The compound's BVH returns exactly the brute-force closest hit.
#include <gtest/gtest.h>

#include <random>

#include "object_test_helpers.h"
#include "render/compound.h"

namespace geovis {
namespace {

using testing::make_segment;

TEST(ObjBvh, ThousandSpheresMatchBruteForce) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> pos(-20, 20), rad(0.05, 1.0);
  std::vector<SceneObjectPtr> spheres;
  for (int i = 0; i < 1000; ++i) {
    const double r = rad(rng);
    auto e = std::make_shared<Ellipsoid>(Vec3{pos(rng), pos(rng), pos(rng)}, Vec3{r, r, r});
    e->object_id = i + 1;
    spheres.push_back(e);
  }
  CompoundObject comp(spheres);
  int hits = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 a{pos(rng), pos(rng), pos(rng)}, b{pos(rng), pos(rng), pos(rng)};
    const Segment seg = make_segment(a, b);
    Hit brute;
    for (const auto& s : spheres) s->intersect(seg, brute);
    Hit fast;
    const bool found = comp.intersect(seg, fast);
    ASSERT_EQ(found, brute.valid()) << k;
    if (!found) continue;
    ++hits;
    EXPECT_EQ(fast.s, brute.s) << k;
    EXPECT_EQ(fast.object_id, brute.object_id) << k;
  }
  EXPECT_GT(hits, 300);  // the test exercises many hits
}

TEST(ObjBvh, UnboundedChildrenAndEmptyCompound) {
  CompoundObject empty;
  Hit h;
  EXPECT_FALSE(empty.intersect(make_segment({0, 0, 0}, {1, 1, 1}), h));
  // A compound with a transform moves all its children.
  auto e = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 1, 1});
  CompoundObject moved({e});
  Transform t = Transform::identity(3);
  t(0, 3) = 3;
  moved.set_transform(t);
  ASSERT_TRUE(moved.intersect(make_segment({-5, 0, 0}, {5, 0, 0}), h));
  EXPECT_NEAR(h.s, 0.7, 1e-12);
  EXPECT_NEAR(h.point.x, 2, 1e-12);
  EXPECT_NEAR(h.normal.x, -1, 1e-12);
}

}  // namespace
}  // namespace geovis
