// `geovis render` and `geovis check`, run in-process (geovis::cli::run) into a temporary folder.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "io/image.h"

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

class RenderCmd : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_render_cmd_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  int run_args(std::vector<std::string> args) {
    args.insert(args.begin(), "geovis");
    std::vector<const char*> argv;
    for (auto& a : args) argv.push_back(a.c_str());
    return run(static_cast<int>(argv.size()), argv.data());
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  bool exists(const std::string& name) const { return fs::exists(dir_ / name); }

  /// A small flat-space scene with `frames` devices; the observer moves along x per frame.
  std::string write_scene(int frames, const std::string& camera_type = "PinHoleCam",
                          const std::string& filter = "FilterRGB") {
    const std::string p = path("scene.scm");
    std::ofstream f(p);
    f << "(init-metric '(type \"Minkowski\") '(id \"metric\"))\n"
         "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(step_ctrl #f) '(step_size 0.5))\n"
         "(init-camera '(type \""
      << camera_type << "\") '(dir #(1 0 0)) '(vup #(0 0 1)) '(fov #(40 30)) '(res #(8 6)) '(filter \"" << filter
      << "\") '(id \"cam\"))\n"
         "(init-raygen '(type \"RayGenSimple\") '(maxNumPoints 200)\n"
         "  `(boundBoxLL ,(vector (- gpDBLMAX) -30.0 -30.0 -30.0)) `(boundBoxUR ,(vector gpDBLMAX 30.0 30.0 30.0)))\n"
         "(local-tetrad '(pos #(0 -10 0 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0)) '(e3 #(0 0 0 1))\n"
         "  '(incoords #f) '(id \"locTedObs\"))\n"
         "(init-projector '(localTetrad \"locTedObs\") '(color #(0 0 0)) '(id \"proj\"))\n"
         "(init-light-mgr '(ambient #(1 1 1)))\n"
         "(init-texture '(type \"UniTex\") '(color #(0.8 0.2 0.2)) '(id \"red\"))\n"
         "(init-shader '(type \"SurfShader\") '(objcolor \"red\") '(ambient 1.0) '(id \"sh\"))\n"
         "(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0 0 0)) '(axlen #(2 2 2)) '(shader \"sh\")\n"
         "  '(id \"ball\"))\n"
         "(do ((i 0 (+ i 1))) ((= i "
      << frames
      << "))\n"
         "  (init-device '(type \"standard\") '(obj \"ball\")\n"
         "               `(setparam (\"locTedObs\" \"pos\" ,(vector 0.0 (- -10.0 i) 0.0 0.0)))))\n";
    return p;
  }

  fs::path dir_;
};

TEST_F(RenderCmd, DefaultSceneRendersToPng) {
  const std::string out = path("default.png");
  ASSERT_EQ(run_args({"render", "-o", out, "--res", "40x30", "--quiet"}), 0);
  const Image img = read_image(out);
  EXPECT_EQ(img.width, 40);
  EXPECT_EQ(img.height, 30);
  // The sky grid is visible: the image is not uniform.
  float lo = 1e9f, hi = -1e9f;
  for (float v : img.pixels) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_GT(hi - lo, 0.2f);
}

TEST_F(RenderCmd, FrameRangeNaming) {
  const std::string scene = write_scene(4);
  // Several frames without a pattern: the number goes before the extension.
  ASSERT_EQ(run_args({"render", scene, "--frames", "1:2", "-o", path("out.png"), "-q"}), 0);
  EXPECT_FALSE(exists("out_0000.png"));
  EXPECT_TRUE(exists("out_0001.png"));
  EXPECT_TRUE(exists("out_0002.png"));
  EXPECT_FALSE(exists("out_0003.png"));
  EXPECT_FALSE(exists("out.png"));
  // A printf pattern, and the format following the extension.
  ASSERT_EQ(run_args({"render", scene, "--frames", "2:3", "-o", path("seq_%03d.ppm"), "-q"}), 0);
  EXPECT_TRUE(exists("seq_002.ppm"));
  EXPECT_TRUE(exists("seq_003.ppm"));
  EXPECT_EQ(read_image(path("seq_003.ppm")).width, 8);
  // A single frame goes to OUT exactly.
  ASSERT_EQ(run_args({"render", scene, "--frames", "3", "-o", path("one.tif"), "--res", "5x4", "-q"}), 0);
  EXPECT_TRUE(exists("one.tif"));
  const Image one = read_image(path("one.tif"));
  EXPECT_EQ(one.width, 5);
  EXPECT_EQ(one.height, 4);
}

