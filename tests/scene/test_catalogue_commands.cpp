// The scene language against the GeoViS reference (docs/geovis-catalogue.md §1):
// exactly GeoViS's commands exist; add-object accepts the id every call gets; texture images and
// meshes named by paths of another machine are found by file name in the search folders.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>

#include "support/geovis_catalogue.h"
#include "io/image.h"
#include "scene/builder.h"
#include "scene/scheme.h"
#include "support/temp_dir.h"

namespace geovis {
namespace {

namespace fs = std::filesystem;

using testing_support::catalogue_commands;

TEST(CatalogueCommands, EveryGeoViSCommandIsDefinedInAScene) {
  const auto cmds = catalogue_commands();
  ASSERT_GE(cmds.size(), 40u);  // 42 names in 40 rows (vec3/vec4, m4d-metriclist/m4d-solverlist)
  const auto& lang = scene_language_names();
  for (const auto& c : cmds) {
    SCOPED_TRACE(c);
    EXPECT_NE(std::find(lang.begin(), lang.end(), c), lang.end());
    // Bound in a scene's module (as a value: every command also works as a procedure).
    EXPECT_NO_THROW(evaluate_scene_string("(define probe " + c + ")", "probe.scm"));
  }
}

TEST(CatalogueCommands, EveryRecordingCommandIsGeoViSsOrADocumentedExtension) {
  const auto cmds = catalogue_commands();
  const std::set<std::string> cat(cmds.begin(), cmds.end());
  const auto& ext = scene_extension_command_names();
  for (const auto& c : scene_command_names()) {
    const bool extension = std::find(ext.begin(), ext.end(), c) != ext.end();
    EXPECT_NE(cat.count(c) > 0, extension) << c << ": a GeoViS command xor a geovis extension";
  }
}

/// A flat scene with a compound "scene" of one ball; `extra` is appended before init-device.
std::string flat_scene(const std::string& extra) {
  return "(init-metric '(type \"Minkowski\") '(id \"metric\"))\n"
         "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(id \"raytracing\"))\n"
         "(init-camera '(type \"PinHoleCam\") '(res #(8 6)) '(id \"cam\"))\n"
         "(init-raygen '(type \"RayGenSimple\") '(solver \"raytracing\"))\n"
         "(local-tetrad '(pos #(0 -10 0 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0))\n"
         "              '(e3 #(0 0 0 1)) '(incoords #f) '(id \"obs\"))\n"
         "(init-projector '(localtetrad \"obs\") '(id \"proj\"))\n"
         "(init-light-mgr '(ambient #(1 1 1)) '(id \"lights\"))\n"
         "(init-texture '(type \"UniTex\") '(color #(1 0 0)) '(id \"red\"))\n"
         "(init-shader '(type \"SurfShader\") '(objcolor \"red\") '(id \"sh\"))\n"
         "(solid-ellipsoid '(center #(0 0 0)) '(shader \"sh\") '(id \"a\"))\n"
         "(solid-ellipsoid '(center #(0 0 3)) '(shader \"sh\") '(id \"b\"))\n"
         "(comp-object '(obj \"a\") '(id \"scene\"))\n" +
         extra + "(init-device '(type \"standard\") '(obj \"scene\"))\n";
}

TEST(CatalogueCommands, AddObjectWithOrWithoutIdGivesNoWarning) {
  // Every GeoViS object gets an id (catalogue §1 conventions): add-object with '(id ...) and
  // without (the evaluator adds "unknownN") both build without an "unknown key" warning.
  for (const std::string add : {"(add-object '(add-to \"scene\") '(obj \"b\") '(id \"addB\"))\n",
                                "(add-object '(add-to \"scene\") '(obj \"b\"))\n"}) {
    SCOPED_TRACE(add);
    Diagnostics diag;
    SchemeOptions so;
    so.diag = &diag;
    BuildOptions bo;
    bo.diag = &diag;
    SceneBuilder b(evaluate_scene_string(flat_scene(add), "add.scm", so), bo);
    const auto jobs = b.build(0);
    ASSERT_EQ(jobs.size(), 1u);
    // Both balls are in the scene: the compound reaches from z = -1 to z = 4.
    EXPECT_NEAR(jobs[0].job.scene->bounds().hi.z, 4.0, 1e-9);
    EXPECT_TRUE(diag.warnings().empty()) << diag.warnings().front();
    // Strict mode (warnings are errors) accepts it too.
    Diagnostics strict;
    strict.strict = true;
    bo.diag = &strict;
    EXPECT_NO_THROW(SceneBuilder(evaluate_scene_string(flat_scene(add), "add.scm"), bo).build(0));
  }
}

TEST(CatalogueCommands, PlaneParallelogramExtensionBuildsAParallelogram) {
  // GeoViS has plane-triangle and plane-ring only; geovis adds the parallelogram with corners p1,
  // p2, p3 and p2 + p3 - p1 (a planar parallelogram), with plane-triangle's keys.
  const std::string pg =
      "(plane-parallelogram '(p1 #(0 0 0)) '(p2 #(3 0 0)) '(p3 #(1 2 0)) '(shader \"sh\") '(id \"pg\"))\n"
      "(add-object '(add-to \"scene\") '(obj \"pg\"))\n";
  const auto jobs = SceneBuilder(evaluate_scene_string(flat_scene(pg), "pg.scm"), {}).build(0);
  ASSERT_EQ(jobs.size(), 1u);
  // The fourth corner (4, 2, 0) lies beyond the triangle p1 p2 p3 (x <= 3).
  EXPECT_NEAR(jobs[0].job.scene->bounds().hi.x, 4.0, 1e-9);
  EXPECT_NEAR(jobs[0].job.scene->bounds().hi.y, 2.0, 1e-9);
  const std::string bad =
      "(plane-parallelogram '(p1 #(0 0 0)) '(p2 #(1 0 0)) '(p3 #(2 0 0)) '(id \"pg\"))\n"
      "(add-object '(add-to \"scene\") '(obj \"pg\"))\n";
  try {
    SceneBuilder(evaluate_scene_string(flat_scene(bad), "bad.scm"), {}).build(0);
    FAIL() << "collinear corners were accepted";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.scm:"), std::string::npos) << m;
    EXPECT_NE(m.find("collinear"), std::string::npos) << m;
  }
}

using testing_support::TempDir;

TEST(CatalogueCommands, TextureNamedByAnotherMachinesPathIsFoundByFileName) {
  // kastorTraschen.scm: (string-append homedir "/local/Texturen/sphereImageMaster_white.tif").
  TempDir t;
  Image img(4, 2, 3);
  for (float& v : img.pixels) v = 0.5f;
  write_image((t.path / "sky.tif").string(), img);
  const std::string tex =
      "(init-texture '(type \"Image\") '(file \"/no/such/home/local/Texturen/sky.tif\") '(id \"img\"))\n"
      "(init-shader '(type \"SurfShader\") '(objcolor \"img\") '(id \"skysh\"))\n"
      "(solid-ellipsoid '(axlen #(40 40 40)) '(shader \"skysh\") '(id \"sky\"))\n"
      "(add-object '(add-to \"scene\") '(obj \"sky\"))\n";
  Diagnostics diag;
  BuildOptions bo;
  bo.diag = &diag;
  bo.search_paths = {t.path.string()};
  SceneBuilder b(evaluate_scene_string(flat_scene(tex), "tex.scm"), bo);
  ASSERT_NO_THROW(b.build(0));
  ASSERT_EQ(diag.warnings().size(), 1u);
  const std::string& w = diag.warnings()[0];
  EXPECT_NE(w.find("tex.scm:14"), std::string::npos) << w;
  EXPECT_NE(w.find("/no/such/home/local/Texturen/sky.tif\" does not exist"), std::string::npos) << w;
  EXPECT_NE(w.find((t.path / "sky.tif").string()), std::string::npos) << w;

  // Relative names ("examples/eso0932a.tif" in fallEddFinkIn.scm) likewise.
  Diagnostics d2;
  bo.diag = &d2;
  std::string rel = tex;
  const std::string abs_name = "/no/such/home/local/Texturen/sky.tif";
  rel.replace(rel.find(abs_name), abs_name.size(), "examples/sky.tif");
  EXPECT_NO_THROW(SceneBuilder(evaluate_scene_string(flat_scene(rel), "rel.scm"), bo).build(0));
  EXPECT_EQ(d2.warnings().size(), 1u);

  // Without a file of that name in a search folder it stays an error naming the file.
  bo.search_paths = {(t.path / "elsewhere").string()};
  try {
    SceneBuilder(evaluate_scene_string(flat_scene(tex), "tex.scm"), bo).build(0);
    FAIL() << "missing texture accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot find texture image \"/no/such/home/local/Texturen/sky.tif\""),
              std::string::npos)
        << e.what();
  }
}

TEST(CatalogueCommands, MeshNamedByAnotherMachinesPathIsFoundByFileName) {
  TempDir t;
  std::ofstream(t.path / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                                       "f 1/1/1 2/2/1 3/3/1\n";
  const std::string mesh =
      "(mesh-obj '(filename \"tri.obj\") '(pathname \"/home/author/models\") '(shader \"sh\") '(id \"m\"))\n"
      "(add-object '(add-to \"scene\") '(obj \"m\"))\n";
  Diagnostics diag;
  BuildOptions bo;
  bo.diag = &diag;
  bo.search_paths = {t.path.string()};
  EXPECT_NO_THROW(SceneBuilder(evaluate_scene_string(flat_scene(mesh), "mesh.scm"), bo).build(0));
  ASSERT_EQ(diag.warnings().size(), 1u);
  EXPECT_NE(diag.warnings()[0].find("/home/author/models/tri.obj\" does not exist"), std::string::npos)
      << diag.warnings()[0];
}

}  // namespace
}  // namespace geovis
