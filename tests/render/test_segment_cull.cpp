// The scene's empty regions (render/segment_cull.h): no surface point of a shape lies inside its
// ball (SceneObject::surface_free_radius), no chord inside it hits the shape, the ball is as large
// as the geometry allows where that is known in closed form; no chord that hits a shape lies
// beyond a face of its (widened) bounding box; and a render that skips the steps inside the balls
// and beyond the box is the render that tests every step, to the bit.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "object_test_helpers.h"
#include "render/compound.h"
#include "render/csg.h"
#include "render/data_exr.h"
#include "render/panorama_camera.h"
#include "render/renderer.h"
#include "render/segment_cull.h"
#include "render/shapes.h"
#include "render/tracer.h"
#include "spacetime/geodesic_packet.h"
#include "spacetime/metric.h"
#include "spacetime/metric_registry.h"

namespace geovis {
// A named namespace: the layer's tests are compiled in unity units (tests/CMakeLists.txt).
namespace segment_cull_test {

using testing::make_segment;

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

Transform affine(const double (&a)[3][3], const Vec3& b) {
  Transform t = Transform::identity(3);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) t(r, c) = a[r][c];
    t(r, 3) = b[r];
  }
  return t;
}

/// Rotation by `deg` about z, scaled by s, then translated by b.
Transform rotate_scale(double deg, double s, const Vec3& b) {
  const double c = std::cos(deg * kPi / 180), n = std::sin(deg * kPi / 180);
  return affine({{s * c, -s * n, 0}, {s * n, s * c, 0}, {0, 0, s}}, b);
}

/// Unit vectors on a θ-φ grid (poles included).
std::vector<Vec3> unit_directions(int n = 24) {
  std::vector<Vec3> out;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double th = kPi * i / n, ph = kPi * j / n;
      out.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
    }
  return out;
}

Vec3 to_parent(const PrimitiveData& p, const Vec3& local) { return p.transformed ? p.to_parent.point(local) : local; }

std::vector<Vec3> ellipsoid_surface(const Ellipsoid& e) {
  std::vector<Vec3> out;
  for (const Vec3& n : unit_directions())
    out.push_back(to_parent(e, e.center + Vec3{e.axlen.x * n.x, e.axlen.y * n.y, e.axlen.z * n.z}));
  return out;
}

std::vector<Vec3> box_surface(const Box& b) {
  std::vector<Vec3> out;
  const int n = 16;
  for (int axis = 0; axis < 3; ++axis)
    for (double face : {b.lo[axis], b.hi[axis]})
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          Vec3 p;
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          p[axis] = face;
          p[u] = b.lo[u] + (b.hi[u] - b.lo[u]) * i / n;
          p[v] = b.lo[v] + (b.hi[v] - b.lo[v]) * j / n;
          out.push_back(to_parent(b, p));
        }
  return out;
}

std::vector<Vec3> cylinder_surface(const Cylinder& c) {
  std::vector<Vec3> out;
  const int n = 32;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = 2 * kPi * j / n, z = c.frame.height * i / n;
      out.push_back(to_parent(c, c.frame.base + c.frame.from_frame_dir({c.r1 * std::cos(a), c.r2 * std::sin(a), z})));
      for (double h : {0.0, c.frame.height})  // the caps
        out.push_back(to_parent(c, c.frame.base + c.frame.from_frame_dir({c.r1 * std::cos(a) * i / n,
                                                                         c.r2 * std::sin(a) * i / n, h})));
    }
  return out;
}

/// No sampled surface point lies inside radius r; returns the smallest |p| sampled.
double expect_outside(const std::vector<Vec3>& surface, double r) {
  double closest = kInf;
  for (const Vec3& p : surface) {
    closest = std::min(closest, norm(p));
    EXPECT_GE(norm(p), r * (1 - 1e-14)) << p.x << " " << p.y << " " << p.z;
  }
  return closest;
}

