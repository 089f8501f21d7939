// Every examples/*.scm (globbed, so a new example is covered without touching this file) passes
// `geovis check --strict`: it evaluates, every frame builds, and there is no warning at all (an
// unknown key, an unset environment variable, a substituted texture, ... would be one). Each is
// described in examples/README.md, and together they use every GeoViS command of the catalogue
// (docs/geovis-catalogue.md §1) but the two README.md explains.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/geovis_catalogue.h"
#include "cli/command.h"

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

int run_args(std::vector<std::string> args) {
  args.insert(args.begin(), "geovis");
  std::vector<const char*> argv;
  for (auto& a : args) argv.push_back(a.c_str());
  return run(static_cast<int>(argv.size()), argv.data());
}

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

}  // namespace
}  // namespace geovis::cli
