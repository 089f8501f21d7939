// The corpus of broken scenes (tests/scene/broken/*.scm): each file makes one mistake a user
// could make and states in its header what the error message must say:
//   ;; expect: <substring of the message>
//   ;; line: <line the message must point at>
// Each scene is evaluated and built (SceneBuilder: every device); the test checks that an
// geovis::Error is thrown (never a crash, never silent success), that the message contains the
// expected text and "file:line".
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/builder.h"
#include "scene/scheme.h"

namespace geovis {
namespace {

const std::string kBrokenDir = std::string(GEOVIS_SOURCE_DIR) + "/tests/scene/broken";

struct BrokenScene {
  std::string path;
  std::string expect;
  int line = 0;
};

std::vector<BrokenScene> load_corpus() {
  std::vector<BrokenScene> out;
  for (const auto& e : std::filesystem::directory_iterator(kBrokenDir)) {
    if (e.path().extension() != ".scm") continue;
    BrokenScene b;
    b.path = e.path().string();
    std::ifstream in(b.path);
    std::string l;
    while (std::getline(in, l) && l.rfind(";;", 0) == 0) {
      if (l.rfind(";; expect: ", 0) == 0) b.expect = l.substr(11);
      if (l.rfind(";; line: ", 0) == 0) b.line = std::stoi(l.substr(9));
    }
    out.push_back(b);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
  return out;
}

// Evaluates and builds; returns the error message ("" if there was none).
std::string evaluate_and_build(const std::string& path) {
  try {
    Diagnostics diag;
    SchemeOptions opts;
    opts.diag = &diag;
    SceneDescription desc = evaluate_scene_file(path, opts);
    BuildOptions bopts;
    bopts.diag = &diag;
    bopts.search_paths = {desc.dir};
    SceneBuilder builder(std::move(desc), bopts);
    for (int d = 0; d < builder.device_count(); ++d) (void)builder.build(d);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(BrokenScenes, CorpusHasAtLeastThirtyScenes) {
  const auto corpus = load_corpus();
  EXPECT_GE(corpus.size(), 30u);
  for (const auto& b : corpus) {
    EXPECT_FALSE(b.expect.empty()) << b.path << ": missing ';; expect:' header";
    EXPECT_GT(b.line, 0) << b.path << ": missing ';; line:' header";
  }
}

TEST(BrokenScenes, EachGivesTheExpectedErrorWithFileAndLine) {
  for (const auto& b : load_corpus()) {
    SCOPED_TRACE(b.path);
    const std::string msg = evaluate_and_build(b.path);
    EXPECT_FALSE(msg.empty()) << "no error for " << b.path;
    if (msg.empty()) continue;
    if (std::getenv("GEOVIS_PRINT_BROKEN")) std::printf("%s\n  -> %s\n", b.path.c_str(), msg.c_str());
    EXPECT_NE(msg.find(b.expect), std::string::npos) << "message: " << msg << "\nexpected: " << b.expect;
    const std::string where = b.path + ":" + std::to_string(b.line) + ":";
    EXPECT_NE(msg.find(where), std::string::npos) << "message: " << msg << "\nexpected location: " << where;
  }
}

// The base all broken scenes are made from is itself valid, so each error comes from its one
// mistake.
TEST(BrokenScenes, BaseSceneIsValid) {
  std::ifstream in(kBrokenDir + "/unknown_command.scm");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string bad = "(init-metrik ";
  const auto at = text.find(bad);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, bad.size(), "(init-metric ");
  SceneDescription desc = evaluate_scene_string(text, "base.scm");
  SceneBuilder builder(std::move(desc), BuildOptions{});
  ASSERT_EQ(builder.device_count(), 1);
  EXPECT_NO_THROW((void)builder.build(0));
}

}  // namespace
}  // namespace geovis
