#!/usr/bin/env python3
"""Renders one thumbnail per registered metric into docs/gallery/metrics/ and writes the contact sheet
docs/gallery/metrics/README.md (issue #15, item 5).

    nice -n 10 docs/gallery/make_metric_gallery.py [GEOVIS] [--only NAME,NAME,... [--update-sheet]]

GEOVIS is the geovis binary (default $GEOVIS, else build/geovis). `--only` re-renders some metrics
(for looking at a set-up); the contact sheet is then not rewritten, unless --update-sheet is given:
then the rows of the re-rendered metrics are replaced (new metrics added in registry order) and the
other rows are kept as they are, with their notes refreshed from NOTES.

The same set-up for every metric (names, coordinate types, parameters and sample positions come from
`geovis metrics --json`, so metrics added later are rendered too):

* the observer sits at the metric's viewing position (VIEW below; default: the sample position
  moved out along the same direction to a pseudo-Cartesian distance of 20, see view_position) at
  rest in the metric's default natural tetrad, and looks at the pseudo-Cartesian origin, "up" being
  +z (-e_theta for the spherical charts);
* a sky sphere of pseudo-Cartesian radius max(20, 4 d) (d = the observer's pseudo-Cartesian
  distance from the origin) with a 10-degree checker grid;
* a checkered ring around the origin with radii 0.2 d .. 0.35 d (11 .. 19 degrees from the centre
  of the image in flat space), its normal tilted by 27 degrees from the line of sight towards "up",
  so that the lensed far side shows above the near side;
* 96 x 72 pixels, 60 x 45 degrees pinhole camera, Cash-Karp RK with eps_abs 1e-6, at most 3000
  points per ray, no coordinate bounding box (GeoViS' default box |x^i| < 50 would cut rays off
  before they reach a sky sphere of radius 80; a ray that leaves every object's bounds for good
  stops as "escaped"); colours are the texture colours (ambient light only, no redshift), and black is
  the projector's colour where no object was hit.

Every image is rendered with --data; the stop reason and colour of every pixel are read back with
`geovis post --csv`. The script fails if a pixel is NaN, and it reports how the rays ended (hit,
horizon = the metric's break condition, escaped, ...) in the contact sheet, so that a black region
can be traced to its cause. NOTES holds the one-line explanation written after looking at each
thumbnail; a metric without a note (a new one) is marked "not yet looked at".
"""
import csv
import glob
import io
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
OUT = os.path.join(ROOT, "docs", "gallery", "metrics")
GENERIC_DISTANCE = 20.0  # far enough that a Schwarzschild shadow (M = 1) covers ~28 of the 60 degrees

