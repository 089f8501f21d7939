// The command line speaks with one voice: every error starts with "geovis: error:" (CLI11's parse
// errors included), a mistyped subcommand gets a suggestion, --help lists the subcommands and the
// default render, `check` reports what `render` would, -q silences the scene too, and the sandbox
// options (--trust-scene, --scene-path, --scene-time-limit, --scene-memory-limit) work.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/command.h"

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

class OneVoice : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_one_voice_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  struct Result {
    int rc;
    std::string out, err;
  };
  Result run_args(std::vector<std::string> args) {
    args.insert(args.begin(), "geovis");
    std::vector<const char*> argv;
    for (auto& a : args) argv.push_back(a.c_str());
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const int rc = run(static_cast<int>(argv.size()), argv.data());
    Result r{rc, testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
    return r;
  }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  /// A small flat-space scene; `extra` is appended; without `device` it has no init-device.
  std::string scene(const std::string& extra = "", bool device = true) const {
    std::string s =
        "(define fview 40.0)\n"
        "(init-metric '(type \"Minkowski\") '(id \"metric\"))\n"
        "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(step_ctrl #f) '(step_size 0.5))\n"
        "(init-camera '(type \"PinHoleCam\") '(dir #(1 0 0)) '(vup #(0 0 1)) `(fov ,(vector fview 30)) "
        "'(res #(8 6)) '(id \"cam\"))\n"
        "(init-raygen '(type \"RayGenSimple\") '(maxNumPoints 200)\n"
        "  `(boundBoxLL ,(vector (- gpDBLMAX) -30.0 -30.0 -30.0)) `(boundBoxUR ,(vector gpDBLMAX 30.0 30.0 30.0)))\n"
        "(local-tetrad '(pos #(0 -10 0 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0)) '(e3 #(0 0 0 1))\n"
        "  '(incoords #f) '(id \"locTedObs\"))\n"
        "(init-projector '(localTetrad \"locTedObs\") '(color #(0 0 0)) '(id \"proj\"))\n"
        "(init-light-mgr '(ambient #(1 1 1)))\n"
        "(init-texture '(type \"UniTex\") '(color #(0.8 0.2 0.2)) '(id \"red\"))\n"
        "(init-shader '(type \"SurfShader\") '(objcolor \"red\") '(ambient 1.0) '(id \"sh\"))\n"
        "(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0 0 0)) '(axlen #(2 2 2)) '(shader \"sh\") "
        "'(id \"ball\"))\n";
    if (device) s += "(init-device '(type \"standard\") '(obj \"ball\"))\n";
    return s + extra;
  }

  fs::path dir_;
};

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

TEST_F(OneVoice, ParseErrorsStartLikeEveryOtherError) {
  const std::string p = write("s.scm", scene());
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"--threads", "abc"}, {"--foo"}, {"render", p, "--foo"}, {"check"}, {"geodesic", "--metric"}}) {
    const Result r = run_args(args);
    SCOPED_TRACE(args[0]);
    EXPECT_EQ(r.rc, 1);
    EXPECT_TRUE(starts_with(r.err, "geovis: error: ")) << r.err;
  }
  EXPECT_NE(run_args({"--threads", "abc"}).err.find("--threads"), std::string::npos);
}

TEST_F(OneVoice, MistypedSubcommandSuggestsTheClosest) {
  const Result r = run_args({"rendr", "x.scm"});
  EXPECT_EQ(r.rc, 1);
  EXPECT_TRUE(starts_with(r.err, "geovis: error: \"rendr\" is neither a subcommand")) << r.err;
  EXPECT_NE(r.err.find("did you mean \"render\"?"), std::string::npos) << r.err;
  EXPECT_NE(run_args({"chek", "x.scm"}).err.find("did you mean \"check\"?"), std::string::npos);
  // A scene file that does not exist is still reported as such.
  EXPECT_NE(run_args({(dir_ / "missing.scm").string()}).err.find("does not exist"), std::string::npos);
}

