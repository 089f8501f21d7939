// Every one of the six real GeoViS scenes (tests/data/geovis/scenes/*.scm) renders
// unchanged through `geovis render` (first frame at 32x24). Their texture images are
// not distributed, so the test writes small stand-ins into a temporary folder at run time and
// passes it as --texture-path; HOME points to an empty temporary folder, so nothing is read from
// the real home directory (kastorTraschen.scm and morristhorne.scm build their texture paths from
// $HOME, fallEddFinkIn.scm names "examples/eso0932a.tif" relative to where GeoViS was started).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "cli/command.h"
#include "io/image.h"

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

const std::string kScenes = std::string(GEOVIS_TEST_DATA_DIR) + "/geovis/scenes/";

/// A stand-in texture: 8 x 4 cells of distinct colours (so that any part of it seen through a
/// lens is still structured), `tint` distinguishes the files.
Image stand_in(int w, int h, float tint) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int cx = x * 8 / w, cy = y * 4 / h;
      float* p = img.at(x, y);
      p[0] = 0.15f + 0.1f * static_cast<float>(cx);
      p[1] = 0.2f + 0.2f * static_cast<float>(cy);
      p[2] = ((cx + cy) % 2 == 0) ? tint : 1.0f - tint;
    }
  return img;
}

class SharedScenesRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_shared_render_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "textures");
    fs::create_directories(dir_ / "home");
    fs::create_directories(dir_ / "work");
    // The file names the scenes ask for (their folders do not matter: the file of that name in
    // a --texture-path folder is used).
    write_image((dir_ / "textures" / "eso0932a.tif").string(), stand_in(128, 64, 0.9f));
    write_image((dir_ / "textures" / "sphereImageMaster_white.tif").string(), stand_in(128, 64, 0.7f));
    write_image((dir_ / "textures" / "marktplatz_tuebingen_2048.tif").string(), stand_in(128, 64, 0.5f));
    write_image((dir_ / "textures" / "marktplatz_stuttgart_2048.tif").string(), stand_in(128, 64, 0.3f));
    if (const char* h = std::getenv("HOME")) old_home_ = h;
    setenv("HOME", (dir_ / "home").c_str(), 1);
    // fallEddFinkIn.scm writes obsMotion.dat (gvs-print-motion) into the working folder.
    old_cwd_ = fs::current_path();
    fs::current_path(dir_ / "work");
  }
  void TearDown() override {
    fs::current_path(old_cwd_);
    if (old_home_)
      setenv("HOME", old_home_->c_str(), 1);
    else
      unsetenv("HOME");
    fs::remove_all(dir_);
  }

  int run_args(std::vector<std::string> args) {
    args.insert(args.begin(), "geovis");
    std::vector<const char*> argv;
    for (auto& a : args) argv.push_back(a.c_str());
    return run(static_cast<int>(argv.size()), argv.data());
  }

  /// Renders frame 0 of the shared scene at W x H; returns the image (empty on failure).
  Image render_first_frame(const std::string& name, int w, int h, std::string* errors = nullptr) {
    const std::string out = (dir_ / (name + ".png")).string();
    ::testing::internal::CaptureStderr();
    const int rc = run_args({"render", kScenes + name + ".scm", "--frames", "0", "--res",
                             std::to_string(w) + "x" + std::to_string(h), "--threads", "2", "--texture-path",
                             (dir_ / "textures").string(), "-o", out});
    const std::string err = ::testing::internal::GetCapturedStderr();
    if (errors) *errors = err;
    EXPECT_EQ(rc, 0) << err;
    if (rc != 0 || !fs::exists(out)) return {};
    return read_image(out);
  }

  fs::path dir_;
  fs::path old_cwd_;
  std::optional<std::string> old_home_;
};

struct Stats {
  int distinct = 0;      ///< distinct 8-bit colours
  double dark = 0;       ///< fraction of (near) black pixels: shadow, background colour #(0 0 0)
  double lum_sigma = 0;  ///< standard deviation of the luminance
};