# Per-metric viewing positions (coordinates as in `geovis metrics`), where the default (sample position
# moved out to distance 20) is not sensible. Each entry: (position or None = the sample position,
# sky radius or None = the default, why).
VIEW = {
    "MorrisThorne": ((0.0, 8.0, math.pi / 2, 0.0), None, "l = 8 b0: the throat fills ~15 degrees"),
    "TeoSimpleWH": ((0.0, 8.0, math.pi / 2, 0.0), None, "l = 8 b0: the throat fills ~15 degrees"),
    "TeoWHl": ((0.0, 8.0, math.pi / 2, 0.0), None, "l = 8 b0: the throat fills ~15 degrees"),
    # Kottler (Lambda = 0.05): the static region is 2.17 < r < 6.43; the chart ends at the
    # cosmological horizon, so the sky must lie inside it.
    # From r = 5 the shadow (critical impact parameter 3 sqrt(3) M / sqrt(1 - 9 Lambda M^2) = 7.0)
    # is 37 degrees in radius and fills the field; it is smallest near the cosmological horizon.
    "Kottler": ((0.0, 6.0, math.pi / 2, 0.0), 6.3, "static region 2.17 < r < 6.43: r = 6, sky at r = 6.3"),
    # Kasner (default u = 0: flat, a Milne-type wedge): the past light cone of an event at time t
    # reaches the t = 0 boundary after a coordinate distance ~t, so the observer must be late.
    "Kasner": ((200.0, 20.0, 0.0, 0.0), None, "t = 200: the past light cone reaches the sky before t = 0"),
    # Dust-filled FLRW universes (big bang at conformal time 0): the particle horizon at conformal
    # time chi is chi, so the observer must be late enough to see the sky at 80 + 20.
    "FriedmanNonEmptyNull": ((200.0, 20.0, math.pi / 2, 0.0), None, "chi = 200: particle horizon beyond the sky"),
    "SultanaDyerBlackhole": ((200.0, 20.0, math.pi / 2, 0.0), None, "t = 200: particle horizon beyond the sky"),
    # Kruskal X = 100 is Schwarzschild r = 14.6 M at T = 0 ((r/2M - 1) e^(r/2M) = X^2 - T^2).
    # Kruskal: X = 20 at T = 0 is r = 9.37 M ((r/2M - 1) e^(r/2M) = X^2 - T^2); the objects are
    # placed by areal radius (Kruskal::to_pseudo_cartesian), and the sky at r = 12 M (X = 45), since
    # X grows like e^(r/4M) and rays to a farther sky exhaust the 3000-point budget.
    "Kruskal": ((0.0, 20.0, math.pi / 2, 0.0), 12.0, "X = 20 (r = 9.37 M), sky at r = 12 M"),
    # Goedel: light from an observer never gets farther than the Goedel radius r_G = 2a (rg in the
    # scaled charts) from him; observer at r_G / 2.
    "Goedel": ((0.0, 1.0, 0.0, 0.0), None, "r = r_G / 2"),
    "GoedelCart": ((0.0, 1.0, 0.0, 0.0), None, "x = r_G / 2"),
    "GoedelScaled": ((0.0, 0.5, 0.0, 0.0), None, "R = r_G / 2"),
    "GoedelScaledCart": ((0.0, 0.5, 0.0, 0.0), None, "X = r_G / 2"),
    # Einstein static universe: xi is bounded by pi (the antipode, spatial infinity of Minkowski).
    "MinkowskiConformal": (None, 3.0, "xi <= pi: sky at xi = 3"),
    # Charts whose spatial coordinates are bounded or not radial: the sample position.
    "BertottiKasner": (None, None, "sample position"),
    "Petrov_Type_D_AII_ES": (None, None, "sample position (0 < z < b)"),
    "Petrov_Type_D_AIII_ES": (None, None, "sample position"),
    "Petrov_Type_D_BII_ES": (None, None, "sample position (0 < z < b)"),
    "Petrov_Type_D_BIII_ES": (None, None, "sample position"),
    "Pravda_C-Metric": (None, None, "sample position"),
    # SchwarzschildGravWave (epsilon = 0.1, sigma = 1): g_tt = -f (1 + epsilon X cos(sigma t)) with
    # epsilon X ~ -0.1 r far out, so the line element keeps its signature at every t only for
    # epsilon |X| < 1, r < 8.8 M (schwarzschild_grav_wave.cpp is_valid); the rays run back through
    # all phases of the wave, so observer and sky must lie inside.
    "SchwarzschildGravWave": ((0.0, 8.0, math.pi / 2, 0.0), 8.5, "r = 8 (epsilon |X| < 1 needs r < 8.8 M), sky at r = 8.5"),
    # Petrov_Type_D_C_ES: every light ray of the static region, sent any way, ends at the horizon
    # G(y) = 0, y = 1.3247, (the note in NOTES), so the objects must lie inside the static region
    # around the observer: a sky sphere of radius 1.4 around (x, y, phi) = (1, 3, 0) (CUSTOM_FRAMES).
    # PlaneGravWave: the objects are at rest before the wave (u = t - x < -a) and u only decreases
    # along a light ray traced back, so an observer at t = 0, x = 20 (u = -20) sees only the flat
    # region before the wave; at t = 20.5 (u = 0.5) the wave has passed the ring and the observer,
    # and the past light cone crosses it.
    "PlaneGravWave": ((20.5, 20.0, 0.0, 0.0), None, "t = 20.5: u = t - x = 0.5, behind the wave (-1 <= u <= 0)"),
    "Petrov_Type_D_C_ES": ((0.0, 0.0, 1.0, 2.0), 1.4, "(x, y) = (1, 2), sky of radius 1.4 around (x, y) = (1, 3), looking along +y (CUSTOM_FRAMES)"),
}

