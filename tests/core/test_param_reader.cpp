#include "core/param_reader.h"

#include <gtest/gtest.h>

namespace geovis {
namespace {

std::vector<ParamSpec> specs() {
  return {{"fov", ParamType::Vec2, "field of view", false, false, std::vector<double>{60, 48},
           ParamRange{0, 180, true, true}},
          {"sep", ParamType::Number, "separation", false, false, 0.1, ParamRange::non_negative()},
          {"mode", ParamType::String, "mode", false, false, std::string("linear")},
          {"on", ParamType::Bool, "switch", false, false, false},
          {"count", ParamType::Int, "count", false, false, 3.0},
          {"file", ParamType::String, "no default: required when read"}};
}

TEST(ParamReader, AbsentKeysReadTheirSpecDefault) {
  const auto s = specs();
  ParamSet ps("init-camera", SourceLoc{"a.scm", 1});
  const ParamReader r(ps, s);
  EXPECT_EQ(r.vector("fov", 2), (std::vector<double>{60, 48}));
  EXPECT_DOUBLE_EQ(r.number("sep"), 0.1);
  EXPECT_EQ(r.string("mode"), "linear");
  EXPECT_FALSE(r.boolean("on"));
  EXPECT_EQ(r.integer("count"), 3);
  EXPECT_THROW(r.string("file"), SceneError);
  EXPECT_THROW(r.number("not-a-key"), std::logic_error);
}

TEST(ParamReader, GivenKeysWin) {
  const auto s = specs();
  ParamSet ps("init-camera", SourceLoc{"a.scm", 1});
  ps.add("sep", 0.5);
  ps.add("mode", "radial");
  EXPECT_DOUBLE_EQ(ParamReader(ps, s).number("sep"), 0.5);
  EXPECT_EQ(ParamReader(ps, s).string("mode"), "radial");
}

TEST(ParamSpecRange, ValidateRejectsNumbersOutsideTheRange) {
  const auto s = specs();
  Diagnostics diag;
  ParamSet ok("init-camera", SourceLoc{"a.scm", 2});
  ok.add("fov", std::vector<double>{90, 179.5});
  ok.add("sep", 0.0);
  EXPECT_NO_THROW(ok.validate(s, diag));
  ParamSet open_end("init-camera", SourceLoc{"a.scm", 3});
  open_end.add("fov", std::vector<double>{180, 40});
  try {
    open_end.validate(s, diag);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("a.scm:3: init-camera: fov: expected numbers in (0, 180)"), std::string::npos)
        << e.what();
  }
  ParamSet negative("init-camera", SourceLoc{"a.scm", 4});
  negative.add("sep", -1e-9);
  EXPECT_THROW(negative.validate(s, diag), SceneError);
}

TEST(ParamReader, ReadsOnlyNumbersInTheRange) {
  // Factories called without validate (tests, builder-internal reads) still see the range.
  const auto s = specs();
  ParamSet ps("init-camera", SourceLoc{"a.scm", 5});
  ps.add("sep", -0.5);
  ps.add("fov", std::vector<double>{0, 30});
  EXPECT_THROW(ParamReader(ps, s).number("sep"), SceneError);
  try {
    ParamReader(ps, s).vector("fov", 2);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("a.scm:5: init-camera: fov: expected numbers in (0, 180)"), std::string::npos)
        << e.what();
  }
}

TEST(ParamSpecRange, TextAndDefaultTextAreWhatTheReferencePrints) {
  EXPECT_EQ((ParamRange{0, 180, true, true}.text()), "(0, 180)");
  EXPECT_EQ(ParamRange::non_negative().text(), "[0, inf)");
  EXPECT_EQ((ParamRange{-1, 1}.text()), "[-1, 1]");
  const auto s = specs();
  EXPECT_EQ(param_default_text(s[0]), "#(60 48)");
  EXPECT_EQ(param_default_text(s[1]), "0.1");
  EXPECT_EQ(param_default_text(s[2]), "\"linear\"");
  EXPECT_EQ(param_default_text(s[3]), "#f");
  EXPECT_EQ(param_default_text(s[5]), "");
}

}  // namespace
}  // namespace geovis
