#!/bin/sh
# Regenerates the camera gallery docs/gallery/*.png (small PNGs, one per camera type, plus the three
# README images) from the repository's example scenes.
#
#   docs/gallery/make_gallery.sh [GEOVIS]      # GEOVIS: the geovis binary (default build/geovis,
#                                              # or the environment variable GEOVIS)
#
# Every image is rendered with 2x2 supersampling (the grid lines of the sky become thinner than a
# pixel near the photon ring and would alias into sparkles otherwise). About 1.5 min on 2 cores.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
geovis=${1:-${GEOVIS:-$root/build/geovis}}
case $geovis in /*) ;; *) geovis=$(pwd)/$geovis ;; esac
out=$root/docs/gallery
cd "$root"
[ -x "$geovis" ] || { echo "make_gallery.sh: no geovis binary at $geovis (build it first)" >&2; exit 1; }

render() { "$geovis" render "$@" --supersample 2 --quiet; }

# PinHoleCam: Schwarzschild black hole, thin checkered disk, grid sky (Einstein ring).
render examples/gallery/pinhole_schwarzschild.scm -o "$out/pinhole.png"
# PanoramaCam 360 x 100 deg at r = 5M: the shadow spans 107 deg of the horizon.
render examples/gallery/panorama_schwarzschild.scm -o "$out/panorama.png"
# 4PICam: Morris-Thorne wormhole, the whole sky of both universes (also the README's wormhole).
render examples/wormhole_4pi.scm -o "$out/fullsky_4pi.png"
# 2PICam dome looking at a Schwarzschild black hole from r = 8M.
render examples/gallery/dome_schwarzschild_hole.scm -o "$out/dome_2pi.png"
# PinHoleStereoCam: one device, two images stereo.left.png / stereo.right.png.
render examples/stereo_minkowski.scm --res 240x192 -o "$out/stereo.png"
# README row: Kerr disk (paper Fig. 3a) and the fall into a black hole (paper Fig. 7, tau = 34.8).
render examples/kerr_disk.scm -o "$out/kerr_disk.png"
render examples/fig7_fall_into_blackhole.scm --frames 6:6 --res 360x60 -o "$out/fall_into_blackhole.png"
# Paper Fig. 9 from the data file, without tracing again: Page-Thorne disk flux and 1+z.
tmp=$(mktemp -d)
"$geovis" render examples/fig9_disk_flux.scm -o "$tmp/fig9.png" --quiet
"$geovis" post "$tmp/fig9.exr" --shader disk-flux --colorbar -o "$out/fig9_disk_flux.png" --quiet
"$geovis" post "$tmp/fig9.exr" --shader redshift --colorbar -o "$out/fig9_redshift.png" --quiet
rm -r "$tmp"

ls -l "$out"/*.png
