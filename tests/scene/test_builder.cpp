// Scene builder semantics (catalogue §1, §8-§10), on scenes written directly as command calls.
#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"
#include "render/camera.h"
#include "scene/builder.h"
#include "spacetime/tetrad.h"

namespace geovis {
namespace {

using KV = std::vector<std::pair<std::string, Value>>;

/// A scene written call by call; each call is on its own line of "scene.scm".
class SceneText {
 public:
  SceneText& add(const std::string& cmd, const KV& kv) {
    ParamSet ps(cmd, SourceLoc{"scene.scm", line_});
    for (const auto& [k, v] : kv) ps.add(k, v, SourceLoc{"scene.scm", line_});
    desc_.calls.push_back(CommandCall{cmd, ps});
    ++line_;
    return *this;
  }
  int line() const { return line_; }
  SceneDescription desc() const { return desc_; }

 private:
  SceneDescription desc_{"scene.scm", ".", {}};
  int line_ = 1;
};

Value vec(std::vector<double> v) { return Value(std::move(v)); }
Value setparam(const std::string& id, const std::string& param, Value v) {
  return Value(ValueList{Value(id), Value(param), std::move(v)});
}

/// Minkowski scene with one observer, two cameras (cam1 8x6, cam2 10x4) and a sphere.
SceneText minkowski_base() {
  SceneText s;
  s.add("init-metric", {{"type", "Minkowski"}, {"id", "metric"}})
      .add("init-solver", {{"type", "GSL_RK_Cash-Karp"}, {"geodtype", "lightlike"}, {"id", "raytracing"}})
      .add("init-camera", {{"type", "PinHoleCam"}, {"res", vec({8, 6})}, {"fov", vec({40, 30})}, {"id", "cam1"}})
      .add("init-camera", {{"type", "PinHoleCam"}, {"res", vec({10, 4})}, {"id", "cam2"}})
      .add("init-raygen", {{"type", "RayGenSimple"},
                           {"solver", "raytracing"},
                           {"maxnumpoints", 1234},
                           {"boundboxll", vec({-1e19, -20, -20, -20})},
                           {"boundboxur", vec({1e19, 20, 20, 20})}})
      .add("local-tetrad", {{"pos", vec({0, -10, 0, 0})},
                            {"e0", vec({1, 0, 0, 0})},
                            {"e1", vec({0, 1, 0, 0})},
                            {"e2", vec({0, 0, 1, 0})},
                            {"e3", vec({0, 0, 0, 1})},
                            {"incoords", true},
                            {"id", "locTedObs"}})
      .add("init-projector", {{"localtetrad", "locTedObs"}, {"color", vec({0.1, 0.2, 0.3})}, {"id", "proj"}})
      .add("init-light-mgr", {{"ambient", vec({1, 1, 1})}, {"id", "lights"}})
      .add("init-texture", {{"type", "UniTex"}, {"color", vec({0.8, 0.1, 0.1})}, {"id", "red"}})
      .add("init-shader", {{"type", "SurfShader"}, {"objcolor", "red"}, {"id", "redShader"}})
      .add("solid-ellipsoid", {{"objtype", 1},
                               {"center", vec({0, 0, 0})},
                               {"axlen", vec({1, 1, 1})},
                               {"shader", "redShader"},
                               {"id", "ball"}})
      .add("solid-ellipsoid", {{"objtype", 1},
                               {"center", vec({0, 3, 0})},
                               {"axlen", vec({1, 1, 1})},
                               {"shader", "redShader"},
                               {"id", "ball2"}});
  return s;
}

std::string error_of(const SceneText& s, int device = 0) {
  try {
    SceneBuilder b(s.desc(), {});
    b.build(device);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SceneBuilder, LastDefinedIsTheDefault) {
  SceneText s = minkowski_base();
  s.add("init-device", {{"type", "standard"}})                                           // device 0: defaults
      .add("init-device", {{"type", "standard"}, {"camera", "cam1"}, {"obj", "ball"}});  // device 1
  SceneBuilder b(s.desc(), {});
  ASSERT_EQ(b.device_count(), 2);
  const auto j0 = b.build(0);
  ASSERT_EQ(j0.size(), 1u);
  EXPECT_EQ(j0[0].job.camera->width(), 10);  // cam2, the last camera defined
  EXPECT_EQ(j0[0].job.scene->id, "ball2");   // the last object created is the scene graph
  const auto j1 = b.build(1);
  EXPECT_EQ(j1[0].job.camera->width(), 8);
  EXPECT_EQ(j1[0].job.scene->id, "ball");
  // Projector colour, observer position and the raygen's limits reach the job.
  EXPECT_DOUBLE_EQ(j0[0].job.background.b, 0.3);
  EXPECT_DOUBLE_EQ(j0[0].job.observer.pos[1], -10.0);
  EXPECT_EQ(j0[0].job.solver.max_steps, 1234);
  EXPECT_EQ(j0[0].job.solver.type, GeodesicType::Lightlike);
  EXPECT_DOUBLE_EQ(j0[0].job.solver.box_ur[1], 20.0);
  EXPECT_EQ(j0[0].job.metric->name(), "Minkowski");
  EXPECT_TRUE(j0[0].job.solver.separable);  // geovis extension, default on
}

TEST(SceneBuilder, SeparableSolverKeySwitchesToTheCoordinateEquations) {
  SceneText s = minkowski_base();
  s.add("init-solver", {{"type", "GSL_RK_Cash-Karp"}, {"separable", false}, {"id", "coordSolver"}})
      .add("init-raygen", {{"type", "RayGenSimple"}, {"solver", "coordSolver"}, {"id", "rg2"}})
      .add("init-projector", {{"localtetrad", "locTedObs"}, {"id", "proj2"}})  // takes the last raygen
      .add("init-device", {{"type", "standard"}});
  SceneBuilder b(s.desc(), {});
  EXPECT_FALSE(b.build(0)[0].job.solver.separable);
}

TEST(SceneBuilder, RungeKuttaNystromNeedsSeparableEquations) {
  // RKN86 integrates y'' = f(y) only: in Minkowski the scene is refused at build time, naming the
  // solver's command and key.
  SceneText s = minkowski_base();
  s.add("init-solver", {{"type", "RKN86"}, {"id", "rkn"}})
      .add("init-raygen", {{"type", "RayGenSimple"}, {"solver", "rkn"}, {"id", "rg2"}})
      .add("init-projector", {{"localtetrad", "locTedObs"}, {"id", "proj2"}})
      .add("init-device", {{"type", "standard"}});
  const std::string e = error_of(s);
  EXPECT_NE(e.find("init-solver: type: RKN86"), std::string::npos) << e;
  EXPECT_NE(e.find("Minkowski"), std::string::npos) << e;
}

TEST(SceneBuilder, LastMetricIsTheDefault) {
  SceneText s = minkowski_base();
  s.add("init-metric", {{"type", "Schwarzschild"}, {"mass", 0.5}, {"id", "bh"}})
      .add("local-tetrad", {{"pos", vec({0, 30, M_PI / 2, 0})}, {"id", "obsBH"}})
      .add("init-projector", {{"localtetrad", "obsBH"}, {"id", "projBH"}})
      .add("init-device", {{"type", "standard"}})
      .add("init-device", {{"type", "standard"}, {"metric", "metric"}, {"projector", "proj"}});
  SceneBuilder b(s.desc(), {});
  const auto j0 = b.build(0);
  EXPECT_EQ(j0[0].job.metric->name(), "Schwarzschild");
  EXPECT_DOUBLE_EQ(j0[0].job.metric->param("mass"), 0.5);
  // Static observer of Schwarzschild (incoords #f, default frame): e_(0) = ∂_t / sqrt(1 - 2M/r)
  // (paper eq. 2).
  EXPECT_NEAR(j0[0].job.observer.e[0][0], 1.0 / std::sqrt(1.0 - 1.0 / 30.0), 1e-12);
  EXPECT_EQ(b.build(1)[0].job.metric->name(), "Minkowski");
}

/// `horizon_eps` (the horizon break margin, Metric::horizon_eps) is a key of every init-metric.
TEST(SceneBuilder, HorizonEpsIsAMetricKey) {
  SceneText s = minkowski_base();
  s.add("init-metric", {{"type", "Schwarzschild"}, {"horizon_eps", 0.01}, {"id", "bh"}})
      .add("local-tetrad", {{"pos", vec({0, 30, M_PI / 2, 0})}, {"id", "obsBH"}})
      .add("init-projector", {{"localtetrad", "obsBH"}, {"id", "projBH"}})
      .add("init-device", {{"type", "standard"}});
  SceneBuilder b(s.desc(), {});
  const auto j0 = b.build(0);
  EXPECT_DOUBLE_EQ(j0[0].job.metric->horizon_eps(), 0.01);
  EXPECT_FALSE(j0[0].job.metric->is_valid(Vec4{{0, 2.019, M_PI / 2, 0}}));
  SceneText bad = minkowski_base();
  bad.add("init-metric", {{"type", "Schwarzschild"}, {"horizon_eps", 0.5}}).add("init-device", {});
  const std::string e = error_of(bad);
  EXPECT_NE(e.find("horizon_eps = 0.5 is out of range"), std::string::npos) << e;
}

TEST(SceneBuilder, SetparamChangesOnlyItsFrame) {
  SceneText s = minkowski_base();
  s.add("init-device", {{"setparam", setparam("locTedObs", "time", 5.0)},
                        {"setparam", setparam("locTedObs", "pos", vec({1, -8, 0, 0}))},
                        {"setparam", setparam("cam1", "fov", vec({20, 15}))}})
      .add("init-device", {{"camera", "cam1"}})
      .add("init-device",
           {{"setparam", setparam("proj", "actualpos", 0)}, {"setparam", setparam("locTedObs", "time", 7.0)}});
  SceneBuilder b(s.desc(), {});
  // Frame 0: "time" then "pos" (later entries win, in order) -> pos = (1, -8, 0, 0).
  const auto j0 = b.build(0);
  EXPECT_DOUBLE_EQ(j0[0].job.observer.pos[0], 1.0);
  EXPECT_DOUBLE_EQ(j0[0].job.observer.pos[1], -8.0);
  // Frame 1: untouched.
  const auto j1 = b.build(1);
  EXPECT_DOUBLE_EQ(j1[0].job.observer.pos[0], 0.0);
  EXPECT_DOUBLE_EQ(j1[0].job.observer.pos[1], -10.0);
  // Frame 2: only the time coordinate changes.
  const auto j2 = b.build(2);
  EXPECT_DOUBLE_EQ(j2[0].job.observer.pos[0], 7.0);
  EXPECT_DOUBLE_EQ(j2[0].job.observer.pos[1], -10.0);
  // Building frames again (out of order, cache warm) gives the same result.
  EXPECT_DOUBLE_EQ(b.build(0)[0].job.observer.pos[1], -8.0);
  EXPECT_DOUBLE_EQ(b.build(1)[0].job.observer.pos[1], -10.0);
}

TEST(SceneBuilder, SetparamOnMetricParameters) {
  SceneText s;
  s.add("init-metric", {{"type", "Schwarzschild"}, {"mass", 1.0}, {"id", "metric"}})
      .add("init-solver", {{"type", "RK4"}, {"id", "raytracing"}})
      .add("init-camera", {{"type", "PinHoleCam"}, {"res", vec({4, 4})}})
      .add("init-raygen", {{"type", "RayGenSimple"}})
      .add("local-tetrad", {{"pos", vec({0, 20, M_PI / 2, 0})}, {"id", "obs"}})
      .add("init-projector", {{"localtetrad", "obs"}})
      .add("init-light-mgr", {{"ambient", vec({1, 1, 1})}})
      .add("init-texture", {{"type", "UniTex"}, {"color", vec({1, 1, 1})}, {"id", "white"}})
      .add("init-shader", {{"type", "SurfShader"}, {"objcolor", "white"}, {"id", "sh"}})
      .add("solid-ellipsoid", {{"objtype", 1}, {"axlen", vec({40, 40, 40})}, {"shader", "sh"}, {"id", "sky"}});
  for (int i = 0; i < 3; ++i) s.add("init-device", {{"setparam", setparam("metric", "mass", 1.0 + i)}});
  SceneBuilder b(s.desc(), {});
  for (int i = 0; i < 3; ++i) {
    const auto j = b.build(i);
    EXPECT_DOUBLE_EQ(j[0].job.metric->param("mass"), 1.0 + i);
    // The observer's static tetrad follows the changed mass: g_tt e0^t e0^t = -1 with
    // g_tt = -(1 - 2M/r).
    const double f = 1.0 - 2.0 * (1.0 + i) / 20.0;
    EXPECT_NEAR(j[0].job.observer.e[0][0], 1.0 / std::sqrt(f), 1e-12);
  }
}

TEST(SceneBuilder, SetParameterIsImmediate) {
  SceneText s = minkowski_base();
  s.add("init-device", {})  // before the change: keeps the old position
      .add("set-parameter", {{"id", "locTedObs"}, {"pos", vec({0, -12, 0, 0})}})
      .add("set-parameter", {{"id", "cam2"}, {"fov", vec({30, 10})}})
      .add("init-device", {});
  SceneBuilder b(s.desc(), {});
  EXPECT_DOUBLE_EQ(b.build(0)[0].job.observer.pos[1], -10.0);
  EXPECT_DOUBLE_EQ(b.build(1)[0].job.observer.pos[1], -12.0);
}

TEST(SceneBuilder, AddObjectAppendsToACompound) {
  SceneText s = minkowski_base();
  s.add("comp-object", {{"obj", "ball"}, {"id", "scene"}})
      .add("solid-ellipsoid", {{"objtype", 1},
                               {"center", vec({0, 0, 3})},
                               {"axlen", vec({1, 1, 1})},
                               {"shader", "redShader"},
                               {"id", "ball3"}})
      .add("add-object", {{"add-to", "scene"}, {"obj", "ball2"}, {"obj", "ball3"}})
      .add("init-device", {{"obj", "scene"}});
  SceneBuilder b(s.desc(), {});
  const auto j = b.build(0);
  ASSERT_TRUE(j[0].job.scene);
  // The compound's bounds cover all three unit balls: centres (0,0,0), (0,3,0), (0,0,3).
  const Bounds3 bb = j[0].job.scene->bounds();
  EXPECT_NEAR(bb.hi.y, 4.0, 1e-9);
  EXPECT_NEAR(bb.hi.z, 4.0, 1e-9);
  EXPECT_NEAR(bb.lo.x, -1.0, 1e-9);
  EXPECT_NE(b.summary().find("comp-object"), std::string::npos);
}

TEST(SceneBuilder, StereoCameraGivesTwoJobs) {
  SceneText s = minkowski_base();
  s.add("init-camera", {{"type", "PinHoleStereoCam"}, {"res", vec({6, 4})}, {"sep", 0.2}, {"id", "stereo"}})
      .add("init-device", {});
  SceneBuilder b(s.desc(), {});
  const auto j = b.build(0);
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[0].eye, "left");
  EXPECT_EQ(j[1].eye, "right");
  // The eyes sit symmetrically about the projector, `sep` apart (flat space, tetrad = coordinate
  // axes, so the offsets are coordinate offsets).
  double dist2 = 0;
  for (int mu = 0; mu < 4; ++mu) {
    EXPECT_NEAR(0.5 * (j[0].job.observer.pos[mu] + j[1].job.observer.pos[mu]), (mu == 1 ? -10.0 : 0.0), 1e-12);
    const double d = j[0].job.observer.pos[mu] - j[1].job.observer.pos[mu];
    dist2 += d * d;
  }
  EXPECT_NEAR(std::sqrt(dist2), 0.2, 1e-12);
}

TEST(SceneBuilder, ResolutionOverrideAndSupersample) {
  SceneText s = minkowski_base();
  s.add("init-device", {{"camera", "cam1"}});
  BuildOptions o;
  o.resolution = std::pair<int, int>{16, 12};
  o.supersample = 3;
  SceneBuilder b(s.desc(), o);
  const auto j = b.build(0);
  EXPECT_EQ(j[0].job.camera->width(), 16);
  EXPECT_EQ(j[0].job.camera->height(), 12);
  EXPECT_EQ(j[0].job.supersample, 3);
}

TEST(SceneBuilder, FilterDataFiles) {
  SceneText s = minkowski_base();
  s.add("init-camera", {{"type", "PinHoleCam"}, {"res", vec({4, 4})}, {"filter", "FilterRGBpdz"}, {"id", "c3"}})
      .add("init-device", {});
  SceneBuilder b(s.desc(), {});
  const auto j = b.build(0);
  EXPECT_EQ(j[0].job.filter, Filter::RGBpdz);
  ASSERT_EQ(j[0].data_files_wanted.size(), 1u);
  EXPECT_EQ(j[0].data_files_wanted[0], ".pdz");
}

TEST(SceneBuilder, UnknownIdsSuggestTheClosest) {
  SceneText s = minkowski_base();
  const int line = s.line();
  s.add("init-device", {{"camera", "cam3"}});
  const std::string e = error_of(s);
  EXPECT_NE(e.find("scene.scm:" + std::to_string(line) + ": init-device: camera: unknown camera id \"cam3\""),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("did you mean"), std::string::npos) << e;

  SceneText s2 = minkowski_base();
  s2.add("init-device", {{"setparam", setparam("locTedObz", "time", 1.0)}});
  try {
    SceneBuilder b(s2.desc(), {});
    FAIL() << "expected an error";
  } catch (const SceneError& err) {
    const std::string m = err.what();
    EXPECT_NE(m.find("init-device: setparam: unknown object id \"locTedObz\"; did you mean \"locTedObs\"?"),
              std::string::npos)
        << m;
  }

  SceneText s3 = minkowski_base();
  s3.add("init-device", {{"setparam", setparam("locTedObs", "tme", 1.0)}});
  try {
    SceneBuilder b(s3.desc(), {});
    FAIL() << "expected an error";
  } catch (const SceneError& err) {
    EXPECT_NE(std::string(err.what()).find("did you mean \"time\"?"), std::string::npos) << err.what();
  }

  SceneText s4 = minkowski_base();
  s4.add("init-shader", {{"type", "SurfShader"}, {"objcolor", "redd"}, {"id", "bad"}}).add("init-device", {});
  const std::string e4 = error_of(s4);
  EXPECT_NE(e4.find("init-shader: objcolor: unknown texture id \"redd\"; did you mean \"red\"?"), std::string::npos)
      << e4;

  // A reference to an existing id of the wrong kind.
  SceneText s5 = minkowski_base();
  s5.add("init-device", {{"camera", "proj"}});
  EXPECT_NE(error_of(s5).find("\"proj\" is a projector"), std::string::npos) << error_of(s5);
}

TEST(SceneBuilder, BadCallsAreErrorsWithLocation) {
  SceneText s = minkowski_base();
  const int line = s.line();
  s.add("solid-ellipsoid", {{"objtype", 1}, {"axlen", vec({1, 1, 1})}, {"shader", "redShader"}, {"id", "ball"}});
  try {
    SceneBuilder b(s.desc(), {});
    FAIL() << "duplicate id accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.scm:" + std::to_string(line) +
                                         ": solid-ellipsoid: id: id \"ball\" is already used"),
              std::string::npos)
        << e.what();
  }
  SceneText m;
  m.add("init-metric", {{"type", "Schwarzschild"}, {"mas", 2.0}}).add("init-device", {});
  const std::string e = error_of(m);
  EXPECT_NE(e.find("scene.scm:1: init-metric: mas:"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean \"mass\""), std::string::npos) << e;