# One line per metric, written after looking at its thumbnail: what the image shows and, for black
# or empty parts, why (the physics, from the stop reasons).
NOTES = {
    "Minkowski": "flat: undistorted grid, ring as an ellipse (tilted 27 degrees)",
    "Schwarzschild": "black disk: the shadow (rays end at the horizon), radius asin(3 sqrt(3) M sqrt(1-2M/r)/r) = 14 degrees at r = 20 M; secondary ring images at its rim",
    "KerrBL": "shadow slightly flattened and shifted by the spin a = 0.5",
    "MorrisThorne": "no horizon: the ring and, inside it, our sky seen around the throat; black centre: rays through the throat into the other universe (l < 0), which is empty (the objects are in chart 0, l > 0), where they escape",
    "TeoSimpleWH": "like Morris-Thorne, twisted by the rotation; black centre: rays through the throat into the empty other universe (l < 0), which run out of the 3000-point budget there (max-steps; no escape test for this metric)",
    "TeoWHl": "as TeoSimpleWH: black centre = rays through the throat into the empty other universe (max-steps)",
    "KastorTraschen": "two extreme RN holes (h = 0: static Majumdar-Papapetrou); black: rays falling towards the holes, whose horizons are points at infinite proper distance in these coordinates, exhaust the 3000-point budget (max-steps)",
    "AlcubierreWarpSimple": "the bubble (R = 1) is small at this distance: nearly flat view",
    "EinsteinRosenWaveWWB": "the cylindrical wave pulse (amplitude c = 1) strongly distorts the ring and sky; no black (no horizon)",
    "RotDihole": "two extreme RN holes (omega = 0); black: as KastorTraschen, rays towards the point horizons exhaust the budget",
    "DeSitterUniv": "flat slicing: the ring and grid as in flat space (null geodesics of a conformally flat metric are straight in comoving coordinates), only the angles scale",
    "SchwarzschildCart": "as Schwarzschild",
    "SchwarzschildIsotropic": "as Schwarzschild (isotropic radius 20 is r = 21 M)",
    "EddFinkIn": "as Schwarzschild (the static observer at the same r)",
    "PainleveGullstrand": "as Schwarzschild (the static observer at the same r)",
    "ReissnerNordstrom": "as Schwarzschild (Q = 0.1 barely changes the shadow)",
    "Kottler": "static patch only: black = shadow (rays end at the black-hole horizon); the ring (r = 1.2 .. 2.1) lies inside the horizon r = 2.17 and is hidden",
    "BarriolaVilenkin": "no horizon; solid-angle deficit (k = 0.8): the sky behind the origin is magnified into a radial pattern inside the ring",
    "JanisNewmanWinicour": "gamma = 1 is Schwarzschild",
    "Ernst": "the Melvin field (B r = 2 at the observer) confines light moving across the field lines: rays sent sideways near the equatorial plane are bent back and fall into the hole, so the shadow (horizon stops) is stretched across the image, cut by the ring",
    "TaubNUT": "shadow of the NUT black hole (l = 0.5), slightly larger than Schwarzschild's",
    "Goedel": "black horizontal band: rays without z-momentum never get farther than the Goedel radius r_G = 2 from the observer and circle there (max-steps); the others drift along z to the sky, which they reach after winding, hence the scrambled grid",
    "GoedelCart": "as Goedel; a few constraint stops (rays that wound many times)",
    "GoedelScaled": "as Goedel (r_G = 1)",
    "GoedelScaledCart": "as Goedel (r_G = 1)",
    "Kasner": "flat Kasner (u = 0: g_yy = t^2): the objects are fixed in comoving coordinates, so at t = 200 the ring is 200 times wider than tall and only its top and bottom arcs are in view; grid checks stretched likewise",
    "Curzon": "no horizon; black: rays approaching the directional singularity at R = 0 exhaust the 3000-point budget (max-steps)",
    "CosmicStringSchwarzschild": "shadow and ring cut by the string's deficit angle (beta = 0.5): part of the ring is missing, the shadow is pinched",
    "MinkowskiConformal": "Einstein static universe from the sample position: black = rays traced back to the chart's past edge psi = -pi (Minkowski's past null infinity and beyond) before reaching the sky at xi = 3: only short paths (the near side) reach it; the ring (xi = 0.2 .. 0.35) is visible",
    "SchwarzschildTortoise": "as Schwarzschild from r* = 20 (r = 16.1 M), so the shadow is larger",
    "MinkowskiRotLattice": "omega = 0: flat",
    "StraightSpinningString": "deficit angle 2 pi (1 - k) = 180 degrees: the ring's far side is cut, the grid jumps along the string",
    "BertottiKasner": "sample position; the 2-spheres have a fixed radius 1/sqrt(Lambda), so the sky grid wraps around; the ring (r = 0.2 .. 0.35) is not in view",
    "DeSitterUnivConformal": "conformally flat: flat-space view (null geodesics are straight in these coordinates)",
    "Petrov_Type_D_AI_ES": "Schwarzschild with b = 2M = 1: a shadow half the size",
    "Petrov_Type_D_AII_ES": "all black (horizon stops): the static region is the slab 0 < z < b = 1 between the singularity z = 0 and the horizon z = b; the sky sphere (radius 20) and most of the ring lie outside it, and every ray leaves the slab first",
    "ExtremeReissnerNordstromDihole": "two extreme RN holes at z = +-1 merge into one double shadow",
    "SchwarzschildWT": "spatial Schwarzschild times flat time: much weaker bending than Schwarzschild (no g_tt), a small black region = rays reaching the throat r = 2M",
    "Kruskal": "black: the shadow, 29.5 degrees in radius from r = 9.37 M, fills most of the view; its rays, traced back, cross the past horizon X = -T into the white hole and stop at the singularity break u + 1 < horizon_eps (horizon); sky and ring only in the corners. The 4% max-steps pixels are a rim, 1 to 2 pixels wide, at 29.0..30.5 degrees around the analytic edge asin(3 sqrt(3) M sqrt(1 - 2M/r)/r) = 29.45 degrees: near-critical rays that wind around the photon sphere r = 3M, where each winding multiplies X and T by e^(dt/4M) (X = -T = 2e3 .. 1e6 afterwards), so that these coordinates need 2000 .. 36000 steps for them. Given 200000 points, of 5 rim rays the two inside the edge end at the singularity (horizon) and the three outside (one of them 0.004 degrees inside, within the tolerance) reach the sky; with 40000 points 1.2% are still left, since the steps needed grow without bound towards the edge. So the rim is a cost of the chart, kept at the common 3000 points: black just inside the edge is right, the sky's photon-ring images just outside are missing",
    "VaidyaIncRad": "all black: every inward ray traced back meets the apparent horizon r = 2 m(v), and m(v) = k s^(1/3) tanh^2(sigma s) grows without bound into the past (s = -v), so the mass always fills the field of view",
    "SultanaDyerBlackhole": "at t = 200 like Schwarzschild (conformally related, null geodesics coincide)",
    "FriedmanNonEmptyNull": "k = 0, conformal time chi = 200: flat-space view (conformally flat)",
    "Petrov_Type_D_AIII_ES": "sample position: no ring in view; the grid converges towards the singular axis -- not yet understood in detail",
    "Petrov_Type_D_BI_ES": "mostly black: the rays run into the Killing horizons sin(theta) = 0 (g_tt = 0) and stop at the break margin sin^2(theta) < horizon_eps (horizon); the visible arches are sky and ring between them. The blackness is physical",
    "Petrov_Type_D_BII_ES": "all black: every ray runs into the Killing horizon r = 0 (g_tt = -z^2 sinh^2 r = 0) and stops at the break margin sinh^2 r < horizon_eps (horizon); the ray's end there is physical",
    "Petrov_Type_D_BIII_ES": "all black: every ray runs into the Rindler horizon r = 0 (g_tt = -z^2 r^2 = 0) and stops at the break margin r^2 < horizon_eps (horizon); the ray's end there is physical",
    "Petrov_Type_D_C_ES": "the static region is y > 1.3247 (G = y^3 - y - 1 > 0; G = 0 is a Killing horizon, g_tt = -G/(x + y)^2 vanishes linearly there), x > -1.3247 (f = x^3 - x + 1 > 0; f = 0 is the axis) and x + y < infinity (curvature singularity at finite proper distance). Light falls to the horizon whichever way it is sent: from the sample position (x, y) = (1, 1.5) all 108 rays of a 12 x 9 pixel sample ended at G < horizon_eps, y = 1.3247 (even rays sent along +y turn round at y = 2.4; only the exact +y ray runs on towards the singularity), with E = G k^t/(x + y)^2 conserved to 4e-7: the observer sees the horizon in every direction, and the former scene (sky of radius 20, mostly outside the region) was 99% black. So sky and ring lie inside the static region around the observer (sky radius 1.4 around (x, y) = (1, 3), observer at (1, 2)): every ray crosses the sky before the horizon (no black). The ring looks large because the y direction is short: proper length dy/((x + y) sqrt G) against dx/((x + y) sqrt f), sqrt G = 4.8, sqrt f = 1 at (1, 3)",
    "Pravda_C-Metric": "all black (horizon stops): the chart is x < -4.8 (G > 0, beyond the axis) and y < -0.9 (F > 0, outside the horizon), so the origin the camera looks at lies beyond the axis and the horizon; every ray ends there",
    "Pravda_C-Metric_Canonical_Coords": "A = 0.01: the two holes are about 1/A = 100 away along +-z, outside the view, so the view is nearly flat; the thin vertical seam through the centre lies on the z axis, presumably the conical singularity (strut/string) that accelerates the holes -- not checked in detail",
    "SchwarzschildGravWave": "from r = 8 (the wave keeps the signature at all times only for r < 8.8 M): the black disk is the Schwarzschild shadow (horizon stops), of the ring (r = 1.6 .. 2.8) only the outer part shows around it; the l = 0 wave is a gauge ripple (Birkhoff), and the picture looks like Schwarzschild's",
    "PlaneGravWave": "the coordinates (x, y, z) of the objects label free test particles (Rosen form). Before the wave (u = t - x < -a) the metric is flat with g_yy = p0^2, g_zz = q0^2, p0 = 3.42, q0 = 0.658 (p0 q0 = (1 + a/2)^2, p0/q0 = e^(2 m(-a)) = 5.20; 5.23 without the series truncation): a coordinate circle of radius R is there an ellipse with proper semi-axes p0 R, q0 R, which the wave makes round (p = q = 1 at u = 0) and then focuses (p = q = 1 - u, zero at u = 1). The former camera at t = 0, x = 20 (u = -20) saw only that region (u decreases along every ray traced back), hence the ring as a flat band, which is right: its elevations on the centre column, 6.2..9.9 and -13.7..-7.5 degrees (288 x 216 render), match 6.2..10.1 and -13.7..-7.4 degrees from straight lines with p0, q0. From t = 20.5 (u = 0.5) the past light cone crosses the wave: the ring, seen at u = -0.35..0.41 (mostly after the wave, p = q), is round and smaller; the sky light, emitted mostly before the wave (u < -1), crossed it and the grid is bent into arcs on both sides",
    "BesselGravWaveCart": "Einstein-Rosen cylindrical Bessel wave (C = 1) from x = 20: the sky is strongly sheared into bands around the horizon line, and the ring is squeezed into a thin line; no black (no horizon). Identical to HalilsoyWave with alpha = 0",
    "HalilsoyWave": "alpha = 0 is the Einstein-Rosen Bessel wave: the same picture as BesselGravWaveCart (cylindrical chart, same event)",
    "Bonnor": "a capture region, but not a horizon shadow. g_tt = -(P/Y)^2 = -(1 - 4m/r + ...): total mass 2m, hence larger than Schwarzschild's; Bonnor's solution is a black dihole (Emparan, PRD 61 (2000) 104009): two extreme magnetically charged holes at the poles of the rod Z = 0, r_b = m + sqrt(m^2 + b^2) = 2.005 (where g_tt has a double zero), joined by a strut, a conical singularity along the rod (circumference/radius -> 2 pi (m^2 + b^2)^2/b^4 = 2 pi 10201). Rays inside the equatorial photon orbit (r = 5.0 m, critical impact parameter 10.75 m, edge at asin(10.75 (1 - 2m/r)^(3/2)/r) = 27.3 degrees from r = 20; rendered without the ring: 27.1..27.6 degrees along the equator, 77% black) run down to the rod and stop at the break margin r < r_b (1 + horizon_eps) (horizon; E and L of a sample ray conserved to 4e-7). Of the 83 captured rays of a 12 x 9 pixel sample, 39 end within 5 degrees of the poles, where P ~ Z and g_tt -> 0: into the throats of the extreme holes; the others reach the strut, where g_tt = -(b^2 sin^2 theta/Y)^2 is not zero: a ray with angular momentum cannot come closer than Z = b_imp^2 P^4/(Y^4 sin^2 theta) (where g_phiphi/(-g_tt) = b_imp^2), r - r_b ~ 1e-9 (an equatorial ray with b_imp = 8 turns round at 1.2e-9), inside the margin and Motion4D's r <= r_b, next to the singular strut (with horizon_eps = 1e-13 the bounce breaks the constraint); so black there is light from the immediate neighbourhood of the strut, not computed. The ring's near side hides the lower part of the disk",
    "AlcubierreWarp": "the bubble (R = 1, sigma = 8, v_s = 1) at the origin, seen from y = -20: ring and grid as in flat space at this resolution",
    "ChazyCurzonRot": "rotating Chazy-Curzon (p = 0.5) from rho = 20 on the equator: the sky and ring are swirled by the rotation around a small black core (2% max-steps: rays approaching the singular source)",
    "TomimatsuSato": "delta = 2 (p = 0.5, q = 0.87, M = 1.73), first render of the prolate spheroidal chart (x = 46.2, y = 0.5: distance 20, 60 degrees from the axis): a black region shifted sideways by the rotation (39% stop at the break, horizon), the ring lensed around it",
    "Glampedakis": "default a = 0, epsilon = 0 is Schwarzschild: the same 14-degree shadow",
    "HartleThorneGB": "default a = 0, eta = 0 is Schwarzschild: the same 14-degree shadow",
    "ErezRosenVar": "quadrupole q = 0.1: indistinguishable from Schwarzschild at this resolution (20% of the rays end at the break, as there)",
}


