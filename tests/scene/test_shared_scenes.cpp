// The six real GeoViS scenes (tests/data/geovis/scenes) evaluate to the expected command calls. Expected
// values are computed here from the scenes' own formulas (e.g. t = t_start + count * t_step), not
// taken from an earlier run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <string>

#include "scene/scheme.h"

namespace geovis {
namespace {

const std::string kScenes = std::string(GEOVIS_TEST_DATA_DIR) + "/geovis/scenes/";
constexpr double kDegToRad = 0.017453292519943295770;  // init.scm DEG_TO_RAD

SceneDescription eval_shared(const std::string& name) {
  // kastorTraschen.scm and morristhorne.scm build texture paths from $HOME.
  setenv("HOME", "/home/tester", 0);
  return evaluate_scene_file(kScenes + name);
}

std::vector<const CommandCall*> calls_of(const SceneDescription& d, const std::string& command) {
  std::vector<const CommandCall*> out;
  for (const auto& c : d.calls)
    if (c.command == command) out.push_back(&c);
  return out;
}

const CommandCall* by_id(const SceneDescription& d, const std::string& id) {
  for (const auto& c : d.calls)
    if (c.params.get_string("id", "") == id) return &c;
  return nullptr;
}

// The single setparam ("obj" "param" value) of a device.
const ValueList& setparam(const CommandCall& c) {
  const Param* p = c.params.find("setparam");
  EXPECT_NE(p, nullptr);
  return std::get<ValueList>(p->value.v);
}

TEST(SharedScenes, SphereAroundBlackholeHas301FramesAtTstartPlusCountTimesTstep) {
  const SceneDescription d = eval_shared("sphereAroundBlackhole.scm");
  const auto devices = calls_of(d, "init-device");
  ASSERT_EQ(devices.size(), 301u);
  for (size_t count = 0; count < devices.size(); ++count) {
    const ValueList& sp = setparam(*devices[count]);
    ASSERT_EQ(sp.size(), 3u);
    EXPECT_EQ(std::get<std::string>(sp[0].v), "locTedObs");
    EXPECT_EQ(std::get<std::string>(sp[1].v), "time");
    EXPECT_DOUBLE_EQ(std::get<double>(sp[2].v), 27.89182 + 0.307812 * static_cast<double>(count));
    EXPECT_EQ(devices[count]->params.get_string("obj"), "lco1");
  }
  // fview = 2.5 (the second define wins), used through `(fov ,(vector fview fview)).
  const CommandCall* cam = by_id(d, "cam1");
  ASSERT_NE(cam, nullptr);
  EXPECT_EQ(cam->params.get_vector("fov", 2), (std::vector<double>{2.5, 2.5}));
  // Observer at r_obs = 30, theta = incl * DEG_TO_RAD.
  const CommandCall* obs = by_id(d, "locTedObs");
  ASSERT_NE(obs, nullptr);
  EXPECT_EQ(obs->params.get_vector("pos", 4), (std::vector<double>{0.0, 30.0, 90.0 * kDegToRad, 0.0}));
  // The motion's local velocity (0 0 lvel).
  EXPECT_EQ(by_id(d, "motion")->params.get_vector("localvel", 3), (std::vector<double>{0, 0, 0.5}));
  // objtype ,gpObjTypeLocal
  EXPECT_EQ(by_id(d, "sphere")->params.get_number("objtype"), 0.0);
}

TEST(SharedScenes, SphereAroundBlackholeKeysAreLowerCaseAndIdsGenerated) {
  const SceneDescription d = eval_shared("sphereAroundBlackhole.scm");
  const auto raygens = calls_of(d, "init-raygen");
  ASSERT_EQ(raygens.size(), 1u);
  const ParamSet& rg = raygens[0]->params;
  // '(boundBoxLL ...) and '(maxNumPoints 3000) arrive lower-cased.
  std::vector<std::string> keys;
  for (const auto& p : rg.entries()) keys.push_back(p.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"type", "boundboxll", "boundboxur", "solver", "maxnumpoints", "id"}));
  EXPECT_EQ(rg.get_vector("boundboxll", 4),
            (std::vector<double>{-1.844674407370955616e19, 0.0, -1.844674407370955616e19, -1.844674407370955616e19}));
  EXPECT_EQ(rg.get_vector("boundboxur", 4)[1], 50.0);
  // No id was given: a generated "unknownN", unique.
  EXPECT_EQ(rg.get_string("id").rfind("unknown", 0), 0u);
  // The checker texture created inside `(objcolor ,(init-texture ...)) is referenced by its id.
  const CommandCall* shader = by_id(d, "sphereShader");
  ASSERT_NE(shader, nullptr);
  const std::string tex_id = shader->params.get_string("objcolor");
  const CommandCall* tex = by_id(d, tex_id);
  ASSERT_NE(tex, nullptr);
  EXPECT_EQ(tex->command, "init-texture");
  EXPECT_EQ(tex->params.get_string("type"), "CheckerT2D");
  EXPECT_EQ(tex->params.get_strings("texture"), (std::vector<std::string>{"utex1", "utex2"}));
  // `(transform ,(scale-obj #(20.0 10.0))): a 2D scale matrix.
  const Transform t = tex->params.get_transform("transform");
  EXPECT_EQ(t.dim, 2);
  EXPECT_EQ(t(0, 0), 20.0);
  EXPECT_EQ(t(1, 1), 10.0);
  EXPECT_EQ(t(0, 3), 0.0);
  // The texture was created before the shader that uses it (evaluation order).
  EXPECT_LT(tex, shader);
  // Source locations: the init-device call is in the do loop at the end of the file.
  const auto devices = calls_of(d, "init-device");
  EXPECT_EQ(devices[0]->params.loc().file, kScenes + "sphereAroundBlackhole.scm");
  EXPECT_EQ(devices[0]->params.loc().line, 175);
  EXPECT_EQ(devices[0]->params.find("setparam")->loc.line, 177);
}