  SceneText t;
  t.add("init-metric", {{"type", "Schwarzshild"}});
  t.add("init-device", {});
  EXPECT_NE(error_of(t).find("did you mean \"Schwarzschild\""), std::string::npos) << error_of(t);

  SceneText none;
  none.add("init-metric", {{"type", "Minkowski"}}).add("init-device", {});
  EXPECT_NE(error_of(none).find("no scene object is defined before this command"), std::string::npos) << error_of(none);

  SceneText cmd;
  cmd.add("init-devise", {});
  try {
    SceneBuilder b(cmd.desc(), {});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean \"init-device\""), std::string::npos) << e.what();
  }
}

TEST(SceneBuilder, ObserverInsideTheHorizonIsAnError) {
  SceneText s;
  s.add("init-metric", {{"type", "Schwarzschild"}, {"mass", 1.0}})
      .add("init-solver", {{"type", "RK4"}})
      .add("init-camera", {{"type", "PinHoleCam"}, {"res", vec({4, 4})}})
      .add("init-raygen", {{"type", "RayGenSimple"}})
      .add("local-tetrad", {{"pos", vec({0, 20, M_PI / 2, 0})}, {"id", "obs"}})
      .add("init-projector", {{"localtetrad", "obs"}})
      .add("init-light-mgr", {})
      .add("init-texture", {{"type", "UniTex"}, {"color", vec({1, 1, 1})}, {"id", "white"}})
      .add("init-shader", {{"type", "SurfShader"}, {"objcolor", "white"}, {"id", "sh"}})
      .add("solid-ellipsoid", {{"objtype", 1}, {"axlen", vec({40, 40, 40})}, {"shader", "sh"}})
      .add("init-device", {{"setparam", setparam("obs", "pos", vec({0, 1.5, M_PI / 2, 0}))}});
  const std::string e = error_of(s);
  EXPECT_NE(e.find("local-tetrad"), std::string::npos) << e;
  EXPECT_NE(e.find("pos"), std::string::npos) << e;
}

