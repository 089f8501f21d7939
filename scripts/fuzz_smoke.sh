#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang, AddressSanitizer and UndefinedBehaviorSanitizer in
# their own build folder (only the targets and the libraries they need) and runs each for a fixed
# time on its seed corpus. Exits non-zero when a run finds a crash, a leak, a sanitizer report or a
# timeout (the input is kept as BUILD_DIR/crash-<target>-*). CTest runs it as the test fuzz_smoke.
# Usage: scripts/fuzz_smoke.sh BUILD_DIR [SECONDS_PER_TARGET]
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build="$1"
seconds="${2:-30}"
command -v clang++ > /dev/null || { echo "fuzz_smoke: clang++ is not installed (scripts/setup.sh installs it)"; exit 1; }
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

start=$(date +%s)
# -O1: the usual optimisation for sanitizer builds (fast to compile, accurate reports); a UB report
# aborts the run (-fno-sanitize-recover) so that the fuzzer counts it as a crash.
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" -DCMAKE_CXX_FLAGS="-fno-sanitize-recover=all" \
  -DGEOVIS_FUZZ=ON -DGEOVIS_SANITIZE=address,undefined -DGEOVIS_BUILD_TESTS=OFF -DGEOVIS_BUILD_BENCH=OFF \
  "${launcher[@]}" > "$build.log" 2>&1 || { cat "$build.log"; exit 1; }
cmake --build "$build" --target fuzz_scene fuzz_files -j "$(nproc)" >> "$build.log" 2>&1 || { tail -n 60 "$build.log"; exit 1; }
echo "fuzz_smoke: built in $(( $(date +%s) - start )) s"

export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$src/fuzz/lsan.supp"
status=0
for target in fuzz_scene fuzz_files; do
  corpus="$build/corpus/$target"
  rm -rf "$corpus"
  mkdir -p "$corpus"
  if [ "$target" = fuzz_scene ]; then
    cp "$src"/tests/data/geovis/scenes/*.scm "$src"/tests/scene/broken/*.scm "$src"/examples/*.scm "$corpus/"
  else
    cp "$src/fuzz/corpus/$target/"* "$corpus/"
  fi
  start=$(date +%s)
  # -timeout: one input may take 10 s (the scene's own time limit is 2 s); -rss_limit_mb: the
  # scene's memory limit is 256 MiB, Guile and the sanitizers add their own.
  if ! (cd "$build" && "$build/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=3072 \
          -print_final_stats=1 -artifact_prefix="$build/crash-$target-" "$corpus" > "$build/$target.log" 2>&1); then
    echo "fuzz_smoke: $target FAILED; the end of its log ($build/$target.log):"
    tail -n 80 "$build/$target.log"
    status=1
  else
    echo "fuzz_smoke: $target ran $(( $(date +%s) - start )) s: $(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$build/$target.log" | grep -o '[0-9]*$') inputs, no finding"
  fi
done
exit $status