/// Random chords with both ends inside the ball that SegmentCull would skip (radius r shrunk by
/// kMargin), some ending right at its rim, in both directions: none hits the object.
void expect_no_hit_inside(const SceneObject& obj, double r) {
  ASSERT_GT(r, 0);
  const double inside = r * (1 - SegmentCull::kMargin);
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  auto point = [&](bool rim) {
    Vec3 p;
    do p = {u(rng), u(rng), u(rng)};
    while (!(norm(p) <= 1 && norm(p) > 0));
    return rim ? (inside * (1 - 1e-15) / norm(p)) * p : inside * p;
  };
  for (int k = 0; k < 4000; ++k) {
    const Vec3 a = point(k % 3 == 0), b = point(k % 5 == 0);
    Hit hit;
    EXPECT_FALSE(obj.intersect(make_segment(a, b), hit)) << "chord " << k;
  }
}

TEST(SegmentCull, CentredSphereIsFreeUpToItsRadiusAndHitJustBeyond) {
  // The background sphere with the camera inside: its inner surface is the only thing to hit.
  Ellipsoid sky({0, 0, 0}, {60, 60, 60});
  EXPECT_EQ(sky.inner_radius(), 0.0);  // the bounds contain the origin
  EXPECT_NEAR(sky.surface_free_radius(), 60.0, 1e-10);
  expect_outside(ellipsoid_surface(sky), 60);
  expect_no_hit_inside(sky, 60);
  // The ball is tight: a chord reaching 1e-6 beyond it leaves the sphere.
  Hit hit;
  EXPECT_TRUE(sky.intersect(make_segment({0, 0, 0}, {60 * (1 + 1e-6), 0, 0}), hit));
}

TEST(SegmentCull, EllipsoidsOffCentreTriaxialAndTransformed) {
  // Centred triaxial: the smallest semi-axis, reached at (±1, 0, 0).
  Ellipsoid tri({0, 0, 0}, {1, 2, 3});
  EXPECT_NEAR(tri.surface_free_radius(), 1.0, 1e-11);
  EXPECT_NEAR(expect_outside(ellipsoid_surface(tri), 1.0), 1.0, 1e-12);
  expect_no_hit_inside(tri, 1.0);
  // Off centre, around the origin: the inscribed ball of radius 2 about (0.5, 0, 0) holds the
  // ball of radius 1.5 about the origin.
  Ellipsoid off({0.5, 0, 0}, {2, 3, 4});
  EXPECT_NEAR(off.surface_free_radius(), 1.5, 1e-11);
  EXPECT_NEAR(expect_outside(ellipsoid_surface(off), 1.5), 1.5, 1e-12);
  expect_no_hit_inside(off, 1.5);
  // Away from the origin: the distance of its bounds.
  Ellipsoid far({10, 0, 0}, {1, 1, 1});
  EXPECT_EQ(far.surface_free_radius(), 9.0);
  expect_no_hit_inside(far, 9.0);
  // Rotated, scaled by 2, translated by (0.5, 0, 0): the unit-radius inscribed ball becomes one
  // of radius 2 about (0.5, 0, 0).
  Ellipsoid moved({0, 0, 0}, {1, 2, 3});
  moved.set_transform(rotate_scale(30, 2, {0.5, 0, 0}));
  EXPECT_NEAR(moved.surface_free_radius(), 1.5, 1e-11);
  expect_outside(ellipsoid_surface(moved), moved.surface_free_radius());
  expect_no_hit_inside(moved, moved.surface_free_radius());
  // Sheared: no closed form, but the bound is positive and holds.
  Ellipsoid sheared({0, 0, 0}, {3, 3, 3});
  sheared.set_transform(affine({{1, 0.5, 0}, {0, 1, 0.3}, {0.2, 0, 1.5}}, {0.1, -0.2, 0.3}));
  EXPECT_GT(sheared.surface_free_radius(), 1.0);
  expect_outside(ellipsoid_surface(sheared), sheared.surface_free_radius());
  expect_no_hit_inside(sheared, sheared.surface_free_radius());
}

