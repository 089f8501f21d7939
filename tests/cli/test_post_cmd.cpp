// `geovis render --data` and `geovis post`, run in-process (geovis::cli::run) into a temporary folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "io/image.h"
#include "render/data_exr.h"

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

class PostCmd : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_post_cmd_" + std::to_string(::getpid()) + "_" +
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

  /// A Keplerian disk around a Schwarzschild hole, 32x24 pixels, with the given camera filter.
  std::string write_scene(const std::string& filter) {
    const std::string p = path("disk.scm");
    std::ofstream f(p);
    f << "(init-metric '(type \"Schwarzschild\") '(mass 1.0) '(id \"metric\"))\n"
         "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(eps_abs 1.0e-8) '(id \"s\"))\n"
         "(init-camera '(type \"PinHoleCam\") '(dir #(1 0 0)) '(vup #(0 0 1)) '(fov #(40 30)) '(res #(32 24))\n"
         "  '(filter \""
      << filter
      << "\") '(id \"cam\"))\n"
         "(init-raygen '(type \"RayGenSimple\") '(solver \"s\") '(maxNumPoints 3000)\n"
         "  `(boundBoxLL ,(vector (- gpDBLMAX) 0.0 (- gpDBLMAX) (- gpDBLMAX)))\n"
         "  `(boundBoxUR ,(vector gpDBLMAX 70.0 gpDBLMAX gpDBLMAX)))\n"
         "(local-tetrad '(pos #(0 40 1.3 0)) '(e0 #(1 0 0 0)) '(e1 #(0 -1 0 0)) '(e2 #(0 0 0 -1))\n"
         "  '(e3 #(0 0 -1 0)) '(incoords #f) '(id \"obs\"))\n"
         "(init-projector '(localTetrad \"obs\") '(id \"proj\"))\n"
         "(init-light-mgr '(ambient #(1 1 1)))\n"
         "(plane-ring `(objtype ,gpObjTypeInCoords) '(rin 6.0) '(rout 15.0) '(emitter \"keplerian\") '(id \"disk\"))\n"
         "(init-device '(type \"standard\") '(obj \"disk\") '(camera \"cam\"))\n";
    return p;
  }
  fs::path dir_;
};

TEST_F(PostCmd, DataFlagWritesTheExrAndPostMakesEveryPicture) {
  const std::string scene = write_scene("FilterRGB");
  ASSERT_EQ(run_args({"render", scene, "-o", path("disk.png"), "--data", "--quiet", "--threads", "1", "--define",
                      "unused=1"}),
            0);
  ASSERT_TRUE(fs::exists(path("disk.exr")));
  EXPECT_FALSE(fs::exists(path("disk.pdz")));  // no GeoViS file without a data filter
  const ChannelImage d = read_data_file(path("disk.exr"));
  EXPECT_EQ(d.meta("geovis:scene.file"), "disk.scm");
  EXPECT_EQ(d.meta("geovis:scene.path"), fs::absolute(path("disk.scm")).lexically_normal().string());
  EXPECT_EQ(d.meta("geovis:scene.hash").size(), 16u);
  EXPECT_EQ(d.meta("geovis:version"), kVersion);
  EXPECT_EQ(d.meta("geovis:scene.defines"), "unused=1");
  for (const char* shader : {"redshift", "disk-flux", "time", "stop"}) {
    const std::string out = path(std::string(shader) + ".png");
    ASSERT_EQ(run_args({"post", path("disk.exr"), "-o", out, "--shader", shader, "--quiet"}), 0) << shader;
    const Image img = read_image(out);
    EXPECT_EQ(img.width, 32) << shader;
    EXPECT_EQ(img.height, 24) << shader;
  }
  // No Jacobi data without FilterRGBjac: a clear error, no image.
  EXPECT_NE(run_args({"post", path("disk.exr"), "-o", path("mu.png"), "--shader", "lensing", "--quiet"}), 0);
  EXPECT_FALSE(fs::exists(path("mu.png")));
  // The colour bar adds a labelled strip below the picture.
  ASSERT_EQ(run_args({"post", path("disk.exr"), "-o", path("bar.png"), "--shader", "redshift", "--colorbar", "--range",
                      "0.8,1.6", "--quiet"}),
            0);
  EXPECT_GT(read_image(path("bar.png")).height, 24);
  ASSERT_EQ(run_args({"post", path("disk.exr"), "-o", path("log.png"), "--shader", "disk-flux", "--log", "--quiet"}),
            0);
}

TEST_F(PostCmd, JacobiFilterGivesLensingAndBothFiles) {
  const std::string scene = write_scene("FilterRGBjac");
  // The Jacobi system is the slow one: a smaller picture.
  ASSERT_EQ(run_args({"render", scene, "-o", path("disk.png"), "--res", "16x12", "--quiet", "--threads", "1"}), 0);
  ASSERT_TRUE(fs::exists(path("disk.exr")));
  ASSERT_TRUE(fs::exists(path("disk.jac")));
  ASSERT_EQ(run_args({"post", path("disk.exr"), "-o", path("mu.png"), "--shader", "lensing", "--log", "--quiet"}), 0);
  // The GeoViS file works too (no stop reasons in it).
  ASSERT_EQ(run_args({"post", path("disk.jac"), "-o", path("z.png"), "--shader", "redshift", "--quiet"}), 0);
  EXPECT_NE(run_args({"post", path("disk.jac"), "-o", path("s.png"), "--shader", "stop", "--quiet"}), 0);
}

TEST_F(PostCmd, CsvOfChosenChannelsAndPixels) {
  const std::string scene = write_scene("FilterRGBpdz");
  ASSERT_EQ(run_args({"render", scene, "-o", path("disk.png"), "--quiet", "--threads", "1"}), 0);
  ASSERT_EQ(run_args({"post", path("disk.exr"), "--csv", path("px.csv"), "--channels", "x1,z,stop", "--pixel", "16,12",
                      "--pixel", "0,0", "--quiet"}),
            0);
  std::ifstream f(path("px.csv"));
  std::string header, a, b, extra;
  std::getline(f, header);
  std::getline(f, a);
  std::getline(f, b);
  EXPECT_EQ(header, "x,y,x1,z,stop");
  EXPECT_EQ(a.rfind("16,12,", 0), 0u);
  EXPECT_EQ(b.rfind("0,0,", 0), 0u);
  EXPECT_FALSE(std::getline(f, extra));
}

TEST_F(PostCmd, BadInputIsAnErrorNotACrash) {
  std::ofstream(path("notes.txt")) << "hello";
  EXPECT_NE(run_args({"post", path("notes.txt"), "-o", path("o.png"), "--shader", "redshift", "--quiet"}), 0);
  EXPECT_NE(run_args({"post", path("missing.exr"), "-o", path("o.png"), "--shader", "redshift", "--quiet"}), 0);
  EXPECT_NE(run_args({"post", path("notes.txt"), "-o", path("o.png"), "--shader", "redshfit", "--quiet"}), 0);
  EXPECT_NE(run_args({"post", path("notes.txt"), "--quiet"}), 0);                       // nothing to do
  EXPECT_NE(run_args({"post", path("notes.txt"), "-o", path("o.png"), "--quiet"}), 0);  // no shader
  EXPECT_NE(run_args({"post", path("notes.txt"), "-o", path("o.png"), "--shader", "time", "--range", "1", "--quiet"}),
            0);
  EXPECT_FALSE(fs::exists(path("o.png")));
}

}  // namespace
}  // namespace geovis::cli
