// libFuzzer target over the scene pipeline: Scheme text -> evaluate_scene_string (in the sandbox)
// -> SceneBuilder -> build(device 0). Any geovis::Error is an expected outcome for malformed input; a crash, a
// sanitizer report, a leak or an exception of another type is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/builder.h"
#include "scene/scheme.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 16384) return 0;  // scenes are small; keep executions fast
  const std::string text(reinterpret_cast<const char*>(data), size);
  geovis::Diagnostics diag;
  geovis::SchemeOptions opts;
  opts.diag = &diag;
  opts.max_calls = 2000;
  opts.time_limit_seconds = 2.0;                // endless Scheme loops are the scene's problem, not a finding
  opts.memory_limit_bytes = size_t{256} << 20;  // so is an unbounded allocation
  opts.print_output = false;
  try {
    geovis::SceneDescription scene = geovis::evaluate_scene_string(text, "fuzz.scm", opts);
    geovis::BuildOptions bopts;
    bopts.diag = &diag;
    bopts.resolution = std::make_pair(4, 4);
    geovis::SceneBuilder builder(std::move(scene), bopts);
    if (builder.device_count() > 0) (void)builder.build(0);
  } catch (const geovis::Error&) {
  }
  return 0;
}
