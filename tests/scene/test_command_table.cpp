// The command table (src/scene/command_table.h) is the one list of scene commands: the Scheme
// bindings, the builder and the scene reference are made from it, and they agree with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "render/plugins.h"
#include "scene/builder.h"
#include "scene/command_table.h"
#include "scene/scene_reference.h"
#include "scene/scheme.h"
#include "scene/scheme_internal.h"
#include "support/geovis_catalogue.h"

namespace geovis {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(CommandTable, NamesAreUniqueAndLowerCase) {
  std::set<std::string> seen;
  for (const SceneCommand& c : scene_commands()) {
    const std::string name(c.name);
    EXPECT_TRUE(seen.insert(name).second) << name << " is listed twice";
    EXPECT_EQ(name, to_lower(name));
    EXPECT_FALSE(c.doc.empty()) << name << " has no doc line";
  }
}

TEST(CommandTable, HoldsExactlyTheGeoViSCommandsAndTheExtensions) {
  std::set<std::string> catalogue;
  for (const auto& c : testing_support::catalogue_commands()) catalogue.insert(c);
  for (const SceneCommand& c : scene_commands()) {
    const std::string name(c.name);
    EXPECT_NE(catalogue.count(name) > 0, c.geovis_extension) << name << ": a GeoViS command xor an extension";
  }
  // The catalogue's getenv and exit are Scheme procedures of the prelude (sandboxed), not commands.
  for (const auto& name : catalogue)
    if (name != "getenv" && name != "exit") {
      EXPECT_NE(find_scene_command(name), nullptr) << name << " of the GeoViS catalogue is not in the table";
    }
}

TEST(CommandTable, ThePreludeWritesNoCommandByHand) {
  // Every command macro comes from scheme_command_definitions(); the prelude only defines the macro.
  const std::string prelude = scheme_detail::kPreludeSource;
  const std::string generated = scheme_command_definitions();
  for (const SceneCommand& c : scene_commands()) {
    const std::string name(c.name);
    EXPECT_EQ(prelude.find("(%gv-define-command " + name + " "), std::string::npos) << name << " is defined by hand";
    EXPECT_EQ(prelude.find("(" + name + " . "), std::string::npos) << name << " is bound by hand";
    EXPECT_NE(generated.find("(%gv-define-command " + name + " \"" + name + "\")"), std::string::npos) << name;
    // ... and bound in a scene's module, usable as a value.
    EXPECT_NO_THROW(evaluate_scene_string("(define probe " + name + ")", "probe.scm")) << name;
  }
}

TEST(CommandTable, EveryTypedCommandDescribesTheKeysOfEachType) {
  for (const SceneCommand& c : scene_commands()) {
    if (!c.types) continue;
    const auto types = c.types();
    EXPECT_FALSE(types.empty()) << c.name;
    if (!c.keys) continue;
    for (const std::string& type : types) {
      SCOPED_TRACE(std::string(c.name) + " " + type);
      std::vector<ParamSpec> keys;
      ASSERT_NO_THROW(keys = c.keys(type));
      EXPECT_FALSE(keys.empty());
    }
  }
}

TEST(CommandTable, EveryDefaultHasItsKeysTypeAndLiesInItsRange) {
  // The factories read these defaults (core/param_reader.h): a default of the wrong shape would
  // throw at the first scene that leaves the key out, one outside its range is a documentation lie.
  int defaults = 0;
  for (const SceneCommand& c : scene_commands()) {
    if (!c.keys) continue;
    const std::vector<std::string> types = c.types ? c.types() : std::vector<std::string>{std::string()};
    for (const std::string& type : types) {
      for (const ParamSpec& k : c.keys(type)) {
        SCOPED_TRACE(std::string(c.name) + " " + type + " " + k.key);
        if (!k.def) continue;
        ++defaults;
        EXPECT_FALSE(k.required) << "a required key has no use for a default";
        EXPECT_TRUE(value_has_shape(k.type, *k.def)) << k.def->describe();
        if (!k.range) continue;
        std::vector<double> numbers;
        if (k.def->is_number()) numbers.push_back(std::get<double>(k.def->v));
        if (k.def->is_vector()) numbers = std::get<std::vector<double>>(k.def->v);
        for (double x : numbers) EXPECT_TRUE(k.range->contains(x)) << x << " not in " << k.range->text();
      }
    }
  }
  EXPECT_GT(defaults, 20);
}

TEST(CommandTable, RegisteredTypesDescribeThemselves) {
  for (const SceneCommand& c : scene_commands()) {
    if (!c.describe) continue;
    ASSERT_TRUE(c.types) << c.name;
    for (const std::string& type : c.types()) {
      const TypeDescription* d = c.describe(type);
      ASSERT_NE(d, nullptr) << c.name << " " << type;
      EXPECT_EQ(d->name, type);
      EXPECT_FALSE(d->doc.empty()) << c.name << " " << type;
    }
  }
}

TEST(CommandTable, ObjectFactoriesKnowEveryObjectCommandOfTheTable) {
  std::set<std::string> table;
  for (const SceneCommand& c : scene_commands())
    if ((c.role == CommandRole::Definition || c.role == CommandRole::Container) && c.kind == DefinitionKind::Object)
      table.insert(std::string(c.name));
  const auto factory = object_commands();
  EXPECT_EQ(table, std::set<std::string>(factory.begin(), factory.end()));
  for (const auto& name : table) EXPECT_FALSE(object_keys(name).empty()) << name;
}

TEST(CommandTable, ChangeableNamesAreKeysOfTheCommand) {
  // GeoViS's per-frame names that differ from the creating key (builder.cpp setparam_key).
  const std::set<std::string> renamed = {"startpoint", "endpoint", "objfilename", "time", "calc"};
  for (const SceneCommand& c : scene_commands()) {
    if (!c.changeable || !c.keys) continue;
    const std::vector<std::string> types = c.types ? c.types() : std::vector<std::string>{std::string()};
    for (const std::string& type : types) {
      const auto keys = c.keys(type);
      for (const std::string& n : c.changeable(type)) {
        if (renamed.count(n)) continue;
        EXPECT_TRUE(std::any_of(keys.begin(), keys.end(), [&](const ParamSpec& k) { return k.key == n; }))
            << c.name << " " << type << ": changeable \"" << n << "\" is not one of its keys";
      }
    }
  }
}

TEST(CommandTable, AddObjectOnlyAddsToCompounds) {
  const std::string scene =
      "(init-metric '(type \"Minkowski\") '(id \"metric\"))\n"
      "(init-texture '(type \"UniTex\") '(color #(1 0 0)) '(id \"red\"))\n"
      "(init-shader '(type \"SurfShader\") '(objcolor \"red\") '(id \"sh\"))\n"
      "(solid-ellipsoid '(center #(0 0 0)) '(shader \"sh\") '(id \"a\"))\n"
      "(solid-ellipsoid '(center #(0 0 3)) '(shader \"sh\") '(id \"b\"))\n"
      "(add-object '(add-to \"a\") '(obj \"b\"))\n";
  try {
    SceneBuilder b(evaluate_scene_string(scene, "add.scm"), BuildOptions{});
    FAIL() << "adding to a solid-ellipsoid was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("add.scm:6: add-object: add-to: \"a\" is a solid-ellipsoid"),
              std::string::npos)
        << e.what();
  }
}

TEST(SceneReference, DocsFileIsUpToDate) {
  const std::string path = std::string(GEOVIS_SOURCE_DIR) + "/docs/scene-reference.md";
  const std::string expected = scene_reference_markdown();
  EXPECT_TRUE(read_text(path) == expected)
      << path << " is out of date: regenerate it with `build/geovis reference -o docs/scene-reference.md`";
}

TEST(SceneReference, NamesEveryCommandTypeAndKey) {
  const std::string ref = scene_reference_markdown();
  for (const SceneCommand& c : scene_commands()) {
    EXPECT_NE(ref.find("### " + std::string(c.name) + "\n"), std::string::npos) << c.name;
    if (c.types && c.name != "init-solver") {
      for (const std::string& t : c.types()) {
        EXPECT_NE(ref.find("#### " + (c.name == "init-metric" ? t : std::string(c.name) + " `" + t + "`")),
                  std::string::npos)
            << c.name << " " << t;
      }
    }
  }
}

}  // namespace
}  // namespace geovis