TEST(SharedScenes, KerrAccretionDiskHas89FramesOfDecreasingInclination) {
  const SceneDescription d = eval_shared("kerrAccretionDisk.scm");
  const auto devices = calls_of(d, "init-device");
  ASSERT_EQ(devices.size(), 89u);
  for (size_t i = 0; i < devices.size(); ++i) {
    const double count = static_cast<double>(i + 1);
    const ValueList& sp = setparam(*devices[i]);
    EXPECT_EQ(std::get<std::string>(sp[1].v), "pos");
    EXPECT_EQ(std::get<std::vector<double>>(sp[2].v),
              (std::vector<double>{0.0, 50.0, (90.0 - count) * kDegToRad, 0.0}));
    EXPECT_EQ(devices[i]->params.get_string("camera"), "cam1");
  }
  // `(dir ,(vector (cos (* vdir DEG_TO_RAD)) (sin ...) 0.0)) with vdir = 0.
  EXPECT_EQ(by_id(d, "cam1")->params.get_vector("dir", 3), (std::vector<double>{1.0, 0.0, 0.0}));
  EXPECT_EQ(by_id(d, "metric")->params.get_number("angmom"), 1.0);
  EXPECT_EQ(by_id(d, "ring")->params.get_number("rout"), 15.0);
  EXPECT_EQ(by_id(d, "pancam")->params.get_number("heading"), -90.0);
}

TEST(SharedScenes, FallEddFinkInHas639FramesAlongTheMotion) {
  const SceneDescription d = eval_shared("fallEddFinkIn.scm");
  const auto devices = calls_of(d, "init-device");
  ASSERT_EQ(devices.size(), 639u);
  for (size_t count = 0; count < devices.size(); ++count) {
    const ValueList& sp = setparam(*devices[count]);
    EXPECT_EQ(std::get<std::string>(sp[0].v), "proj");
    EXPECT_EQ(std::get<std::string>(sp[1].v), "actualpos");
    EXPECT_EQ(std::get<double>(sp[2].v), 11.0 * static_cast<double>(count));
  }
  ASSERT_EQ(calls_of(d, "gvs-print-motion").size(), 1u);
  const CommandCall* motion = by_id(d, "obsMotion");
  ASSERT_NE(motion, nullptr);
  EXPECT_EQ(motion->params.get_vector("pos", 4), (std::vector<double>{0.0, 10.0, 1.570796326794897, 0.0}));
  EXPECT_EQ(motion->params.get_bool("step_ctrl", true), true);  // not a motion key: absent
  EXPECT_EQ(by_id(d, "gsolver")->params.get_bool("step_ctrl"), false);
  // Two cameras; the background uses `(transform ,(rotate-obj "z" 0.0)) = identity.
  const Transform t = by_id(d, "bgSphere")->params.get_transform("transform");
  EXPECT_EQ(t.dim, 3);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(t(r, c), r == c ? 1.0 : 0.0);
}