KNOWN_TYPES = ("cartesian", "spherical", "cylinder", "prolatespheroidal", "custom")

# Charts whose natural tetrad and pseudo-Cartesian coordinates need their own camera (the generic
# rules below treat a custom chart as spherical). Each entry gives, in the metric's default natural
# tetrad, the camera axes e1 (line of sight), e2, e3 (up), and in pseudo-Cartesian coordinates the
# point the camera looks at (the centre of sky and ring), the observer's direction n from it and the
# up direction u.
#  * Petrov_Type_D_C_ES: coordinates (t, phi, x, y), pseudo-Cartesian (x, y, phi)
#    (petrov_type_d_c_es.cpp), tetrad e(1) = d/dphi, e(2) = d/dx, e(3) = d/dy. The static region is
#    x + y > 0, f(x) = x^3 - x + 1 > 0 (x > -1.3247, the axis f = 0), G(y) = y^3 - y - 1 > 0
#    (y > 1.3247, the horizon G = 0): the origin (y = 0) lies outside it, and every light ray ends at
#    the horizon (NOTES). From (x, y) = (1, 2) the camera looks along +y (e(3)), up +x (e(2)), at
#    the point (x, y, phi) = (1, 3, 0); the sky sphere of radius 1.4 around it (VIEW) lies inside the
#    static region (1.6 <= y <= 4.4, -0.4 <= x <= 2.4) and encloses the observer, so each ray crosses
#    it before it can reach the horizon; its phi extent 2.8 stays below 4 pi/f'(x0) = 2.95, the period
#    of phi that makes the axis f = 0 regular. `pseudo_cartesian` maps the observer's position.
CUSTOM_FRAMES = {
    "Petrov_Type_D_C_ES": dict(e1=[0.0, 0.0, 1.0], e2=[-1.0, 0.0, 0.0], e3=[0.0, 1.0, 0.0],
                               center=[1.0, 3.0, 0.0], n=[0.0, -1.0, 0.0], u=[1.0, 0.0, 0.0],
                               pseudo_cartesian=lambda pos: (pos[2], pos[3], pos[1])),
}