TEST(SceneBuilder, DeviceIndexOutOfRange) {
  SceneText s = minkowski_base();
  s.add("init-device", {});
  SceneBuilder b(s.desc(), {});
  EXPECT_THROW(b.build(1), Error);
  EXPECT_THROW(b.build(-1), Error);
}

TEST(SceneBuilder, SetChangeObjAddsToADevice) {
  SceneText s = minkowski_base();
  s.add("init-device", {{"id", "dev0"}})
      .add("set-changeobj", {{"device", "dev0"}, {"setparam", setparam("locTedObs", "time", 3.0)}});
  SceneBuilder b(s.desc(), {});
  EXPECT_DOUBLE_EQ(b.build(0)[0].job.observer.pos[0], 3.0);

  SceneText bad = minkowski_base();
  bad.add("init-device", {{"id", "dev0"}}).add("set-changeobj", {{"device", "dev1"}});
  EXPECT_NE(error_of(bad).find("did you mean \"dev0\""), std::string::npos) << error_of(bad);
}

TEST(SceneBuilder, ObjectIdsFollowCreationOrder) {
  // GeoViS numbers primitives 1, 2, ... in creation order, also when frames are rebuilt from the
  // cache and when a compound lists them in another order.
  SceneText s = minkowski_base();
  s.add("comp-object", {{"obj", "ball2"}, {"obj", "ball"}, {"id", "scene"}});
  s.add("init-device", {{"obj", "scene"}, {"setparam", setparam("ball2", "axlen", vec({2, 2, 2}))}});
  s.add("init-device", {{"obj", "scene"}});
  SceneBuilder b(s.desc(), {});
  for (int d : {0, 1, 0}) {
    const auto j = b.build(d);
    // A ray along +y from the observer (y = -10) hits "ball" (objID 1) first.
    Segment seg;
    seg.x0 = Vec4{{0, 0, -10, 0}};
    seg.x1 = Vec4{{10, 0, 0, 0}};
    seg.p0 = Vec3{0, -10, 0};
    seg.p1 = Vec3{0, 0, 0};
    seg.metric = j[0].job.metric.get();
    Hit hit;
    ASSERT_TRUE(j[0].job.scene->intersect(seg, hit));
    EXPECT_EQ(hit.object_id, 1) << "device " << d;
  }
}

