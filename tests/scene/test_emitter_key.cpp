// The geovis plane-ring key `emitter` (render/plugins.cpp): "keplerian" makes a thin disk of matter
// on circular geodesics whose velocity enters 1+z; only in the equatorial plane of spherical
// coordinates; GeoViS scenes (no key) keep the disk at rest.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/error.h"
#include "render/shapes.h"
#include "scene/builder.h"
#include "scene/scheme.h"

namespace geovis {
namespace {

std::string disk_scene(const std::string& metric, const std::string& ring_keys) {
  return "(init-metric '(type \"" + metric + "\") '(id \"metric\"))\n"
         "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(id \"s\"))\n"
         "(init-camera '(type \"PinHoleCam\") '(res #(8 6)) '(id \"cam\"))\n"
         "(init-raygen '(type \"RayGenSimple\") '(solver \"s\"))\n"
         "(local-tetrad '(pos #(0 40 1.3 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0))\n"
         "              '(e3 #(0 0 0 1)) '(incoords #f) '(id \"obs\"))\n"
         "(init-projector '(localtetrad \"obs\") '(id \"proj\"))\n"
         "(plane-ring '(rin 6.0) '(rout 15.0) " + ring_keys + " '(id \"disk\"))\n"
         "(init-device '(type \"standard\") '(obj \"disk\"))\n";
}

std::shared_ptr<const PlaneRing> build_ring(const std::string& text, Diagnostics* diag = nullptr) {
  BuildOptions bo;
  bo.diag = diag;
  SceneBuilder b(evaluate_scene_string(text, "disk.scm"), bo);
  const auto jobs = b.build(0);
  return std::dynamic_pointer_cast<const PlaneRing>(jobs.at(0).job.scene);
}

std::string build_error(const std::string& text) {
  try {
    build_ring(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(EmitterKey, KeplerianDiskOrAtRest) {
  Diagnostics strict;
  strict.strict = true;
  auto ring = build_ring(disk_scene("Schwarzschild", "'(emitter \"keplerian\")"), &strict);
  ASSERT_TRUE(ring);
  EXPECT_TRUE(ring->keplerian_disk);
  ring = build_ring(disk_scene("KerrBL", "'(emitter \"Keplerian\")"));
  ASSERT_TRUE(ring);
  EXPECT_TRUE(ring->keplerian_disk);
  ring = build_ring(disk_scene("Schwarzschild", "'(emitter \"rest\")"));
  EXPECT_FALSE(ring->keplerian_disk);
  ring = build_ring(disk_scene("Schwarzschild", ""));  // GeoViS scenes: at rest
  EXPECT_FALSE(ring->keplerian_disk);
}

TEST(EmitterKey, ClearErrors) {
  EXPECT_NE(build_error(disk_scene("Schwarzschild", "'(emitter \"keplerain\")")).find("did you mean \"keplerian\""),
            std::string::npos);
  EXPECT_NE(build_error(disk_scene("Minkowski", "'(emitter \"keplerian\")")).find("spherical coordinates"),
            std::string::npos);
  EXPECT_NE(build_error(disk_scene("Schwarzschild", "'(emitter \"keplerian\") '(normal #(1 0 0))"))
                .find("equatorial plane"),
            std::string::npos);
  EXPECT_NE(build_error(disk_scene("Schwarzschild", "'(emitter \"keplerian\") '(center #(0 0 1))"))
                .find("equatorial plane"),
            std::string::npos);
}

}  // namespace
}  // namespace geovis