def param_default(metric, name):
    return next(p["default"] for p in metric["params"] if p["name"] == name)


def pseudo_cartesian(pos, coord_type, metric=None):
    """The observer's spatial point in pseudo-Cartesian coordinates (as Metric::to_pseudo_cartesian
    for the standard coordinate types; custom charts are treated as spherical)."""
    _, a, b, c = pos
    if coord_type == "prolatespheroidal":
        # (x, y, phi) with foci z = +-k (tomimatsu_sato.cpp): rho = k sqrt((x^2 - 1)(1 - y^2)), z = k x y
        k = param_default(metric, "k")
        rho = k * math.sqrt(max(0.0, (a * a - 1.0) * (1.0 - b * b)))
        return (rho * math.cos(c), rho * math.sin(c), k * a * b)
    if coord_type == "cylinder":
        return (a * math.cos(b), a * math.sin(b), c)
    if coord_type in ("spherical", "custom") or coord_type not in KNOWN_TYPES:
        return (a * math.sin(b) * math.cos(c), a * math.sin(b) * math.sin(c), a * math.cos(b))
    return (a, b, c)


def view_position(m):
    """(position, sky radius or None, why) of the observer for metric m."""
    name, pos, ctype = m["name"], list(m["sample_position"]), m["coordinate_type"]
    if name in VIEW:
        p, sky, why = VIEW[name]
        return (list(p) if p is not None else pos), sky, why
    if ctype not in KNOWN_TYPES:
        return pos, None, "sample position (coordinate type %s unknown to this script)" % ctype
    # Default: move the sample point out along the same direction to distance GENERIC_DISTANCE
    # (never inwards), the metric's asymptotic region for the asymptotically flat ones.
    R = GENERIC_DISTANCE
    if ctype == "prolatespheroidal":
        # keep y (the polar angle's cosine far out) and phi, move x out to distance R:
        # |p|^2 = k^2 (x^2 - 1 + y^2)
        k = param_default(m, "k")
        x = math.sqrt((R / k) ** 2 + 1.0 - pos[2] ** 2)
        if pos[1] < x:
            pos[1] = x
        return pos, None, "default: x moved out to %.4g (distance %g)" % (pos[1], R)
    if ctype in ("spherical", "custom"):
        if pos[1] < R:
            pos[1] = R
        return pos, None, "default: r moved out to %g" % pos[1]
    if ctype == "cylinder":
        d = math.hypot(pos[1], pos[3])
        if d == 0:
            pos[1] = R
        elif d < R:
            pos[1], pos[3] = pos[1] * R / d, pos[3] * R / d
        return pos, None, "default: moved out to distance %g" % max(d, R)
    d = math.sqrt(pos[1] ** 2 + pos[2] ** 2 + pos[3] ** 2)
    if d == 0:
        pos[1] = R
    elif d < R:
        pos[1:] = [v * R / d for v in pos[1:]]
    return pos, None, "default: moved out to distance %g" % max(d, R)


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def frame(pos, ctype, metric=None):
    """Camera axes e1 (line of sight), e2, e3 (up) in the natural tetrad of the chart, and the
    observer's outward direction n and up direction u in pseudo-Cartesian coordinates."""
    p = pseudo_cartesian(pos, ctype, metric)
    if ctype not in KNOWN_TYPES:
        # A chart this script does not know (e.g. prolate spheroidal): look along -e(1), up e(3).
        return [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]
    if ctype == "prolatespheroidal":
        # natural tetrad (e_x, e_y, e_phi) (tomimatsu_sato.cpp): x grows outwards and y towards +z
        # (y is cos(theta) far out), so n = e_x, up = +e_y
        k = param_default(metric, "k")
        x, y, ph = pos[1], pos[2], pos[3]
        rho = math.sqrt(max(1e-300, (x * x - 1.0) * (1.0 - y * y)))
        n_loc, up_loc = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]
        n = unit(p)
        drho_dy = -k * y * (x * x - 1.0) / rho
        u = unit([drho_dy * math.cos(ph), drho_dy * math.sin(ph), k * x])
    elif ctype in ("spherical", "custom"):
        # natural tetrad (e_r, e_theta, e_phi): n = e_r, up = -e_theta (north)
        n_loc, up_loc = [1.0, 0.0, 0.0], [0.0, -1.0, 0.0]
        th, ph = pos[2], pos[3]
        n = unit(p) if any(p) else [1.0, 0.0, 0.0]
        u = [-math.cos(th) * math.cos(ph), -math.cos(th) * math.sin(ph), math.sin(th)]
    else:
        # Cartesian (e_x, e_y, e_z) or cylindrical (e_rho, e_phi, e_z) natural tetrad: at the
        # observer both are a Cartesian frame (rotated by phi for the cylinder).
        if ctype == "cylinder":
            loc = [pos[1], 0.0, pos[3]]
        else:
            loc = list(p)
        n_loc = unit(loc) if any(loc) else [1.0, 0.0, 0.0]
        z = [0.0, 0.0, 1.0] if abs(n_loc[2]) < 0.99 else [0.0, 1.0, 0.0]
        up_loc = unit([zi - dot(z, n_loc) * ni for zi, ni in zip(z, n_loc)])
        n = unit(p) if any(p) else [1.0, 0.0, 0.0]
        zc = [0.0, 0.0, 1.0] if abs(n[2]) < 0.99 else [0.0, 1.0, 0.0]
        u = unit([zi - dot(zc, n) * ni for zi, ni in zip(zc, n)])
    e1 = [-x for x in n_loc]
    e3 = up_loc
    e2 = cross(e3, e1)
    return e1, e2, e3, n, u