TEST_F(RenderCmd, DefaultOutputNameFollowsTheScene) {
  const std::string scene = write_scene(2);
  const fs::path cwd = fs::current_path();
  fs::current_path(dir_);
  const int rc = run_args({"render", scene, "-q"});
  fs::current_path(cwd);
  ASSERT_EQ(rc, 0);
  EXPECT_TRUE(exists("scene_0000.png"));
  EXPECT_TRUE(exists("scene_0001.png"));
}

TEST_F(RenderCmd, ResumeSkipsFramesOnDisk) {
  const std::string scene = write_scene(3);
  ASSERT_EQ(run_args({"render", scene, "-o", path("f_%d.png"), "-q"}), 0);
  ASSERT_TRUE(exists("f_0.png") && exists("f_1.png") && exists("f_2.png"));
  // Remove frame 1: --resume keeps 0 as it is (the same file: a rewrite would be a new inode)
  // and renders 1 again. (What is not a complete frame: test_render_outputs.cpp.)
  struct stat before {
  }, after{};
  ASSERT_EQ(::stat(path("f_0.png").c_str(), &before), 0);
  fs::remove(path("f_1.png"));
  ASSERT_EQ(run_args({"render", scene, "-o", path("f_%d.png"), "--resume", "-q"}), 0);
  ASSERT_EQ(::stat(path("f_0.png").c_str(), &after), 0);
  EXPECT_EQ(after.st_ino, before.st_ino);
  EXPECT_EQ(read_image(path("f_1.png")).width, 8);
}

TEST_F(RenderCmd, StereoAndFilterFiles) {
  const std::string scene = write_scene(1, "PinHoleStereoCam");
  ASSERT_EQ(run_args({"render", scene, "-o", path("st.png"), "-q"}), 0);
  EXPECT_TRUE(exists("st.left.png"));
  EXPECT_TRUE(exists("st.right.png"));
  const std::string scene2 = write_scene(1, "PinHoleCam", "FilterRGBpdz");
  ASSERT_EQ(run_args({"render", scene2, "-o", path("pd.png"), "-q"}), 0);
  EXPECT_TRUE(exists("pd.png"));
  ASSERT_TRUE(exists("pd.pdz"));
  // int32 W, H, nc = 10, then W*H*10 float64 (catalogue §3).
  EXPECT_EQ(fs::file_size(path("pd.pdz")), 12u + 8u * 6u * 10u * 8u);
}

TEST_F(RenderCmd, BadArgumentsFail) {
  const std::string scene = write_scene(2);
  EXPECT_NE(run_args({"render", scene, "--res", "0x5", "-q"}), 0);
  EXPECT_NE(run_args({"render", scene, "--res", "abc", "-q"}), 0);
  EXPECT_NE(run_args({"render", scene, "--frames", "1:0", "-q"}), 0);
  EXPECT_NE(run_args({"render", scene, "--frames", "5", "-q"}), 0);
  EXPECT_NE(run_args({"render", scene, "-o", path("x.xyz"), "-q"}), 0);
  EXPECT_NE(run_args({"render", scene, "-o", path("x_%s.png"), "-q"}), 0);
  EXPECT_NE(run_args({"render", scene, "--supersample", "0", "-q"}), 0);
  EXPECT_NE(run_args({"render", scene, "--define", "novalue", "-q"}), 0);
  EXPECT_NE(run_args({"render", path("missing.scm"), "-q"}), 0);
  EXPECT_NE(run_args({"render", scene, "--no-such-option"}), 0);
  EXPECT_FALSE(exists("x.xyz"));
  // A scene error stops with a non-zero status and writes nothing.
  { std::ofstream(path("bad.scm")) << "(init-metric '(type \"Schwarzshild\"))\n(init-device '(type \"standard\"))\n"; }
  EXPECT_NE(run_args({"render", path("bad.scm"), "-o", path("bad.png"), "-q"}), 0);
  EXPECT_FALSE(exists("bad.png"));
}

TEST_F(RenderCmd, StrictTurnsWarningsIntoErrors) {
  const std::string p = write_scene(1);
  {
    std::ofstream f(p, std::ios::app);
    f << "(init-camera '(type \"PinHoleCam\") '(res #(4 4)) '(colour #(1 1 1)) '(id \"cam2\"))\n"
         "(init-device '(type \"standard\") '(obj \"ball\") '(camera \"cam2\"))\n";
  }
  EXPECT_EQ(run_args({"render", p, "--frames", "1", "-o", path("w.png"), "-q"}), 0);
  EXPECT_NE(run_args({"render", p, "--frames", "1", "-o", path("w2.png"), "--strict", "-q"}), 0);
  EXPECT_FALSE(exists("w2.png"));
}

