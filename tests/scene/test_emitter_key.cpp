// The geovis plane-ring key `emitter` (render/plugins.cpp): "keplerian" makes a thin disk of matter
// on circular geodesics whose velocity enters 1+z; only in the equatorial plane of spherical
// coordinates; GeoViS scenes (no key) keep the disk at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/error.h"
#include "render/shapes.h"
#include "render/tracer.h"
#include "scene/builder.h"
#include "scene/scheme.h"

namespace geovis {
namespace {

std::string disk_scene(const std::string& metric, const std::string& ring_keys) {
  return "(init-metric '(type \"" + metric +
         "\") '(id \"metric\"))\n"
         "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(id \"s\"))\n"
         "(init-camera '(type \"PinHoleCam\") '(res #(8 6)) '(id \"cam\"))\n"
         "(init-raygen '(type \"RayGenSimple\") '(solver \"s\"))\n"
         "(local-tetrad '(pos #(0 40 1.3 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0))\n"
         "              '(e3 #(0 0 0 1)) '(incoords #f) '(id \"obs\"))\n"
         "(init-projector '(localtetrad \"obs\") '(id \"proj\"))\n"
         "(plane-ring '(rin 6.0) '(rout 15.0) " +
         ring_keys +
         " '(id \"disk\"))\n"
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
  EXPECT_NE(
      build_error(disk_scene("Schwarzschild", "'(emitter \"keplerian\") '(normal #(1 0 0))")).find("equatorial plane"),
      std::string::npos);
  EXPECT_NE(
      build_error(disk_scene("Schwarzschild", "'(emitter \"keplerian\") '(center #(0 0 1))")).find("equatorial plane"),
      std::string::npos);
}

TEST(EmitterVelocity, LocalObjectOnItsMotionGivesTheRelativisticDoppler) {
  // Minkowski: a sphere moving with β along the line of sight, seen head-on by an observer at
  // rest. 1+z = ω_src/ω_obs = √((1 − β)/(1 + β)) when it approaches and √((1 + β)/(1 − β)) when it
  // recedes (longitudinal relativistic Doppler effect, e.g. Rindler, Relativity (2006) eq. 4.45).
  for (const double beta : {0.5, -0.5}) {  // velocity along −x: towards the observer at x = −10
    const std::string scene =
        "(init-metric '(type \"Minkowski\") '(id \"metric\"))\n"
        "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(id \"s\"))\n"
        "(init-camera '(type \"PinHoleCam\") '(dir #(1 0 0)) '(vup #(0 0 1)) '(res #(9 9)) '(id \"cam\"))\n"
        "(init-raygen '(type \"RayGenSimple\") '(solver \"s\")\n"
        "  `(boundBoxLL ,(vector (- gpDBLMAX) -50.0 -50.0 -50.0)) `(boundBoxUR ,(vector gpDBLMAX 50.0 50.0 50.0)))\n"
        "(local-tetrad '(pos #(0 -10 0 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0)) '(e3 #(0 0 0 1))\n"
        "  '(incoords #f) '(id \"obs\"))\n"
        "(init-projector '(localtetrad \"obs\") '(id \"proj\"))\n"
        "(init-motion '(type \"ConstVelocity\") '(boost #(" +
        std::to_string(-beta) +
        " 0 0)) '(id \"move\"))\n"
        "(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(axlen #(1 1 1)) '(motion \"move\") '(id \"ball\"))\n"
        "(init-device '(type \"standard\") '(obj \"ball\") '(camera \"cam\"))\n";
    SceneBuilder b(evaluate_scene_string(scene, "moving.scm"), BuildOptions{});
    const auto jobs = b.build(0);
    const Tracer tracer(jobs.at(0).job);
    TraceStats st;
    const TraceResult r = tracer.trace_direction(Vec3{1, 0, 0}, st);
    ASSERT_TRUE(r.hit) << beta;
    EXPECT_NEAR(r.freqshift, std::sqrt((1 - beta) / (1 + beta)), 1e-9) << beta;
  }
}

}  // namespace
}  // namespace geovis
