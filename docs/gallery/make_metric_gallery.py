#!/usr/bin/env python3
"""Renders one thumbnail per registered metric into docs/gallery/metrics/ and writes the contact sheet
docs/gallery/metrics/README.md.

    docs/gallery/make_metric_gallery.py [GEOVIS]   # GEOVIS: the geovis binary (default build/geovis)

Every metric gets the same set-up (`geovis metrics --json` gives the names, sample positions and
coordinate types): the observer sits at the metric's sample position in its default natural tetrad
and looks along -e(1) (towards the centre for the spherical and cylindrical charts); the scene is a
sky sphere with a 10-degree grid, given in the metric's pseudo-Cartesian coordinates, of radius
max(20, 4 d) (d = the observer's pseudo-Cartesian distance from the origin), and a checkered ring
(radii 0.4 D .. 0.7 D, D = max(d, 5)) around the origin, normal to the x axis. Rays stop after 3000
points. 96 x 72 pixels, 60 x 45 degrees.

Status: the script runs (all metrics render, about 6 minutes on 2 busy cores), but the set-up is not
final: from the sample positions at r = 6 M the shadows of Schwarzschild-like metrics and of the
Curzon particle fill the 60-degree field, and the flat Kasner default (u = 0) sees only the t = 0
boundary of its Milne wedge, so those thumbnails are black. The observer should sit farther out
before the images are reviewed and committed.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
OUT = os.path.join(ROOT, "docs", "gallery", "metrics")


def pseudo_cartesian(pos, coord_type):
    """The observer's spatial point in pseudo-Cartesian coordinates (as Metric::to_pseudo_cartesian
    for the standard coordinate types; custom charts are treated as spherical)."""
    _, a, b, c = pos
    if coord_type == "cylinder":
        return (a * math.cos(b), a * math.sin(b), c)
    if coord_type in ("spherical", "custom"):
        return (a * math.sin(b) * math.cos(c), a * math.sin(b) * math.sin(c), a * math.cos(b))
    return (a, b, c)


def scene(metric):
    pos = metric["sample_position"]
    ctype = metric["coordinate_type"]
    p = pseudo_cartesian(pos, ctype)
    d = math.sqrt(sum(v * v for v in p))
    sky = max(20.0, 4.0 * d)
    ring = max(d, 5.0)
    # Camera frame in the natural tetrad: look along -e(1); up is -e(2) (= +theta-hat reversed, i.e.
    # north) for spherical charts and +e(3) (= z) for the others.
    if ctype == "spherical" or ctype == "custom":
        e = "'(e1 #(0.0 -1.0 0.0 0.0)) '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0))"
    else:
        e = "'(e1 #(0.0 -1.0 0.0 0.0)) '(e2 #(0.0 0.0 -1.0 0.0)) '(e3 #(0.0 0.0 0.0 1.0))"
    return f"""
(init-metric '(type "{metric['name']}") '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-6) '(step_size 0.01)
             '(id "raytracing"))
(init-camera '(type "PinHoleCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0)) '(fov #(60.0 45.0))
             '(res #(96 72)) '(filter "FilterRGB") '(id "cam"))
(init-raygen '(type "RayGenSimple") '(solver "raytracing") '(maxNumPoints 3000))
(local-tetrad '(pos #({pos[0]!r} {pos[1]!r} {pos[2]!r} {pos[3]!r}))
              '(e0 #(1.0 0.0 0.0 0.0)) {e}
              '(incoords #f) '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))
(init-texture '(type "UniTex") '(color #(0.08 0.10 0.25)) '(id "skyDark"))
(init-texture '(type "UniTex") '(color #(0.55 0.60 0.85)) '(id "skyLight"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "skyDark") '(texture "skyLight")
                                       `(transform ,(scale-obj #(36.0 18.0)))))
             '(ambient 1.0) '(id "skyShader"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0)) '(axlen #({sky} {sky} {sky}))
                 '(shader "skyShader") '(id "sky"))
(init-texture '(type "UniTex") '(color #(0.9 0.55 0.1)) '(id "ringA"))
(init-texture '(type "UniTex") '(color #(0.95 0.9 0.7)) '(id "ringB"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "ringA") '(texture "ringB")
                                       `(transform ,(scale-obj #(24.0 4.0)))))
             '(ambient 1.0) '(id "ringShader"))
(plane-ring `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0)) '(normal #(1.0 0.0 0.0))
            '(rin {0.4 * ring}) '(rout {0.7 * ring}) '(shader "ringShader") '(id "ring"))
(comp-object '(obj "sky") '(obj "ring") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
"""


def main():
    geovis = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("GEOVIS", os.path.join(ROOT, "build", "geovis"))
    geovis = os.path.abspath(geovis)
    if not os.access(geovis, os.X_OK):
        sys.exit(f"make_metric_gallery.py: no geovis binary at {geovis} (build it first)")
    metrics = json.loads(subprocess.run([geovis, "metrics", "--json"], check=True, capture_output=True,
                                        text=True).stdout)
    os.makedirs(OUT, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for m in metrics:
            name = m["name"]
            scm = os.path.join(tmp, name + ".scm")
            with open(scm, "w") as f:
                f.write(scene(m))
            png = os.path.join(OUT, name + ".png")
            r = subprocess.run([geovis, "render", scm, "-o", png, "--quiet"], capture_output=True, text=True)
            status = "ok" if r.returncode == 0 else "failed: " + r.stderr.strip().splitlines()[-1]
            print(f"{name}: {status}")
            rows.append((name, m["doc"], status))
    with open(os.path.join(OUT, "README.md"), "w") as f:
        f.write("# Metric gallery (contact sheet)\n\n")
        f.write("Generated by `docs/gallery/make_metric_gallery.py`: every metric with its default parameters, seen\n"
                "from its sample position (`geovis metrics`) along -e(1); grid-textured sky sphere and a checkered\n"
                "ring in the metric's pseudo-Cartesian coordinates. Black: no object hit (the ray ended at a\n"
                "horizon, a singularity or the chart edge, or left the scene).\n\n")
        f.write("| metric | image | description |\n|---|---|---|\n")
        for name, doc, status in rows:
            img = f"![{name}]({name}.png)" if status == "ok" else status
            f.write(f"| `{name}` | {img} | {doc} |\n")


if __name__ == "__main__":
    main()
