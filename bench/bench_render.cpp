// Rendering throughput (pixels/s) of two reference scenes on 1 and 2 threads; see the "Rendering"
// section of docs/PERFORMANCE.md. Run:
//   cmake --build build --target geovis_bench && build/bench/geovis_bench --benchmark_filter=Render
//
// Scenes (256x256, FilterRGB, Cash-Karp, maxNumPoints 3000):
//   schwarzschild: M = 1, static observer at r = 30 (θ = 80°) looking at the hole, a background
//     sphere r = 50 and a thin disk 6 <= r <= 15, eps_abs = 1e-8 (as GeoViS's examples);
//   kerr: KerrBL M = 1, a = 0.9, observer r = 50, θ = 80°, fov 38° (GeoViS kerrAccretionDisk.scm),
//     disk 3 <= r <= 12, bounding box r < 70, eps_abs = 1e-8.
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cmath>
#include <numbers>

#include "render/pinhole_camera.h"
#include "render/plugins.h"
#include "render/renderer.h"
#include "spacetime/metric_registry.h"

namespace geovis {
namespace {

constexpr int kRes = 256;

ParamSet params(const char* cmd, std::initializer_list<std::pair<const char*, Value>> kv) {
  ParamSet ps(cmd, {});
  for (const auto& [k, v] : kv) ps.add(k, v);
  return ps;
}

/// Two uniform SurfShaders ("disk", "sky") in ctx.
void add_shaders(BuildContext& ctx) {
  ctx.textures["tdisk"] =
      make_texture(params("init-texture", {{"type", "UniTex"}, {"color", std::vector<double>{0.8, 0.16, 0.16}}}), ctx);
  ctx.textures["tsky"] =
      make_texture(params("init-texture", {{"type", "UniTex"}, {"color", std::vector<double>{0.3, 0.3, 0.6}}}), ctx);
  ctx.shaders["disk"] = make_shader(params("init-shader", {{"type", "SurfShader"}, {"objcolor", "tdisk"}}), ctx);
  ctx.shaders["sky"] = make_shader(params("init-shader", {{"type", "SurfShader"}, {"objcolor", "tsky"}}), ctx);
}

SceneObjectPtr disk(BuildContext& ctx, double rin, double rout) {
  return make_object(params("plane-ring", {{"objtype", 1},
                                           {"center", std::vector<double>{0, 0, 0}},
                                           {"normal", std::vector<double>{0, 0, 1}},
                                           {"rin", rin},
                                           {"rout", rout},
                                           {"shader", "disk"},
                                           {"id", "disk"}}),
                     ctx);
}

RenderJob observer_job(std::shared_ptr<const Metric> m, double r_obs, double fov) {
  RenderJob job;
  job.metric = m;
  job.observer.pos = Vec4{{0, r_obs, 80 * std::numbers::pi / 180, 0}};
  job.observer.e = m->natural_tetrad(job.observer.pos, TetradKind::Default);
  job.camera = std::make_shared<PinholeCamera>(Vec3{-1, 0, 0}, Vec3{0, 0, 1}, fov, fov, kRes, kRes);
  job.background = Color{0.2, 0.2, 0.2};
  job.solver.kind = SolverKind::CashKarp45;
  job.solver.eps_abs = 1e-8;
  job.solver.max_steps = 3000;
  return job;
}

RenderJob schwarzschild_scene() {
  auto m = std::shared_ptr<const Metric>(make_metric("Schwarzschild"));
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  ctx.metric = m;
  add_shaders(ctx);
  RenderJob job = observer_job(m, 30, 50);
  ctx.objects["disk"] = disk(ctx, 6, 15);
  ctx.objects["sky"] = make_object(params("solid-ellipsoid", {{"objtype", 1},
                                                              {"center", std::vector<double>{0, 0, 0}},
                                                              {"axlen", std::vector<double>{50, 50, 50}},
                                                              {"shader", "sky"},
                                                              {"id", "sky"}}),
                                   ctx);
  ParamSet comp("comp-object", {});
  comp.add("obj", "disk");
  comp.add("obj", "sky");
  comp.add("id", "scene");
  job.scene = make_object(comp, ctx);
  job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
  job.solver.box_ur = Vec4{{1e300, 60, 1e300, 1e300}};
  return job;
}

RenderJob kerr_scene() {
  std::shared_ptr<Metric> kerr = make_metric("KerrBL");
  kerr->set_param("angmom", 0.9);
  auto m = std::shared_ptr<const Metric>(std::move(kerr));
  BuildContext ctx;
  Diagnostics diag;
  ctx.diag = &diag;
  ctx.metric = m;
  add_shaders(ctx);
  RenderJob job = observer_job(m, 50, 38);
  job.scene = disk(ctx, 3, 12);
  job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
  job.solver.box_ur = Vec4{{1e300, 70, 1e300, 1e300}};
  return job;
}

/// CPU seconds used by the whole process so far (all threads; the benchmark's own CPU column
/// only covers the main thread).
double process_cpu_seconds() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

/// separable: the Mino-time (Carter) equations for these two metrics (default), else the
/// coordinate geodesic equation as GeoViS integrates it.
void BM_Render(benchmark::State& state, RenderJob (*make)(), int threads, bool separable) {
  RenderJob job = make();
  job.solver.separable = separable;
  RenderOptions opt;
  opt.threads = threads;
  opt.progress = false;
  RenderStats stats;
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    RenderResult r = render(job, opt);
    benchmark::DoNotOptimize(r.image.pixels.data());
    stats = r.stats;
  }
  const double cpu = (process_cpu_seconds() - cpu0) / double(state.iterations());
  const double px = double(kRes) * kRes;
  // Throughput per core from the CPU time of all render threads: independent of other load.
  state.counters["px/cpu-s"] = px / cpu;
  state.counters["cpu-s"] = cpu;
  state.counters["px/s"] = benchmark::Counter(px * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["steps/ray"] = double(stats.steps) / double(stats.rays);
  state.counters["rhs/ray"] = double(stats.rhs_evals) / double(stats.rays);
}

BENCHMARK_CAPTURE(BM_Render, schwarzschild_1thread, &schwarzschild_scene, 1, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Render, schwarzschild_2threads, &schwarzschild_scene, 2, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Render, schwarzschild_1thread_coordinates, &schwarzschild_scene, 1, false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Render, kerr_1thread, &kerr_scene, 1, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Render, kerr_2threads, &kerr_scene, 2, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Render, kerr_1thread_coordinates, &kerr_scene, 1, false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

}  // namespace
}  // namespace geovis

// Weak, so that another bench file may provide the program's main() instead.
__attribute__((weak)) int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