Stats stats_of(const Image& img) {
  Stats s;
  std::set<std::tuple<int, int, int>> colours;
  double sum = 0, sum2 = 0;
  int dark = 0;
  const int n = img.width * img.height;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.at(x, y);
      colours.emplace(std::lround(p[0] * 255), std::lround(p[1] * 255), std::lround(p[2] * 255));
      const double l = (p[0] + p[1] + p[2]) / 3.0;
      sum += l;
      sum2 += l * l;
      if (p[0] < 0.02f && p[1] < 0.02f && p[2] < 0.02f) ++dark;
    }
  s.distinct = static_cast<int>(colours.size());
  s.dark = static_cast<double>(dark) / n;
  const double mean = sum / n;
  s.lum_sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  return s;
}

// Each scene has several differently coloured surfaces (textured celestial sphere(s), checkered
// objects, a black shadow or background) in view of its first frame, so a correct render shows
// several colours; a single colour means nothing or everything was hit.
void expect_structured(const std::string& name, const Image& img, int w, int h) {
  SCOPED_TRACE(name);
  ASSERT_EQ(img.width, w);
  ASSERT_EQ(img.height, h);
  const Stats s = stats_of(img);
  std::printf("%-22s %d colours, %.0f%% black, luminance sigma %.3f\n", name.c_str(), s.distinct, 100 * s.dark,
              s.lum_sigma);
  EXPECT_GE(s.distinct, 4);
  EXPECT_GT(s.lum_sigma, 0.02);
  EXPECT_LT(s.dark, 0.95);
}

constexpr int kW = 32, kH = 24;

TEST_F(SharedScenesRender, SphereAroundBlackhole) {
  // 301 frames; frame 0 is the orbiting sphere straight between observer and hole
  // (tests/scene/test_paper_scenes.cpp measures its position).
  const Image img = render_first_frame("sphereAroundBlackhole", kW, kH);
  ASSERT_NO_FATAL_FAILURE(expect_structured("sphereAroundBlackhole", img, kW, kH));
  // fov 2.5 deg around the sphere (radius 0.5 at distance ~24): the checkered sphere fills the
  // middle of the image; the black background (color #(0 0 0), no celestial sphere) the corners.
  const float* c = img.at(kW / 2, kH / 2);
  EXPECT_GT(c[0] + c[1] + c[2], 0.1f) << "image centre is background";
  const float* corner = img.at(0, 0);
  EXPECT_LT(corner[0] + corner[1] + corner[2], 0.06f) << "corner is not background";
}

TEST_F(SharedScenesRender, FallEddFinkIn) {
  std::string err;
  const Image img = render_first_frame("fallEddFinkIn", kW, kH, &err);
  ASSERT_NO_FATAL_FAILURE(expect_structured("fallEddFinkIn", img, kW, kH));
  // "examples/eso0932a.tif" was replaced by the stand-in of that name, and said so.
  EXPECT_NE(err.find("eso0932a.tif"), std::string::npos) << err;
  // gvs-print-motion wrote the observer's worldline into the working folder.
  EXPECT_TRUE(fs::exists(dir_ / "work" / "obsMotion.dat"));
}

TEST_F(SharedScenesRender, MinkWheel) {
  const Image img = render_first_frame("minkWheel", kW, kH);
  ASSERT_NO_FATAL_FAILURE(expect_structured("minkWheel", img, kW, kH));
}

TEST_F(SharedScenesRender, KerrAccretionDisk) {
  const Image img = render_first_frame("kerrAccretionDisk", kW, kH);
  ASSERT_NO_FATAL_FAILURE(expect_structured("kerrAccretionDisk", img, kW, kH));
}

TEST_F(SharedScenesRender, KastorTraschen) {
  std::string err;
  const Image img = render_first_frame("kastorTraschen", kW, kH, &err);
  ASSERT_NO_FATAL_FAILURE(expect_structured("kastorTraschen", img, kW, kH));
  EXPECT_NE(err.find("sphereImageMaster_white.tif"), std::string::npos) << err;
}

TEST_F(SharedScenesRender, MorrisThorne) {
  std::string err;
  const Image img = render_first_frame("morristhorne", kW, kH, &err);
  ASSERT_NO_FATAL_FAILURE(expect_structured("morristhorne", img, kW, kH));
  EXPECT_NE(err.find("marktplatz_tuebingen_2048.tif"), std::string::npos) << err;
  EXPECT_NE(err.find("marktplatz_stuttgart_2048.tif"), std::string::npos) << err;
}

}  // namespace
}  // namespace geovis::cli