TEST(SegmentCull, BoxAndCylinderInscribedBalls) {
  Box box({-2, -1, -3}, {2, 1, 3});
  EXPECT_NEAR(box.surface_free_radius(), 1.0, 1e-11);
  EXPECT_NEAR(expect_outside(box_surface(box), 1.0), 1.0, 1e-12);
  expect_no_hit_inside(box, 1.0);
  Box turned({-2, -2, -2}, {2, 2, 2});
  turned.set_transform(rotate_scale(45, 1, {0, 0, 0}));
  EXPECT_NEAR(turned.surface_free_radius(), 2.0, 1e-11);
  expect_outside(box_surface(turned), turned.surface_free_radius());
  expect_no_hit_inside(turned, turned.surface_free_radius());
  // Axis from (0, 0, −2) to (0, 0, 2), radii 1 and 1.5: min(r1, r2, h/2) about the middle.
  Cylinder cyl({0, 0, -2}, {0, 0, 2}, 1, 1.5);
  EXPECT_NEAR(cyl.surface_free_radius(), 1.0, 1e-11);
  EXPECT_NEAR(expect_outside(cylinder_surface(cyl), 1.0), 1.0, 1e-12);
  expect_no_hit_inside(cyl, 1.0);
  Cylinder tilted({-1, -1, -1}, {1, 1.5, 1.2}, 2, 2.5);
  EXPECT_GT(tilted.surface_free_radius(), 0.5);
  expect_outside(cylinder_surface(tilted), tilted.surface_free_radius());
  expect_no_hit_inside(tilted, tilted.surface_free_radius());
  // A ring around the origin has its hole there: nothing is known to be free.
  Ring ring({0, 0, -1}, {0, 0, 1}, 3, 3, 1, 1);
  EXPECT_EQ(ring.surface_free_radius(), 0.0);
}

TEST(SegmentCull, CsgTakesTheSmallerOfItsSolids) {
  // A sphere of radius 5 with a ball of radius 1 about (3, 0, 0) cut out: the cavity's surface is
  // 2 from the origin.
  auto big = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{5, 5, 5});
  auto small = std::make_shared<Ellipsoid>(Vec3{3, 0, 0}, Vec3{1, 1, 1});
  for (CsgOp op : {CsgOp::Difference, CsgOp::Union, CsgOp::Intersection}) {
    CsgObject csg(op, big, small);
    const double r = csg.surface_free_radius();
    // The intersection (the small ball) is at least its bounds' distance away.
    EXPECT_NEAR(r, 2.0, 1e-11) << static_cast<int>(op);
    expect_outside(ellipsoid_surface(*small), r);
    expect_no_hit_inside(csg, r);
  }
}

TEST(SegmentCull, CompoundsPerChartAndThroughTheirTransform) {
  auto sky0 = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{50, 50, 50});
  auto sky1 = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{30, 30, 30});
  sky1->chart = 1;
  auto near0 = std::make_shared<Box>(Vec3{20, -1, -1}, Vec3{22, 1, 1});
  CompoundObject scene({sky0, sky1, near0});
  const SegmentCull cull(scene);
  EXPECT_EQ(cull.radius(0), 20 * (1 - SegmentCull::kMargin));
  EXPECT_NEAR(cull.radius(1), 30 * (1 - SegmentCull::kMargin), 1e-10);
  EXPECT_EQ(cull.radius(2), kInf);  // no object in chart 2: nothing to hit there
  EXPECT_EQ(cull.radius(SegmentCull::kCharts), 0.0);
  // Squared radii.
  EXPECT_TRUE(cull.inside_empty_ball(0, 19.9 * 19.9, 0, 0.0));
  EXPECT_FALSE(cull.inside_empty_ball(0, 19.9 * 19.9, 0, 20.0 * 20.0));
  EXPECT_FALSE(cull.inside_empty_ball(0, 1.0, 1, 1.0));  // a chord changing chart is tested
  EXPECT_TRUE(cull.inside_empty_ball(1, 29.0 * 29.0, 1, 1.0));
  // Scaled by 3 and moved by (1, 0, 0): the sphere of radius 2 becomes one of radius 6 about
  // (1, 0, 0), free up to 5 around the origin.
  CompoundObject group({std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{2, 2, 2})});
  group.set_transform(rotate_scale(0, 3, {1, 0, 0}));
  double free[2] = {kInf, kInf};
  group.restrict_surface_free_radii(free, 2);
  EXPECT_NEAR(free[0], 5.0, 1e-10);
  EXPECT_EQ(free[1], kInf);
  expect_no_hit_inside(group, free[0]);
}