def vec(v):
    return " ".join("%.10g" % x for x in v)


def scene(metric, pos, sky_override):
    ctype = metric["coordinate_type"]
    custom = CUSTOM_FRAMES.get(metric["name"])
    if custom and "pseudo_cartesian" in custom:
        p = custom["pseudo_cartesian"](pos)
    else:
        p = pseudo_cartesian(pos, ctype, metric)
    center = tuple(custom["center"]) if custom else (0.0, 0.0, 0.0)
    d = math.sqrt(sum((v - c) ** 2 for v, c in zip(p, center)))
    sky = sky_override if sky_override else max(20.0, 4.0 * d)
    if d == 0:  # a chart whose sample point this helper maps to the origin (custom chart)
        d = 5.0
    if custom:
        e1, e2, e3, n, u = custom["e1"], custom["e2"], custom["e3"], custom["n"], custom["u"]
    else:
        e1, e2, e3, n, u = frame(pos, ctype, metric)
    # ring normal: the line of sight tilted by atan(0.5) = 27 degrees towards "up"
    normal = unit([a + 0.5 * b for a, b in zip(n, u)])
    return f"""
(init-metric '(type "{metric['name']}") '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-6) '(step_size 0.01)
             `(boundBoxLL ,(vector (- gpDBLMAX) (- gpDBLMAX) (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vector gpDBLMAX gpDBLMAX gpDBLMAX gpDBLMAX))
             '(id "raytracing"))
(init-camera '(type "PinHoleCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0)) '(fov #(60.0 45.0))
             '(res #(96 72)) '(filter "FilterRGB") '(id "cam"))
(init-raygen '(type "RayGenSimple") '(solver "raytracing") '(maxNumPoints 3000))
(local-tetrad '(pos #({vec(pos)}))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 {vec(e1)})) '(e2 #(0.0 {vec(e2)})) '(e3 #(0.0 {vec(e3)}))
              '(incoords #f) '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))
(init-texture '(type "UniTex") '(color #(0.08 0.10 0.25)) '(id "skyDark"))
(init-texture '(type "UniTex") '(color #(0.55 0.60 0.85)) '(id "skyLight"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "skyDark") '(texture "skyLight")
                                       `(transform ,(scale-obj #(36.0 18.0)))))
             '(ambient 1.0) '(id "skyShader"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #({vec(center)})) '(axlen #({sky} {sky} {sky}))
                 '(shader "skyShader") '(id "sky"))
(init-texture '(type "UniTex") '(color #(0.9 0.55 0.1)) '(id "ringA"))
(init-texture '(type "UniTex") '(color #(0.95 0.9 0.7)) '(id "ringB"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "ringA") '(texture "ringB")
                                       `(transform ,(scale-obj #(16.0 2.0)))))
             '(ambient 1.0) '(id "ringShader"))
(plane-ring `(objtype ,gpObjTypeInCoords) '(center #({vec(center)})) '(normal #({vec(normal)}))
            '(rin {0.2 * d:.6g}) '(rout {0.35 * d:.6g}) '(shader "ringShader") '(id "ring"))
(comp-object '(obj "sky") '(obj "ring") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
"""


