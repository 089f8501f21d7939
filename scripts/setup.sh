#!/usr/bin/env bash
# Installs every build and run-time dependency (Debian 12 packages) and builds geovis in ./build.
# Run as root on a fresh Debian 12 machine (or with sudo). Idempotent: re-running only rebuilds.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  g++ cmake ninja-build pkg-config git
  guile-3.0-dev            # the Scheme scene language
  libpng-dev libtiff-dev libjpeg62-turbo-dev libopenexr-dev  # image files: PNG, TIFF, JPEG, OpenEXR
  libnetpbm-dev libstb-dev # image files: PBM/PGM/PPM/PAM (Netpbm), Radiance HDR (stb_image)
  libfreetype-dev          # labels of geovis post --colorbar
  libcli11-dev             # command line
  nlohmann-json3-dev       # JSON output
  libtinyobjloader-dev     # Wavefront OBJ meshes
  libgtest-dev             # tests
  libbenchmark-dev libgsl-dev  # benchmarks (GSL is the reference integrator)
  ffmpeg                   # --movie (optional at run time)
  clang libclang-rt-14-dev # the fuzz_smoke test: libFuzzer, AddressSanitizer, UndefinedBehaviorSanitizer
  libopenmpi-dev openmpi-bin  # rendering on several MPI ranks (mpirun; optional)
  fonts-dejavu-core        # labels of geovis post --colorbar
  libtinyexr-dev           # tests: an OpenEXR reader independent of the OpenEXR library, for the data files
  libcpp-httplib-dev       # geovis view: the local HTTP server
  libhwy-dev               # Google Highway: SIMD packets of rays with runtime dispatch
  chromium                 # the viewer's browser tests (headless, driven by Playwright)
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# geovis view builds its page (web/: TypeScript, vite, three.js) with npm at build time. Debian's
# nodejs (18) and npm (9) do; a machine that already has Node.js with its own npm (e.g. from
# NodeSource) keeps it: Debian's npm package would conflict with it.
command -v npm > /dev/null || missing+=(nodejs npm)
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)" >> build.log 2>&1 || { tail -n 80 build.log; exit 1; }
echo "geovis built: build/geovis (build log: build.log)"