// ---- the bounding box ---------------------------------------------------------------------------

/// Random chords around `obj` (ends in its bounds grown by half their size on each side, some
/// pinned to a face of the bounds or a few ulps beyond it, some parallel to a face just outside):
/// none that hits the object is beyond the (widened) bounds of SegmentCull, and none that misses
/// changes the hit it is given. Returns the chords that hit and those the box skips (both must be
/// many for the test to mean something).
void expect_hits_inside_bounds(const SceneObject& obj, int& hits, int& skipped) {
  const SegmentCull cull(obj);
  const Bounds3 b = obj.bounds();
  ASSERT_FALSE(b.empty());
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(cull.bounds().lo[i], b.lo[i]);
    EXPECT_GT(cull.bounds().hi[i], b.hi[i]);
  }
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  std::uniform_int_distribution<int> pick(0, 5), ulps(0, 4);
  // A flat box (a ring, a triangle) grows by its largest size across its thin axis.
  const double size = std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
  auto point = [&](int k) {
    Vec3 p;
    for (int i = 0; i < 3; ++i) {
      const double extent = b.hi[i] - b.lo[i];
      p[i] = extent > 1e-3 * size ? b.lo[i] + u(rng) * extent : 0.5 * (b.lo[i] + b.hi[i]) + (u(rng) - 0.5) * size;
    }
    if (k % 3 == 0) {  // on a face or a few ulps beyond it
      const int face = pick(rng), axis = face / 2;
      double x = face % 2 ? b.hi[axis] : b.lo[axis];
      for (int n = ulps(rng); n > 0; --n) x = std::nextafter(x, face % 2 ? kInf : -kInf);
      p[axis] = x;
    }
    return p;
  };
  hits = skipped = 0;
  for (int k = 0; k < 20000; ++k) {
    Vec3 a = point(k), c = point(k + 1);
    if (k % 7 == 0) {  // parallel to a face, a few ulps outside it
      const int face = pick(rng), axis = face / 2;
      double x = face % 2 ? b.hi[axis] : b.lo[axis];
      for (int n = 1 + ulps(rng); n > 0; --n) x = std::nextafter(x, face % 2 ? kInf : -kInf);
      a[axis] = c[axis] = x;
    }
    Hit hit;
    hit.object_id = -13;  // a miss leaves the hit as it is (SceneObject::intersect)
    const bool hit_found = obj.intersect(make_segment(a, c), hit);
    const bool beyond = cull.outside_bounds(a, c);
    if (!hit_found) {
      EXPECT_TRUE(hit.object_id == -13 && !hit.valid()) << "chord " << k;
    }
    hits += hit_found;
    skipped += beyond;
    EXPECT_FALSE(hit_found && beyond) << "chord " << k << " (" << a.x << " " << a.y << " " << a.z << ") -> (" << c.x
                                      << " " << c.y << " " << c.z << ")";
  }
}

