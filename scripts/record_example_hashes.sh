#!/usr/bin/env bash
# Re-records tests/data/examples/pixel_hashes.txt: the pixel hashes of every examples/*.scm at
# 24x18 (first frame), which the test ExamplePicture.IsPixelIdenticalToTheRecordedOne compares
# against. Run it only for a change that is meant to change pictures, and say why in the commit.
# Usage: scripts/record_example_hashes.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
cmake --build "$build" --target test_cli
out=tests/data/examples/pixel_hashes.txt
mkdir -p "$(dirname "$out")"
rm -f "$out".*
GEOVIS_RECORD_EXAMPLE_HASHES=1 "$build"/tests/test_cli --gtest_filter='Examples/ExamplePicture.*' >/dev/null
cat "$out".* | sort > "$out"
rm -f "$out".*
git --no-pager diff --stat -- "$out" || true
echo "recorded $(wc -l < "$out") example hashes in $out"
