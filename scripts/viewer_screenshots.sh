#!/usr/bin/env bash
# Screenshots of `geovis view` for docs/gallery/viewer/: runs the viewer's browser test
# (tests/cli/viewer/viewer_test.mjs) with its screenshots written there. Needs build/geovis and
# Debian's chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
node tests/cli/viewer/viewer_test.mjs --geovis build/geovis --source . --out build/viewer-screenshots \
  --screenshots docs/gallery/viewer