TEST(SegmentCull, ChordsThatHitAreNeverBeyondTheBounds) {
  std::vector<SceneObjectPtr> objects;
  // The Kerr disk's ring (flat bounds: only chords crossing its plane are tested), and tilted.
  // The flat ring needs the widening: a chord from a subnormal distance above its plane upwards
  // hits it at t = −0 (t = −z₀/Δz underflows), which the unwidened box would skip (~100 of the
  // chords here).
  objects.push_back(std::make_shared<PlaneRing>(Vec3{0, 0, 0}, Vec3{0, 0, 1}, 3, 15));
  objects.push_back(std::make_shared<PlaneRing>(Vec3{1, -2, 0.5}, Vec3{0.3, 0.2, 1}, 1, 4));
  auto turned_ring = std::make_shared<PlaneRing>(Vec3{0, 0, 0}, Vec3{0, 0, 1}, 2, 6);
  turned_ring->set_transform(affine({{1, 0, 0}, {0, 0.6, -0.8}, {0, 0.8, 0.6}}, {0, 0, 3}));
  objects.push_back(turned_ring);
  objects.push_back(std::make_shared<Triangle>(Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 3, 0}));
  // Solids whose bounds touch them: the sphere and the box at the middle of each face.
  objects.push_back(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 1, 1}));
  objects.push_back(std::make_shared<Box>(Vec3{-2, -1, -3}, Vec3{2, 1, 3}));
  auto moved = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 2, 3});
  moved->set_transform(rotate_scale(30, 2, {0.5, 0, 0}));
  objects.push_back(moved);
  objects.push_back(std::make_shared<Cylinder>(Vec3{-1, -1, -1}, Vec3{1, 1.5, 1.2}, 2, 2.5));
  // A transformed group of a sphere and a ring.
  auto group = std::make_shared<CompoundObject>(
      std::vector<SceneObjectPtr>{std::make_shared<Ellipsoid>(Vec3{4, 0, 0}, Vec3{1, 1, 1}),
                                  std::make_shared<PlaneRing>(Vec3{0, 0, 0}, Vec3{0, 0, 1}, 1, 3)});
  group->set_transform(rotate_scale(20, 1.5, {0, 1, 0}));
  objects.push_back(group);
  for (size_t i = 0; i < objects.size(); ++i) {
    SCOPED_TRACE(i);
    int hits = 0, skipped = 0;
    expect_hits_inside_bounds(*objects[i], hits, skipped);
    EXPECT_GT(hits, 500);
    EXPECT_GT(skipped, 2000);
  }
}

TEST(SegmentCull, EmptyAndUnboundedScenes) {
  // An object that can never be hit (disjoint solids intersected): every chord is beyond its
  // empty bounds. Unknown bounds: none is.
  auto a = std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 1, 1});
  auto b = std::make_shared<Ellipsoid>(Vec3{5, 0, 0}, Vec3{1, 1, 1});
  const CsgObject nothing(CsgOp::Intersection, a, b);
  ASSERT_TRUE(nothing.bounds().empty());
  EXPECT_TRUE(SegmentCull(nothing).outside_bounds({0, 0, 0}, {5, 0, 0}));
  const Vec3 far{1e300, -1e300, 1e300};
  EXPECT_FALSE(SegmentCull().outside_bounds(far, far));
  // A NaN coordinate puts no chord beyond a face of its axis.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(SegmentCull(*a).outside_bounds({nan, 0, 0}, {5, 0, 0}));
  EXPECT_TRUE(SegmentCull(*a).outside_bounds({0, 5, 0}, {5, 5, 0}));
}

// ---- renders with and without skipping ----------------------------------------------------------

/// The colour tells where the hit was (any change of a hit changes the picture).
struct PositionShader : Shader {
  Color shade(const Hit& h, const ShadeContext&) const override {
    return {0.5 + 0.01 * h.point.x, 0.5 + 0.01 * h.point.y, 0.5 + 0.01 * h.point.z + 0.1 * h.object_id};
  }
};