STOPS = ["hit", "escaped", "horizon", "box", "max-steps", "constraint", "error", "no-ray"]


def analyse(geovis, exr):
    """(number of NaN colour values, {stop reason: pixel count}, fraction of black pixels)."""
    r = subprocess.run([geovis, "post", exr, "--csv", "-", "--channels", "R,G,B,stop", "--quiet"],
                       check=True, capture_output=True, text=True)
    rows = list(csv.reader(io.StringIO(r.stdout)))
    head, rows = rows[0], rows[1:]
    ir, ig, ib, ist = (head.index(c) for c in ("R", "G", "B", "stop"))
    nan, black, stops = 0, 0, {}
    for row in rows:
        rgb = [float(row[i]) for i in (ir, ig, ib)]
        nan += sum(1 for v in rgb if math.isnan(v))
        black += all(v == 0 for v in rgb)
        s = STOPS[int(float(row[ist]))] if row[ist] not in ("", "nan") else "?"
        stops[s] = stops.get(s, 0) + 1
    return nan, stops, black / max(len(rows), 1)


def render(geovis, m, pos, sky, tmp):
    name = m["name"]
    scm = os.path.join(tmp, name + ".scm")
    with open(scm, "w") as f:
        f.write(scene(m, pos, sky))
    png = os.path.join(tmp, name + ".png")
    r = subprocess.run([geovis, "render", scm, "-o", png, "--data", "--quiet"], capture_output=True, text=True)
    if r.returncode != 0:
        lines = r.stderr.strip().splitlines()
        return None, None, (lines[-1] if lines else "exit code %d" % r.returncode)
    exrs = glob.glob(os.path.join(tmp, name + "*.exr"))
    if not exrs:
        return None, None, "no data file written"
    return png, exrs[0], None


def fmt_pos(pos):
    return "(" + ", ".join("%.4g" % v for v in pos) + ")"


