#include "core/type_registry.h"

#include <gtest/gtest.h>

namespace geovis {
namespace {

// A kind of its own, so the registries of the real kinds are untouched.
struct ExampleType : TypeDescription {
  int value = 0;
};
using ExampleRegistry = TypeRegistry<ExampleType>;

const TypeRegistrar<ExampleType> zeta{{{"Zeta", {}, "last by name", {}}, 3}};
const TypeRegistrar<ExampleType> alpha{{{"Alpha", {"GeoViSAlpha"}, "first by name", {}}, 1}};
const TypeRegistrar<ExampleType> mid{{{"Middle", {}, "between", {}}, 2}};

TEST(TypeRegistry, KeepsStaticRegistrationsSortedByName) {
  EXPECT_EQ(ExampleRegistry::instance().names(), (std::vector<std::string>{"Alpha", "Middle", "Zeta"}));
  EXPECT_EQ(ExampleRegistry::instance().names_and_aliases(),
            (std::vector<std::string>{"Alpha", "GeoViSAlpha", "Middle", "Zeta"}));
}

TEST(TypeRegistry, FindsNamesAndAliasesExactlyThenCaseInsensitively) {
  const auto& r = ExampleRegistry::instance();
  EXPECT_EQ(r.find("Middle")->value, 2);
  EXPECT_EQ(r.find("geovisalpha")->value, 1);
  EXPECT_EQ(r.find("ZETA")->value, 3);
  EXPECT_EQ(r.find("Beta"), nullptr);
}

TEST(TypeRegistry, UnknownNameSuggestsTheClosestAndListsTheValidOnes) {
  try {
    ExampleRegistry::instance().get("Midle", "example type");
    FAIL();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("unknown example type \"Midle\""), std::string::npos) << m;
    EXPECT_NE(m.find("did you mean \"Middle\""), std::string::npos) << m;
    EXPECT_NE(m.find("(valid: Alpha, Middle, Zeta)"), std::string::npos) << m;
  }
  ParamSet ps("init-example", SourceLoc{"s.scm", 4});
  try {
    ExampleRegistry::instance().get(ps, "type", "Alhpa", "example type");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("s.scm:4: init-example: type:"), std::string::npos) << e.what();
  }
}

TEST(TypeRegistry, RegisteringANameTwiceIsAnError) {
  TypeRegistry<ExampleType> r;
  r.add({{"One", {"Uno"}, "", {}}, 1});
  EXPECT_THROW(r.add({{"Uno", {}, "", {}}, 2}), std::logic_error);
  EXPECT_THROW(r.add({{"Two", {"One"}, "", {}}, 2}), std::logic_error);
}

}  // namespace
}  // namespace geovis