/// The scene with no empty ball and unknown bounds: the tracer tests every step (and stops no ray
/// as escaped: the scenes here stop every ray before, at a hit, the horizon or the bounding box).
struct EveryStepTested final : SceneObject {
  explicit EveryStepTested(SceneObjectPtr s) : scene(std::move(s)) {}
  bool intersect(const Segment& seg, Hit& hit) const override { return scene->intersect(seg, hit); }
  Bounds3 bounds() const override { return Bounds3::infinite(); }
  double inner_radius() const override { return scene->inner_radius(); }
  void restrict_surface_free_radii(double* free, int n) const override {
    for (int c = 0; c < n; ++c) free[c] = 0;
  }
  SceneObjectPtr scene;
};

template <class T>
std::shared_ptr<T> shaded(std::shared_ptr<T> obj, const Shader& s, int id, int chart = 0) {
  obj->shader = &s;
  obj->object_id = id;
  obj->chart = chart;
  return obj;
}

/// A 72×32 panorama along −e_(1) of the observer of `kind` at radius r on the equator of metric
/// `name`, the rays' radial coordinate bounded to [r_min, 100], at most 5000 steps.
RenderJob equator_panorama_job(const char* name, double r, double r_min, TetradKind kind = TetradKind::Default) {
  auto metric = std::shared_ptr<const Metric>(make_metric(name));
  RenderJob job;
  job.metric = metric;
  job.observer.pos = Vec4{{0, r, kPi / 2, 0}};
  job.observer.e = metric->natural_tetrad(job.observer.pos, kind);
  job.camera = std::make_shared<PanoramaCamera>(Vec3{-1, 0, 0}, Vec3{0, 0, 1}, 360, 160, 72, 32);
  job.solver.box_ll = Vec4{{-1e300, r_min, -1e300, -1e300}};
  job.solver.box_ur = Vec4{{1e300, 100, 1e300, 1e300}};
  job.solver.max_steps = 5000;
  return job;
}

/// Renders `job` as it is and with every step tested: the same pixels, data and stop reasons, and
/// no more steps (the same, but for the rays that fall into a hole and are captured inside the
/// empty ball, Tracer's capture radius, capture.h).
void expect_same_render(RenderJob job, double expected_free_radius) {
  job.filter = Filter::RGBpdz;
  EXPECT_NEAR(Tracer(job).segment_cull().radius(0), expected_free_radius * (1 - SegmentCull::kMargin), 1e-10);
  RenderOptions opt;
  opt.progress = false;
  opt.threads = 1;
  const RenderResult skipping = render(job, opt);
  job.scene = std::make_shared<EveryStepTested>(job.scene);
  EXPECT_EQ(Tracer(job).segment_cull().radius(0), 0.0);
  EXPECT_EQ(Tracer(job).segment_cull().bounds().lo.x, -kInf);
  const RenderResult every = render(job, opt);
  ASSERT_EQ(skipping.data.size(), every.data.size());
  int differ = 0, hits = 0;
  for (int y = 0; y < every.image.height; ++y)
    for (int x = 0; x < every.image.width; ++x)
      for (int c = 0; c < 3; ++c) differ += skipping.image.at(x, y)[c] != every.image.at(x, y)[c];
  for (size_t i = 0; i < every.data.size(); ++i) {
    hits += every.data[i].hit;
    differ += skipping.data[i].object_id != every.data[i].object_id;
    differ += ray_stop(skipping.data[i]) != ray_stop(every.data[i]);
    for (int k = 0; k < 4; ++k) differ += skipping.data[i].pos[k] != every.data[i].pos[k];
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(hits, static_cast<int>(every.data.size()) / 2);
  EXPECT_LE(skipping.stats.steps, every.stats.steps);
}

TEST(SegmentCull, SchwarzschildSceneRendersTheSameWithAndWithoutSkipping) {
  // Static observer at r = 10 inside a background sphere of radius 40, with a box, a turned and
  // scaled ellipsoid (its bounds 11.97 away) and a CSG solid around it (a ball with a cavity; the
  // difference lies within the outer ball's bounds, 11 away).
  static PositionShader shader;
  RenderJob job = equator_panorama_job("Schwarzschild", 10, 0, TetradKind::Static);
  auto turned = shaded(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 3, 1}), shader, 3);
  turned->set_transform(rotate_scale(40, 1.5, {-16, 4, 2}));
  auto cut = std::make_shared<CsgObject>(CsgOp::Difference,
                                         shaded(std::make_shared<Ellipsoid>(Vec3{0, 14, 0}, Vec3{3, 3, 3}), shader, 4),
                                         shaded(std::make_shared<Ellipsoid>(Vec3{0, 12, 0}, Vec3{2, 2, 2}), shader, 5));
  job.scene = std::make_shared<CompoundObject>(std::vector<SceneObjectPtr>{
      shaded(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{40, 40, 40}), shader, 1),
      shaded(std::make_shared<Box>(Vec3{12, -2, -2}, Vec3{15, 2, 2}), shader, 2), turned, cut});
  expect_same_render(job, 11.0);
}