TEST_F(OneVoice, TopLevelHelpListsSubcommandsAndTheDefaultRender) {
  const Result r = run_args({"--help"});
  EXPECT_EQ(r.rc, 0);
  for (const char* cmd : {"check", "geodesic", "metrics", "render"}) EXPECT_NE(r.out.find(cmd), std::string::npos);
  EXPECT_NE(r.out.find("geovis [render options]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("renders the built-in scene"), std::string::npos) << r.out;
}

TEST_F(OneVoice, CheckReportsTheErrorRenderWouldGive) {
  const std::string p = write("nodevice.scm", scene("", /*device=*/false));
  const Result check = run_args({"check", p});
  const Result render = run_args({"render", p, "-o", (dir_ / "x.png").string()});
  EXPECT_EQ(check.rc, 1);
  EXPECT_EQ(render.rc, 1);
  EXPECT_NE(check.err.find("geovis: error: the scene has no init-device"), std::string::npos) << check.err;
  EXPECT_EQ(check.err, render.err);
  // An action that render would refuse (a file outside the output folder) is refused by check.
  const std::string ray = write("ray.scm", scene("(calc-ray '(filename \"../ray.txt\") '(raygen \"unknown1\") "
                                                 "'(locted \"locTedObs\") '(dir #(0.0 80.0)))\n"));
  const Result check_ray = run_args({"check", ray});
  EXPECT_EQ(check_ray.rc, 1);
  EXPECT_NE(check_ray.err.find("is outside the output folder"), std::string::npos) << check_ray.err;
}

TEST_F(OneVoice, QuietAlsoSilencesTheScene) {
  const std::string p = write("talk.scm", scene("(display \"scene-says-hello\")\n(newline)\n"));
  const Result loud = run_args({"check", p});
  EXPECT_EQ(loud.rc, 0);
  EXPECT_NE(loud.out.find("scene-says-hello"), std::string::npos);
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"check", p, "-q"}, {"-q", "check", p}, {"render", p, "-q", "-o", (dir_ / "t.png").string()}}) {
    const Result quiet = run_args(args);
    EXPECT_EQ(quiet.rc, 0) << quiet.err;
    EXPECT_EQ(quiet.out, "");
    EXPECT_EQ(quiet.err, "");
  }
}

TEST_F(OneVoice, DefineThatIsNoDatumNamesTheOption) {
  const std::string p = write("s.scm", scene());
  const Result r = run_args({"check", p, "--define", "fview=("});
  EXPECT_EQ(r.rc, 1);
  EXPECT_TRUE(starts_with(r.err, "geovis: error: --define fview=(: the value is not a Scheme datum")) << r.err;
  EXPECT_EQ(r.err.find("unknown port"), std::string::npos) << r.err;
}

TEST_F(OneVoice, SandboxOptions) {
  const std::string victim = write("victim.txt", "x");
  const std::string p = write("s.scm", scene("(delete-file \"" + victim + "\")\n"));
  const Result sandboxed = run_args({"check", p, "-q"});
  EXPECT_EQ(sandboxed.rc, 1);
  EXPECT_NE(sandboxed.err.find("\"delete-file\" is not available in scenes (they run sandboxed; --trust-scene "
                               "lifts this)"),
            std::string::npos)
      << sandboxed.err;
  EXPECT_TRUE(fs::exists(victim));
  EXPECT_EQ(run_args({"check", p, "-q", "--trust-scene"}).rc, 0);
  EXPECT_FALSE(fs::exists(victim));

  write("lib/part.scm", "(define part 1)\n");
  const std::string loader = write("scenes/loader.scm", scene("(load \"part.scm\")\n"));
  EXPECT_EQ(run_args({"check", loader, "-q"}).rc, 1);
  EXPECT_EQ(run_args({"check", loader, "-q", "--scene-path", (dir_ / "lib").string()}).rc, 0);
  EXPECT_NE(run_args({"check", loader, "--scene-path", (dir_ / "nolib").string()}).err.find("--scene-path"),
            std::string::npos);

  const std::string loop = write("loop.scm", scene("(let loop () (loop))\n"));
  const Result slow = run_args({"check", loop, "--scene-time-limit", "0.5"});
  EXPECT_EQ(slow.rc, 1);
  EXPECT_NE(slow.err.find("time limit of 0.5 s"), std::string::npos) << slow.err;
  const std::string grow = write("grow.scm", scene("(let grow ((l '())) (grow (cons (make-vector 100 0) l)))\n"));
  const Result big = run_args({"check", grow, "--scene-memory-limit", "40"});
  EXPECT_EQ(big.rc, 1);
  EXPECT_NE(big.err.find("more memory than the limit of 40 MiB"), std::string::npos) << big.err;
}

}  // namespace
}  // namespace geovis::cli