TEST(SceneBuilder, CalcRayInMinkowskiIsAStraightLine) {
  const std::string file = (std::filesystem::temp_directory_path() / "geovis_test_calc_ray.txt").string();
  SceneText s = minkowski_base();
  // dir = (ksi, chi) = (90, 90) deg: local direction (cos ksi sin chi, sin ksi sin chi, cos chi)
  // = e_(2) = +y; the ray is past-directed: k = -e0 + e2.
  s.add("calc-ray",
        {{"filename", file}, {"locted", "locTedObs"}, {"pos", vec({0, -10, 0, 0})}, {"dir", vec({90, 90})}});
  BuildOptions bopts;  // the file goes to the output folder
  bopts.output_dir = std::filesystem::temp_directory_path().string();
  SceneBuilder b(s.desc(), bopts);
  std::ostringstream log;
  b.run_actions(log);
  std::ifstream in(file);
  double t, x, y, z;
  int n = 0;
  while (in >> t >> x >> y >> z) {
    // Null straight line through (0, -10, 0, 0) with direction (-1, 0, 1, 0).
    EXPECT_NEAR(x, -10.0, 1e-9);
    EXPECT_NEAR(z, 0.0, 1e-9);
    EXPECT_NEAR(t, -y, 1e-9);
    ++n;
  }
  EXPECT_GT(n, 2);
  // It stops at the raygen's bounding box |y| <= 20 (first point beyond it included).
  EXPECT_GT(y, 19.0);
  std::filesystem::remove(file);
}

