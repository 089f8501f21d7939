// Each scene of the GeoViS fidelity set (tests/data/fidelity/, copied from GeoViS's
// examples with stand-in textures) renders, unchanged, to the picture GeoViS rendered from it
// (<scene>.geovis.png, GeoViS output), by the match rule of tests/data/fidelity/README.md
// (io/image_match.h). The render runs in-process at the scene's own resolution (its first frame);
// the scenes name their textures relative to their own folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/command.h"
#include "io/image.h"
#include "io/image_match.h"
#include "render/tracer.h"
#include "scene/builder.h"
#include "scene/scheme.h"
#include "spacetime/horizon.h"
#include "spacetime/kerr_mino.h"
#include "support/run_geovis.h"

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(GEOVIS_SOURCE_DIR) / "tests" / "data" / "fidelity";

class FidelityScene : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("geovis_fidelity_" + std::string(GetParam()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

using testing_support::run_args;

int to8(double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }
bool is_colour8(const float* p, const Color& c) {
  return to8(p[0]) == to8(c.r) && to8(p[1]) == to8(c.g) && to8(p[2]) == to8(c.b);
}

/// Rays into the hole that GeoViS paints with the background (kerrAccretionDisk_jac, the documented
/// difference "RGBjac rays at the edge of a black hole's shadow", docs/geovis-differences.md):
/// GeoViS's FilterRGBjac gives a ray that runs into the hole its constraint colour, except where its
/// Jacobi integration exhausts maxNumPoints first (the diverging Boyer–Lindquist components of the
/// Jacobi fields shrink the steps) — then it shows the background. Where the reference shows exactly
/// the background and our image exactly the constraint colour, this proves, independently of the
/// renderer, that the pixel's light ray falls into the hole: its Carter radial potential R(r) is
/// positive on all of [r₊(1 + 10⁻⁶), r_obs] and it starts inward, so r decreases monotonically to the
/// horizon (Carter, Phys. Rev. 174 (1968) 1559; KerrMinoConstants::radial_potential_positive_on), and
/// no object lies on its way (or, where that certificate is inconclusive, the geodesic integrated
/// without a scene stops at the horizon break radius). Such a pixel of the reference is set to the constraint colour;
/// any other difference is left for the match rule. Returns the number of corrected pixels; a differing pixel that
/// cannot be proven is a failure.
int correct_rays_into_the_hole(const fs::path& scene, const Image& image, Image& reference) {
  BuildOptions opts;
  opts.search_paths = {scene.parent_path().string()};
  SceneBuilder builder(evaluate_scene_file(scene.string()), opts);
  const RenderJob& job = builder.build(0).at(0).job;
  const Tracer tracer(job);
  const Color background = tracer.stop_color(StopReason::MaxSteps);
  const Color into_hole = tracer.stop_color(StopReason::Invalid);
  const Metric& m = *job.metric;
  const double M = m.param("mass"), a = m.param("angmom");
  const auto horizon = central_surface(m);
  EXPECT_TRUE(horizon.has_value());
  if (!horizon) return 0;
  const double r_obs = job.observer.pos[1];
  // Near the edge of the shadow R(r) nearly has a double root and the certificate may be
  // inconclusive: there the geodesic (Carter's equations in Mino time, no capture stop, no scene)
  // is integrated until it stops, which must be at the horizon break radius.
  auto falls_in = [&](const Vec4& k) {
    SolverConfig cfg = job.solver;
    cfg.type = GeodesicType::Lightlike;
    cfg.separable = true;
    cfg.capture_radius = 0;
    cfg.max_steps = 100000;
    double y[kMaxSystemDim] = {};
    for (int i = 0; i < 4; ++i) y[i] = job.observer.pos[i], y[4 + i] = k[i];
    const GeodesicResult r = m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
    return r.reason == StopReason::Invalid && y[1] < horizon->radius * 1.01;
  };
  int corrected = 0, unproven = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (!is_colour8(reference.at(x, y), background) || !is_colour8(image.at(x, y), into_hole)) continue;
      Vec3 d;
      if (!job.camera->direction(x + 0.5, y + 0.5, d)) continue;
      const Vec4 k = local_null_direction(job.observer.e, normalize(d), true);
      const KerrMinoConstants c = kerr_mino_constants(M, a, job.observer.pos, k, 0.0);
      if ((k[1] < 0 && c.radial_potential_positive_on(horizon->radius * (1 + 1e-6), r_obs)) || falls_in(k)) {
        float* p = reference.at(x, y);
        p[0] = float(into_hole.r), p[1] = float(into_hole.g), p[2] = float(into_hole.b);
        ++corrected;
      } else {
        ++unproven;
      }
    }
  EXPECT_EQ(unproven, 0) << "pixels where GeoViS shows the background and we the constraint colour, but the ray "
                            "is not proven to fall into the hole";
  return corrected;
}

TEST_P(FidelityScene, MatchesGeoViSReference) {
  const std::string name = GetParam();
  Image reference = read_image((kData / (name + ".geovis.png")).string());
  const std::string out = (dir_ / (name + ".png")).string();
  ::testing::internal::CaptureStderr();
  const auto start = std::chrono::steady_clock::now();
  const int rc = run_args({"render", (kData / (name + ".scm")).string(), "--frames", "0", "--threads", "2", "-o", out});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string err = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(rc, 0) << err;
  const Image image = read_image(out);
  int corrected = 0;
  if (name == "kerrAccretionDisk_jac")
    corrected = correct_rays_into_the_hole(kData / (name + ".scm"), image, reference);
  const ImageMatch m = match_images(image, reference);
  std::printf("%-22s %s (render %.1f s)", name.c_str(), m.summary().c_str(), seconds);
  if (corrected) std::printf(", %d reference pixels of rays into the hole set to the constraint colour", corrected);
  std::printf("\n");
  EXPECT_TRUE(m.matches) << name << ": " << m.summary();
}

INSTANTIATE_TEST_SUITE_P(GeoViSExamples, FidelityScene,
                         ::testing::Values("kerrAccretionDisk", "kerrAccretionDisk_jac", "movClock", "minkBall",
                                           "gridForApp", "appViewMovBall", "mtContactRings", "schwarzschild",
                                           "sphereAroundBlackhole", "minkWheel_mid"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

}  // namespace
}  // namespace geovis::cli