TEST(SegmentCull, MorrisThorneBothChartsRenderTheSameWithAndWithoutSkipping) {
  // The wormhole scene: an observer at l = 3 sees a sphere of radius 50 on each side of the
  // throat (chart 0: l > 0, chart 1: l <= 0).
  static PositionShader shader;
  RenderJob job = equator_panorama_job("MorrisThorne", 3, -100);
  job.scene = std::make_shared<CompoundObject>(std::vector<SceneObjectPtr>{
      shaded(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{50, 50, 50}), shader, 1, 0),
      shaded(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{50, 50, 50}), shader, 2, 1)});
  EXPECT_NEAR(Tracer(job).segment_cull().radius(1), 50 * (1 - SegmentCull::kMargin), 1e-10);
  expect_same_render(job, 50.0);
}

TEST(SegmentCull, EddingtonFinkelsteinInsideTheSkyRendersTheSameWithAndWithoutSkipping) {
  // fallEddFinkIn's setting: ingoing Eddington–Finkelstein coordinates, the observer at r = 10
  // inside a sky of radius 60, here with a ball at r = 20 beside it.
  static PositionShader shader;
  RenderJob job = equator_panorama_job("EddFinkIn", 10, 0);
  job.scene = std::make_shared<CompoundObject>(std::vector<SceneObjectPtr>{
      shaded(std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{60, 60, 60}), shader, 1),
      shaded(std::make_shared<Ellipsoid>(Vec3{0, 20, 0}, Vec3{2, 2, 2}), shader, 2)});
  expect_same_render(job, 18.0);
}

TEST(SegmentCull, KerrDiskRendersTheSameWithAndWithoutSkipping) {
  // kerrAccretionDisk's setting: Kerr in Mino time (the integrator hands the pseudo-Cartesian
  // ends over), a ring of radii 3 and 15 in the equatorial plane, seen from r = 18, 60° above it.
  // Its bounds are flat: only chords crossing the plane near the ring are tested. The rays are
  // bounded to r <= 20, inside the escape radius (the ring's bounding sphere, 15√2), so both
  // renders stop every ray at the same step.
  static PositionShader shader;
  RenderJob job = equator_panorama_job("KerrBL", 18, 0);
  job.observer.pos = Vec4{{0, 18, kPi / 6, 0}};
  job.observer.e = job.metric->natural_tetrad(job.observer.pos, TetradKind::Default);
  job.camera = std::make_shared<PanoramaCamera>(Vec3{-1, 0, 0}, Vec3{0, 0, 1}, 80, 80, 40, 40);
  job.solver.box_ur = Vec4{{1e300, 20, 1e300, 1e300}};
  job.scene = std::make_shared<CompoundObject>(
      std::vector<SceneObjectPtr>{shaded(std::make_shared<PlaneRing>(Vec3{0, 0, 0}, Vec3{0, 0, 1}, 3, 15), shader, 1)});
  EXPECT_NEAR(Tracer(job).segment_cull().bounds().hi.z, 15 * std::sqrt(2.0) * SegmentCull::kMargin, 1e-15);
  expect_same_render(job, 3.0);
}

