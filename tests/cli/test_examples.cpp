// Every examples/*.scm (globbed, so a new example is covered without touching this file) passes
// `geovis check --strict`: it evaluates, every frame builds, and there is no warning at all (an
// unknown key, an unset environment variable, a substituted texture, ... would be one). Each is
// described in examples/README.md, and together they use every GeoViS command of the catalogue
// (docs/geovis-catalogue.md §1) but the two README.md explains. Their pictures at a small
// resolution are pixel-identical to the recorded ones (a refactor must not change a picture).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/geovis_catalogue.h"
#include "cli/command.h"
#include "core/hash.h"
#include "io/image.h"
#include "support/run_geovis.h"

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

const fs::path kExamples = fs::path(GEOVIS_SOURCE_DIR) / "examples";

std::vector<fs::path> example_scenes() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(kExamples))
    if (e.is_regular_file() && e.path().extension() == ".scm") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

using testing_support::run_args;

TEST(Examples, EachPassesCheckStrictWithoutWarnings) {
  const auto scenes = example_scenes();
  ASSERT_GE(scenes.size(), 10u);
  for (const auto& scene : scenes) {
    SCOPED_TRACE(scene.filename().string());
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const int rc = run_args({"check", "--strict", scene.string()});
    const std::string out = testing::internal::GetCapturedStdout();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(rc, 0) << err;
    EXPECT_EQ(err, "");
    EXPECT_NE(out.find("\nok\n"), std::string::npos) << out;
    // At least one image.
    EXPECT_EQ(out.find("images:   0\n"), std::string::npos) << out;
  }
}

TEST(Examples, EachIsDescribedInTheReadme) {
  std::ifstream in(kExamples / "README.md");
  ASSERT_TRUE(in.good()) << "examples/README.md is missing";
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string readme = ss.str();
  for (const auto& scene : example_scenes())
    EXPECT_NE(readme.find(scene.filename().string()), std::string::npos)
        << scene.filename() << " is not in examples/README.md";
}

using testing_support::catalogue_commands;

TEST(Examples, TogetherUseEveryGeoViSCommand) {
  // The text of every example and include file.
  std::string text;
  for (const auto& e : fs::recursive_directory_iterator(kExamples))
    if (e.is_regular_file() && e.path().extension() == ".scm") {
      std::ifstream in(e.path());
      std::stringstream ss;
      ss << in.rdbuf();
      text += ss.str() + "\n";
    }
  // Not in an example on purpose (examples/README.md, "Coverage"): getenv makes a scene depend on
  // the machine (kastorTraschen.scm and morristhorne.scm in tests/data/geovis/scenes use it), exit stops a
  // scene before anything is rendered (tests/cli/test_render_cmd.cpp covers it).
  const std::vector<std::string> not_shown = {"getenv", "exit"};
  const auto cmds = catalogue_commands();
  ASSERT_GE(cmds.size(), 40u);
  for (const auto& c : cmds) {
    if (std::find(not_shown.begin(), not_shown.end(), c) != not_shown.end()) continue;
    // A call "(name ..." or "(name)", or name passed to apply.
    const bool used = text.find("(" + c + " ") != std::string::npos || text.find("(" + c + ")") != std::string::npos ||
                      text.find("(" + c + "\n") != std::string::npos ||
                      text.find("(apply " + c + " ") != std::string::npos ||
                      text.find("(apply " + c + "\n") != std::string::npos;
    EXPECT_TRUE(used) << c << " is used by no example";
  }
}

// ---- pictures: pixel-identical to the recorded hashes -------------------------------------------
//
// tests/data/examples/pixel_hashes.txt holds, per example, the FNV-1a hash of the pixels of its
// first frame at 24x18 (every PNG it writes). A change that is not meant to change what a scene
// shows (a refactor, a speed-up that executes the same operations) must leave them all alone; a
// change that is meant to (physics, GeoViS semantics) re-records them with
// scripts/record_example_hashes.sh and says in its commit message which pictures changed and why.
// The hashes were first recorded with the build of commit f7cf77a, before the command table.

const fs::path kHashFile = fs::path(GEOVIS_TEST_DATA_DIR) / "examples" / "pixel_hashes.txt";

std::map<std::string, std::string> recorded_hashes() {
  std::map<std::string, std::string> out;
  std::ifstream in(kHashFile);
  std::string name, hash;
  while (in >> name >> hash) out[name] = hash;
  return out;
}

std::string example_name(const testing::TestParamInfo<std::string>& info) {
  std::string n = info.param;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

std::vector<std::string> example_stems() {
  std::vector<std::string> out;
  for (const auto& p : example_scenes()) out.push_back(p.stem().string());
  return out;
}

class ExamplePicture : public testing::TestWithParam<std::string> {};

TEST_P(ExamplePicture, IsPixelIdenticalToTheRecordedOne) {
  const std::string stem = GetParam();
  const fs::path dir = fs::temp_directory_path() / ("geovis_example_" + stem + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Text outputs of a scene (calc-ray, gvs-print-motion) go to the working folder: the temporary one.
  const fs::path cwd = fs::current_path();
  fs::current_path(dir);
  testing::internal::CaptureStderr();
  const int rc = run_args({"render", (kExamples / (stem + ".scm")).string(), "--res", "24x18", "--frames", "0:0",
                           "--threads", "1", "--quiet", "-o", (dir / (stem + ".png")).string()});
  const std::string err = testing::internal::GetCapturedStderr();
  fs::current_path(cwd);
  ASSERT_EQ(rc, 0) << err;
  std::vector<fs::path> pngs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".png") pngs.push_back(e.path());
  std::sort(pngs.begin(), pngs.end());
  ASSERT_FALSE(pngs.empty());
  std::uint64_t h = kFnv1a64Seed;
  for (const auto& p : pngs) {
    const Image img = read_image(p.string());
    h = fnv1a64(img.pixels.data(), img.pixels.size() * sizeof(float), h);
  }
  fs::remove_all(dir);
  const std::string got = fnv1a64_text(h);
  if (std::getenv("GEOVIS_RECORD_EXAMPLE_HASHES")) {
    std::ofstream(kHashFile.string() + "." + stem, std::ios::trunc) << stem << " " << got << "\n";
    GTEST_SKIP() << "recorded " << stem << " " << got;
  }
  const auto recorded = recorded_hashes();
  const auto it = recorded.find(stem);
  ASSERT_NE(it, recorded.end()) << stem << " has no recorded hash in " << kHashFile
                                << " (scripts/record_example_hashes.sh records it)";
  EXPECT_EQ(got, it->second) << stem
                             << ": the picture changed. If that is intended, re-record with "
                                "scripts/record_example_hashes.sh and say why in the commit.";
}

INSTANTIATE_TEST_SUITE_P(Examples, ExamplePicture, testing::ValuesIn(example_stems()), example_name);

}  // namespace
}  // namespace geovis::cli