TEST(SharedScenes, MinkWheelBuildsEightSpokesAnd224Frames) {
  const SceneDescription d = eval_shared("minkWheel.scm");
  EXPECT_EQ(calls_of(d, "init-device").size(), 224u);
  EXPECT_EQ(calls_of(d, "add-object").size(), 8u);
  // (do ... (define angle (* 45.0 count)) (solid-cylinder ... `(transform ,(rotate-obj "x" angle))
  //  `(id ,(string-append "spoke_" (number->string count)))) ...)
  for (int count = 0; count < 8; ++count) {
    const CommandCall* spoke = by_id(d, "spoke_" + std::to_string(count));
    ASSERT_NE(spoke, nullptr) << count;
    const Transform t = spoke->params.get_transform("transform");
    const double a = 45.0 * count * kDegToRad;
    EXPECT_NEAR(t(1, 1), std::cos(a), 1e-15);
    EXPECT_NEAR(t(2, 1), std::sin(a), 1e-15);
    EXPECT_NEAR(t(1, 2), -std::sin(a), 1e-15);
    EXPECT_EQ(t(0, 0), 1.0);
  }
  const auto adds = calls_of(d, "add-object");
  EXPECT_EQ(adds[3]->params.get_string("add-to"), "scene");
  EXPECT_EQ(adds[3]->params.get_string("obj"), "spoke_3");
  // Three obj entries kept in order.
  EXPECT_EQ(by_id(d, "scene")->params.get_strings("obj"), (std::vector<std::string>{"csg", "cy3", "box"}));
  EXPECT_EQ(by_id(d, "csg")->params.get_number("csgtype"), 1.0);
  // tstep = (tmax - tmin) / 224.
  const auto devices = calls_of(d, "init-device");
  const double tstep = (28.7 - 6.3) / 224.0;
  EXPECT_DOUBLE_EQ(std::get<double>(setparam(*devices[100])[2].v), 6.3 + tstep * 100.0);
  // viewAngle = -18 deg.
  const double va = -18.0 * kDegToRad;
  EXPECT_EQ(by_id(d, "cam")->params.get_vector("vup", 3), (std::vector<double>{-std::sin(va), 0.0, std::cos(va)}));
}

TEST(SharedScenes, KastorTraschenUsesHomeAndHas30Frames) {
  const SceneDescription d = eval_shared("kastorTraschen.scm");
  const auto devices = calls_of(d, "init-device");
  ASSERT_EQ(devices.size(), 30u);
  for (size_t count = 0; count < devices.size(); ++count)
    EXPECT_EQ(std::get<double>(setparam(*devices[count])[2].v), -20.0 + static_cast<double>(count) * 10.0);
  // (string-append homedir "/local/Texturen/sphereImageMaster_white.tif"), strings keep case.
  const auto textures = calls_of(d, "init-texture");
  ASSERT_EQ(textures.size(), 1u);
  EXPECT_EQ(textures[0]->params.get_string("file"),
            std::string(std::getenv("HOME")) + "/local/Texturen/sphereImageMaster_white.tif");
  EXPECT_EQ(by_id(d, "metric")->params.get_number("z2"), -4.0);
}

TEST(SharedScenes, MorrisThorneHasOneFrameAndTwoCharts) {
  const SceneDescription d = eval_shared("morristhorne.scm");
  const auto devices = calls_of(d, "init-device");
  ASSERT_EQ(devices.size(), 1u);
  EXPECT_EQ(devices[0]->params.get_string("camera"), "cam2");
  EXPECT_EQ(std::get<std::vector<double>>(setparam(*devices[0])[2].v), (std::vector<double>{0.0, 1.0, 1.5707963, 0.0}));
  EXPECT_EQ(by_id(d, "bgimage")->params.get_number("chart"), 0.0);
  EXPECT_EQ(by_id(d, "bgimage2")->params.get_number("chart"), 1.0);
  EXPECT_EQ(calls_of(d, "init-camera").size(), 2u);
}

TEST(SharedScenes, AllSixEvaluateAndEveryCallHasAUniqueId) {
  for (const char* name : {"fallEddFinkIn.scm", "kastorTraschen.scm", "kerrAccretionDisk.scm", "minkWheel.scm",
                           "morristhorne.scm", "sphereAroundBlackhole.scm"}) {
    SCOPED_TRACE(name);
    const SceneDescription d = eval_shared(name);
    EXPECT_EQ(d.file, kScenes + name);
    EXPECT_EQ(d.dir, std::string(GEOVIS_TEST_DATA_DIR) + "/geovis/scenes");
    std::set<std::string> ids;
    for (const auto& c : d.calls) {
      EXPECT_EQ(c.command, c.params.command());
      EXPECT_GT(c.params.loc().line, 0);
      const auto all = c.params.find_all("id");
      ASSERT_EQ(all.size(), 1u) << c.command;
      // gvs-print-motion's id names the motion it prints; every other id is a new object.
      if (c.command != "gvs-print-motion") {
        EXPECT_TRUE(ids.insert(all[0]->value.is_string() ? std::get<std::string>(all[0]->value.v) : "").second)
            << c.command;
      }
      for (const auto& p : c.params.entries()) EXPECT_EQ(p.key, to_lower(p.key));
    }
  }
}

}  // namespace
}  // namespace geovis