TEST(SegmentCull, ChordsOfAPacketCulledAtOnceAsOneByOne) {
  // chart0_chords_skipped (all lanes at once) against inside_empty_ball || outside_bounds chord by
  // chord, and the next starts it writes (p1 and dot(p1, p1) on the lanes asked for, the old
  // starts on the others, to the bit), on random chords around kerrAccretionDisk's ring (a ball of
  // radius 3 and a flat box, so both tests decide), with ends on the ball's rim, on the box's
  // faces and with NaN coordinates.
  const SegmentCull cull(PlaneRing(Vec3{0, 0, 0}, Vec3{0, 0, 1}, 3, 15));
  const double rim = cull.radius(0), face = cull.bounds().hi.z;
  ASSERT_GT(rim, 2.9);
  ASSERT_GT(face, 0.0);
  ASSERT_LT(face, 1e-3);
  constexpr int W = kPacketLanes;
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  auto point = [&](int kind) {
    Vec3 p{u(rng), u(rng), u(rng)};
    switch (kind) {
      case 0: return 2.9 * p;                         // in the ball
      case 1: return rim / std::sqrt(dot(p, p)) * p;  // on its rim
      case 2: return Vec3{20 * p.x, 20 * p.y, face};  // on the box's top face
      case 3: return Vec3{20 * p.x, std::numeric_limits<double>::quiet_NaN(), 20 * p.z};
      default: return Vec3{20 * p.x, 20 * p.y, p.z < 0 ? -face - 1e-3 * p.z : face + 1e-3 * p.z};  // above or below
    }
  };
  auto same_bits = [](double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
  };
  int skipped_count = 0, tested_count = 0;
  for (int round = 0; round < 4000; ++round) {
    alignas(64) double p0[3][W], r0[W], p1[3][W], next_p[3][W], next_r0[W];
    Vec3 a[W], b[W];
    for (int l = 0; l < W; ++l) {
      a[l] = point(static_cast<int>(rng() % 6));
      b[l] = point(static_cast<int>(rng() % 6));
      for (int i = 0; i < 3; ++i) {
        p0[i][l] = a[l][i];
        p1[i][l] = b[l][i];
      }
      r0[l] = dot(a[l], a[l]);
    }
    const unsigned lanes = rng() & 0xffu;
    const unsigned skipped = cull.chart0_chords_skipped(lanes, p0[0], r0, p1[0], next_p[0], next_r0);
    for (int l = 0; l < W; ++l) {
      const bool on = lanes >> l & 1u;
      const double r1 = dot(b[l], b[l]);
      const bool skip = on && (cull.inside_empty_ball(0, r0[l], 0, r1) || cull.outside_bounds(a[l], b[l]));
      EXPECT_EQ((skipped >> l & 1u) != 0, skip) << "round " << round << " lane " << l;
      (skip ? skipped_count : tested_count) += on;
      EXPECT_TRUE(same_bits(next_r0[l], on ? r1 : r0[l]));
      for (int i = 0; i < 3; ++i) EXPECT_TRUE(same_bits(next_p[i][l], on ? b[l][i] : a[l][i]));
    }
  }
  // Both outcomes, often.
  EXPECT_GT(skipped_count, 2000);
  EXPECT_GT(tested_count, 2000);
}

}  // namespace segment_cull_test
}  // namespace geovis
