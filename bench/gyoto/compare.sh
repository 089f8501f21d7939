#!/usr/bin/env bash
# Gyoto against geovis on the same view, one thread each, side by side (README.md in this folder).
# Usage: bench/gyoto/compare.sh path/to/geovis [repeats]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
geovis="$(realpath "${1:?usage: compare.sh path/to/geovis [repeats]}")"
repeats="${2:-3}"
command -v gyoto > /dev/null || { echo "compare.sh: gyoto is not installed (apt-get install gyoto-bin)"; exit 1; }
[ -x /usr/bin/time ] || { echo "compare.sh: /usr/bin/time is not installed (apt-get install time)"; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$here/gyoto-kerr-disk.xml" "$here/gyoto-kerr-disk.scm" "$work/"
cd "$work"

# run NAME COMMAND...: appends "wall cpu" of one run to NAME.times
run() {
  local name="$1"
  shift
  /usr/bin/time -f "%e %U %S" -o "$name.one" "$@" > "$name.log" 2>&1 || { cat "$name.log"; exit 1; }
  awk '{ printf "%s %.3f\n", $1, $2 + $3 }' "$name.one" >> "$name.times"
}
for ((i = 0; i < repeats; ++i)); do
  rm -f out.fits
  run gyoto gyoto -T1 -r128 gyoto-kerr-disk.xml '!out.fits'
  run geovis "$geovis" render gyoto-kerr-disk.scm --threads 1 -q -o geovis.png
done
best() { sort -n -k"$2" "$1.times" | head -n1 | awk -v k="$2" '{ print $k }'; }
gw=$(best gyoto 1) gc=$(best gyoto 2) vw=$(best geovis 1) vc=$(best geovis 2)
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) CPUs, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "gyoto  $(gyoto --version 2>&1 | head -n1 | tr -d '\n'): best of $repeats: wall ${gw} s, CPU ${gc} s"
echo "geovis $("$geovis" --version): best of $repeats: wall ${vw} s, CPU ${vc} s"
awk -v a="$gw" -v b="$vw" -v c="$gc" -v d="$vc" \
  'BEGIN { printf "geovis is %.1fx faster in wall time, %.1fx in CPU time (goal: 100x)\n", a / b, c / d }'
