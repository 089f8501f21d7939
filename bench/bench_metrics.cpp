// Cost of one evaluation of the Christoffel symbols, closed form against automatic
// differentiation, for every registered metric at its sample position (nudged a little per call
// so nothing is cached): `geovis_bench --benchmark_filter=BM_Christoffel`. The ratio AD/closed is
// the criterion of docs/PERFORMANCE.md ("Metrics") for metrics that could do without a closed form.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "spacetime/metric_registry.h"

namespace {

using namespace geovis;

void christoffel_bench(benchmark::State& state, bool ad) {
  const auto names = metric_names();
  const std::string name = names[static_cast<size_t>(state.range(0))];
  const auto m = make_metric(name);
  state.SetLabel(name);
  Vec4 x = m->info().sample_pos;
  Christoffel G;
  double nudge = 1e-9;
  for (auto _ : state) {
    x[1] += nudge;
    nudge = -nudge;
    if (ad)
      m->christoffel_ad(x, G);
    else
      m->christoffel(x, G);
    benchmark::DoNotOptimize(G);
  }
}

void BM_ChristoffelClosed(benchmark::State& state) { christoffel_bench(state, false); }
void BM_ChristoffelAD(benchmark::State& state) { christoffel_bench(state, true); }

void every_metric(benchmark::internal::Benchmark* b) {
  for (size_t i = 0; i < metric_names().size(); ++i) b->Arg(static_cast<int>(i));
}

}  // namespace

BENCHMARK(BM_ChristoffelClosed)->Apply(every_metric);
BENCHMARK(BM_ChristoffelAD)->Apply(every_metric);
