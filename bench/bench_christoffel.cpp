// Cost of one evaluation of the Christoffel symbols of every registered metric, closed form against
// automatic differentiation (the fallback), at the metric's sample position (moved by 1e-12 in x^0
// each call so nothing is hoisted): `build/bench/geovis_bench --benchmark_filter=BM_Christoffel`.
// The rule for metrics (docs/PERFORMANCE.md, "Metrics"): automatic differentiation is acceptable
// only within 2× of a closed form.
#include <benchmark/benchmark.h>

#include <string>

#include "spacetime/metric_registry.h"

namespace {

using namespace geovis;

void christoffel_cost(benchmark::State& state, const std::string& name, bool ad) {
  const auto m = make_metric(name);
  Vec4 x = m->info().sample_pos;
  Christoffel G;
  for (auto _ : state) {
    x[0] += 1e-12;
    if (ad)
      m->christoffel_ad(x, G);
    else
      m->christoffel(x, G);
    benchmark::DoNotOptimize(G);
  }
}

const int registered = [] {
  for (const std::string& n : metric_names())
    for (bool ad : {false, true})
      benchmark::RegisterBenchmark(("BM_Christoffel/" + n + (ad ? "/ad" : "/closed")).c_str(),
                                   [n, ad](benchmark::State& s) { christoffel_cost(s, n, ad); })
          ->Unit(benchmark::kNanosecond);
  return 0;
}();

}  // namespace