def main():
    args = sys.argv[1:]
    only = None
    update_sheet = "--update-sheet" in args
    if update_sheet:
        args.remove("--update-sheet")
    if "--only" in args:
        i = args.index("--only")
        only = set(args[i + 1].split(","))
        del args[i:i + 2]
    geovis = args[0] if args else os.environ.get("GEOVIS", os.path.join(ROOT, "build", "geovis"))
    geovis = os.path.abspath(geovis)
    if not os.access(geovis, os.X_OK):
        sys.exit(f"make_metric_gallery.py: no geovis binary at {geovis} (build it first)")
    metrics = json.loads(subprocess.run([geovis, "metrics", "--json"], check=True, capture_output=True,
                                        text=True).stdout)
    os.makedirs(OUT, exist_ok=True)
    rows, bad = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for m in metrics:
            name = m["name"]
            if only is not None and name not in only:
                continue
            pos, sky, why = view_position(m)
            png, exr, err = render(geovis, m, pos, sky, tmp)
            if err is not None and pos != list(m["sample_position"]):
                # e.g. a new metric whose chart does not reach the default viewing position
                why = "sample position (default viewing position failed: %s)" % err
                print(f"{name}: {fmt_pos(pos)} failed ({err}); rendering from the sample position")
                pos, sky = list(m["sample_position"]), None
                png, exr, err = render(geovis, m, pos, sky, tmp)
            if err is not None:
                print(f"{name}: FAILED: {err}")
                bad.append(name)
                rows.append((m, pos, why, None, "render failed: " + err))
                continue
            nan, stops, black = analyse(geovis, exr)
            shutil.copyfile(png, os.path.join(OUT, name + ".png"))
            total = sum(stops.values())
            rays = ", ".join("%s %d%%" % (k, round(100 * v / total)) for k, v in
                             sorted(stops.items(), key=lambda kv: -kv[1]))
            print(f"{name}: {fmt_pos(pos)} black {100 * black:.0f}%  rays: {rays}" + (f"  NaN: {nan}" if nan else ""))
            if nan:
                bad.append(name)
            rows.append((m, pos, why, rays, None))
    if only is None:
        # drop thumbnails of metrics that no longer exist
        names = {m["name"] for m in metrics}
        for f in glob.glob(os.path.join(OUT, "*.png")):
            if os.path.basename(f)[:-4] not in names:
                os.remove(f)
        write_sheet(rows)
    elif update_sheet:
        write_sheet(rows, metrics)
    if bad:
        sys.exit("make_metric_gallery.py: NaN pixels or failed renders: " + ", ".join(bad))


def read_sheet_rows():
    """{metric name: table cells} of the current contact sheet."""
    cells = {}
    path = os.path.join(OUT, "README.md")
    if not os.path.exists(path):
        return cells
    with open(path) as f:
        for line in f:
            if not line.startswith("| ") or line.startswith("| image"):
                continue
            c = line.rstrip("\n").strip().strip("|").split(" | ")
            if len(c) == 6 and c[1].startswith("`"):
                cells[c[1].strip("` ")] = [x.strip() for x in c]
    return cells


def write_sheet(rows, metrics=None):
    """The contact sheet from `rows`; with `metrics` (a partial run) the rows of the other metrics
    are taken from the current sheet, in the registry's order."""
    old = read_sheet_rows() if metrics is not None else {}
    if metrics is not None:
        new = {r[0]["name"]: r for r in rows}
        merged = []
        for m in metrics:
            if m["name"] in new:
                merged.append(new[m["name"]])
            elif m["name"] in old:
                merged.append((m, None, None, None, old[m["name"]]))
        rows = merged
    with open(os.path.join(OUT, "README.md"), "w") as f:
        f.write("# Metric gallery (contact sheet)\n\n")
        f.write(
            "Generated by [`docs/gallery/make_metric_gallery.py`](../make_metric_gallery.py) (its docstring has\n"
            "the set-up): every metric with its default parameters, one camera set-up for all: an observer at\n"
            "rest in the default natural tetrad at the viewing position, looking at the origin; a sky sphere\n"
            "with a 10-degree checker grid (blue) and a checkered ring (orange) around the origin, both given\n"
            "in the metric's pseudo-Cartesian coordinates; 96 x 72 pixels, 60 x 45 degrees. Colours are the\n"
            "texture colours (no redshift). Black: no object hit. *Rays* says how the pixels' light rays\n"
            "ended (traced backwards from the camera): hit = sky or ring, horizon = the metric's break\n"
            "condition (horizon, singularity, chart edge), escaped = left the scene's bounds without hitting,\n"
            "max-steps = the 3000 points per ray ran out. No thumbnail has NaN pixels (the script checks).\n\n")
        f.write("| image | metric | description | observer position | note | rays |\n|---|---|---|---|---|---|\n")
        for m, pos, why, rays, err in rows:
            name = m["name"]
            if pos is None:  # kept from the current sheet (partial run), with the note refreshed
                c = err
                c[4] = NOTES.get(name, "*not yet looked at*")
                f.write("| " + " | ".join(c) + " |\n")
                continue
            img = f"![{name}]({name}.png)" if err is None else err
            note = NOTES.get(name, "*not yet looked at*")
            doc = m["doc"].replace("|", "/")
            f.write(f"| {img} | `{name}` | {doc} | {fmt_pos(pos)}: {why} | {note} | {rays or ''} |\n")


if __name__ == "__main__":
    main()