TEST_F(RenderCmd, CheckBuildsWithoutRendering) {
  const std::string scene = write_scene(3);
  testing::internal::CaptureStdout();
  const int rc = run_args({"check", scene});
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(rc, 0);
  EXPECT_NE(out.find("Minkowski"), std::string::npos) << out;
  EXPECT_NE(out.find("PinHoleCam 8x6"), std::string::npos) << out;
  EXPECT_NE(out.find("1 solid-ellipsoid"), std::string::npos) << out;
  EXPECT_NE(out.find("frames:   3"), std::string::npos) << out;
  EXPECT_FALSE(exists("scene_0000.png"));
  EXPECT_NE(run_args({"check", path("missing.scm")}), 0);
}

TEST_F(RenderCmd, SceneCallingExitStopsWithoutErrorAndRendersNothing) {
  // GeoViS's (exit) ends the program while the scene is read: nothing is rendered. It is not an
  // error: the status is the scene's exit code, and no "error" is reported.
  for (const auto& [call, code] : std::vector<std::pair<std::string, int>>{{"(exit)", 0}, {"(exit 3)", 3}}) {
    SCOPED_TRACE(call);
    const std::string p = write_scene(2);
    int exit_line = 1;  // the line the call is appended on
    {
      std::ifstream in(p);
      for (std::string l; std::getline(in, l);) ++exit_line;
    }
    { std::ofstream(p, std::ios::app) << call << "\n"; }
    testing::internal::CaptureStderr();
    const int rc = run_args({"render", p, "-o", path("ex_%d.png")});
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(rc, code);
    EXPECT_FALSE(exists("ex_0.png"));
    EXPECT_EQ(err.find("error"), std::string::npos) << err;
    EXPECT_NE(err.find("scene.scm:" + std::to_string(exit_line) + ": exit: the scene called " +
                       (code ? call : std::string("(exit 0)"))),
              std::string::npos)
        << err;
    // -q: silent.
    testing::internal::CaptureStderr();
    EXPECT_EQ(run_args({"render", p, "-o", path("ex_%d.png"), "-q"}), code);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    // check: the same status, no summary, no error.
    testing::internal::CaptureStderr();
    testing::internal::CaptureStdout();
    EXPECT_EQ(run_args({"check", p}), code);
    const std::string out = testing::internal::GetCapturedStdout();
    const std::string cerr = testing::internal::GetCapturedStderr();
    EXPECT_EQ(out.find("ok"), std::string::npos) << out;
    EXPECT_EQ(cerr.find("error"), std::string::npos) << cerr;
    EXPECT_NE(cerr.find("the scene called"), std::string::npos) << cerr;
  }
}

TEST_F(RenderCmd, MovieOfOneFrameAndOfASequence) {
  if (system("command -v ffmpeg >/dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg is not installed";
  const std::string scene = write_scene(3);
  // One frame written to a plain file name (no frame pattern): ffmpeg's image2 reader must take it.
  ASSERT_EQ(
      run_args({"render", scene, "--frames", "1:1", "-o", path("one.png"), "--movie", path("one.mp4"), "--quiet"}), 0);
  EXPECT_TRUE(exists("one.png"));
  EXPECT_GT(fs::file_size(dir_ / "one.mp4"), 0u);
  // A sequence: frames out_0000.png .. out_0002.png, then the movie.
  ASSERT_EQ(run_args({"render", scene, "-o", path("out.png"), "--movie", path("seq.mp4"), "--quiet"}), 0);
  EXPECT_TRUE(exists("out_0002.png"));
  EXPECT_GT(fs::file_size(dir_ / "seq.mp4"), 0u);
}

TEST_F(RenderCmd, MovieWithoutFfmpegFailsBeforeRendering) {
  const std::string scene = write_scene(2);
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", dir_.c_str(), 1);  // a folder without ffmpeg
  testing::internal::CaptureStderr();
  const int rc = run_args({"render", scene, "-o", path("out.png"), "--movie", path("m.mp4"), "--quiet"});
  const std::string err = testing::internal::GetCapturedStderr();
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_NE(rc, 0);
  EXPECT_NE(err.find("ffmpeg is not installed"), std::string::npos) << err;
  EXPECT_FALSE(exists("out_0000.png"));  // nothing rendered: the check comes first
}
}  // namespace
}  // namespace geovis::cli
