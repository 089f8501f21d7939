// The recorded ray of one pixel (render/ray_path.h) against flat space, where the ray is the
// straight line x(λ) = x_obs + λ(−1, d) for the past-directed k = −e_(0) + d (paper eq. 7, identity
// tetrad) and the first hit on a sphere is the closest root of |p − c| = R.
#include <gtest/gtest.h>

#include <cmath>

#include "render/build_context.h"
#include "render/pinhole_camera.h"
#include "render/plugins.h"
#include "render/ray_path.h"
#include "spacetime/metric_registry.h"

namespace geovis {
namespace {

struct WhiteShader : Shader {
  Color shade(const Hit&, const ShadeContext&) const override { return {1, 1, 1}; }
};

Tetrad identity_tetrad() {
  Tetrad e{};
  for (int a = 0; a < 4; ++a) e[a][a] = 1.0;
  return e;
}

/// A GeoViS solid-ellipsoid (render/plugins.h) of radius R at c.
SceneObjectPtr make_sphere(BuildContext& ctx, const Vec3& c, double R) {
  ctx.shaders["white"] = std::make_shared<WhiteShader>();
  ParamSet ps("solid-ellipsoid", {});
  ps.add("objtype", 1);
  ps.add("center", std::vector<double>{c.x, c.y, c.z});
  ps.add("axlen", std::vector<double>{R, R, R});
  ps.add("shader", "white");
  ps.add("id", "sphere");
  return make_object(ps, ctx);
}

RenderJob flat_job(BuildContext& ctx, Diagnostics& diag) {
  auto metric = std::shared_ptr<const Metric>(make_metric("Minkowski"));
  ctx.diag = &diag;
  ctx.metric = metric;
  RenderJob job;
  job.metric = metric;
  job.observer.pos = Vec4{{0, 1, 2, 3}};
  job.observer.e = identity_tetrad();
  job.camera = std::make_shared<PinholeCamera>(Vec3{1, 0, 0}, Vec3{0, 0, 1}, 40, 30, 40, 30);
  job.scene = make_sphere(ctx, Vec3{21, 2, 3}, 4);
  job.solver.box_ll = Vec4{{-1e300, -100, -100, -100}};
  job.solver.box_ur = Vec4{{1e300, 100, 100, 100}};
  return job;
}

TEST(RayPath, FlatSpaceRayIsTheStraightLineToTheFirstHit) {
  BuildContext ctx;
  Diagnostics diag;
  const RenderJob job = flat_job(ctx, diag);
  for (auto [px, py] : {std::pair{20.5, 15.5}, std::pair{23.5, 12.5}, std::pair{0.5, 0.5}}) {
    SCOPED_TRACE(std::to_string(px) + "," + std::to_string(py));
    const RayPath path = trace_ray_path(job, px, py);
    ASSERT_TRUE(path.traced);
    Vec3 d;
    ASSERT_TRUE(job.camera->direction(px, py, d));
    d = normalize(d);
    EXPECT_NEAR(norm(path.local_dir - d), 0.0, 1e-15);
    // The identity tetrad is the natural one of Minkowski: same direction, scale 1.
    EXPECT_NEAR(norm(path.natural_dir - d), 0.0, 1e-15);
    EXPECT_NEAR(path.natural_scale, 1.0, 1e-15);
    ASSERT_GE(path.points.size(), 2u);
    EXPECT_EQ(path.points.front().lambda, 0.0);
    for (const RayPoint& p : path.points) {
      const Vec3 expect = Vec3{1, 2, 3} + p.lambda * d;
      EXPECT_NEAR(norm(p.p - expect), 0.0, 1e-9 * (1 + p.lambda));
      EXPECT_NEAR(p.x[0], -p.lambda, 1e-9 * (1 + p.lambda));  // backwards in time, t = −λ
    }
    for (size_t i = 1; i < path.points.size(); ++i) EXPECT_GT(path.points[i].lambda, path.points[i - 1].lambda);
    // First hit: smallest λ with |o + λd − c| = R, o − c = (−20, 0, 0).
    const Vec3 oc{-20, 0, 0};
    const double b = dot(oc, d), disc = b * b - (dot(oc, oc) - 16);
    if (disc > 0) {
      ASSERT_TRUE(path.result.hit);
      EXPECT_NEAR(path.points.back().lambda, -b - std::sqrt(disc), 1e-8);
      EXPECT_NEAR(norm(path.points.back().p - (Vec3{1, 2, 3} + (-b - std::sqrt(disc)) * d)), 0.0, 1e-8);
    } else {
      EXPECT_FALSE(path.result.hit);
    }
  }
}

}  // namespace
}  // namespace geovis