TEST(SceneBuilder, CalcRayWriteErrorsKeepTheOldFileAndSayWhy) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "geovis_test_calc_ray_errors";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto run_calc_ray = [&dir](const std::string& file) {
    SceneText s = minkowski_base();
    s.add("calc-ray",
          {{"filename", file}, {"locted", "locTedObs"}, {"pos", vec({0, -10, 0, 0})}, {"dir", vec({90, 90})}});
    BuildOptions bopts;
    bopts.output_dir = dir.string();  // sandboxed scenes write only below the output folder
    SceneBuilder b(s.desc(), bopts);
    std::ostringstream log;
    b.run_actions(log);
  };
  const std::string missing = (dir / "no-such-folder" / "ray.txt").string();
  try {
    run_calc_ray(missing);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("\"" + missing + "\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
  // A disk that fills up while writing: the old file stays as it was.
  const std::string file = (dir / "ray.txt").string();
  write_file_atomic(file, "old ray\n");
  fail_writes_at_byte_for_testing(10, ENOSPC);
  std::string message;
  try {
    run_calc_ray(file);
  } catch (const SceneError& e) {
    message = e.what();
  }
  fail_writes_at_byte_for_testing(-1, 0);
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "old ray");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
  std::filesystem::remove_all(dir);
}

TEST(SceneBuilder, GvsPrintListsTheParameters) {
  SceneText s = minkowski_base();
  s.add("gvs-print", {{"id", "cam1"}});
  SceneBuilder b(s.desc(), {});
  std::ostringstream log;
  b.run_actions(log);
  EXPECT_NE(log.str().find("init-camera \"cam1\""), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("res"), std::string::npos);
}

}  // namespace
}  // namespace geovis
