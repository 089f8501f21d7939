// A cube written as a Wavefront OBJ file behaves exactly like the equivalent solid-box.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "object_test_helpers.h"
#include "render/mesh.h"
#include "render/plugins.h"

namespace geovis {
namespace {

using testing::make_segment;

std::string write_cube(const std::string& dir) {
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/cube.obj";
  std::ofstream f(path);
  // Cube [−1,1]³, counter-clockwise faces seen from outside, with vt and vn (GeoViS needs both).
  f << "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
       "vn -1 0 0\nvn 1 0 0\nvn 0 -1 0\nvn 0 1 0\nvn 0 0 -1\nvn 0 0 1\n"
       "f 1/1/1 5/2/1 8/3/1 4/4/1\n"
       "f 2/1/2 3/2/2 7/3/2 6/4/2\n"
       "f 1/1/3 2/2/3 6/3/3 5/4/3\n"
       "f 4/1/4 8/2/4 7/3/4 3/4/4\n"
       "f 1/1/5 4/2/5 3/3/5 2/4/5\n"
       "f 5/1/6 6/2/6 7/3/6 8/4/6\n";
  return path;
}

TEST(ObjMesh, CubeEqualsBox) {
  const std::string dir = std::string(GEOVIS_BINARY_DIR) + "/test_mesh_tmp";
  write_cube(dir);
  BuildContext ctx;
  ctx.search_paths = {dir};
  ParamSet ps("mesh-obj", {});
  ps.add("filename", "cube.obj");
  auto mesh = make_object(ps, ctx);
  EXPECT_EQ(ctx.next_object_id(), 2);  // the mesh is one primitive: objID 1
  Box box({-1, -1, -1}, {1, 1, 1});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-4, 4);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const Segment seg = make_segment({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
    Hit hb, hm;
    const bool fb = box.intersect(seg, hb), fm = mesh->intersect(seg, hm);
    ASSERT_EQ(fb, fm) << k;
    if (!fb) continue;
    ++hits;
    EXPECT_NEAR(hm.s, hb.s, 1e-12) << k;
    EXPECT_NEAR(hm.normal.x, hb.normal.x, 1e-12);
    EXPECT_NEAR(hm.normal.y, hb.normal.y, 1e-12);
    EXPECT_NEAR(hm.normal.z, hb.normal.z, 1e-12);
    EXPECT_EQ(hm.object_id, 1);
  }
  EXPECT_GT(hits, 100);
}

TEST(ObjMesh, PathnameTransformAndMissingFile) {
  const std::string dir = std::string(GEOVIS_BINARY_DIR) + "/test_mesh_tmp2";
  write_cube(dir);
  BuildContext ctx;
  ParamSet ps("mesh-obj", {});
  ps.add("pathname", dir);
  ps.add("filename", "cube.obj");
  Transform t = Transform::identity(3);
  t(2, 3) = 5;
  ps.add("transform", t);
  auto mesh = make_object(ps, ctx);
  Hit h;
  ASSERT_TRUE(mesh->intersect(make_segment({0, 0, 10}, {0, 0, 0}), h));
  EXPECT_NEAR(h.s, 0.4, 1e-12);  // top face at z = 6
  ParamSet missing("mesh-obj", SourceLoc{"s.scm", 3});
  missing.add("filename", "nonexistent_mesh.obj");
  try {
    make_object(missing, ctx);
    FAIL();
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("s.scm:3: mesh-obj: filename"), std::string::npos) << msg;
    EXPECT_NE(msg.find("nonexistent_mesh.obj"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace geovis
