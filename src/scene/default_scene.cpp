#include "scene/default_scene.h"

namespace geovis {

// Physics of the scene (G = c = 1, M = 1, r_s = 2):
//  * circular geodesic at r = 10 M (stable: r > 6 M); speed measured by the static observer
//    v = sqrt(M / (r - 2M)) = sqrt(1/8) = 0.353553 (Misner, Thorne & Wheeler, Gravitation,
//    eq. 25.19 ff.; Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, §2.2.1);
//    coordinate angular velocity Omega = sqrt(M / r^3) = 0.0316, period 2 pi / Omega = 199;
//  * the observer sits at r = 30 M, inclination 80 deg, at coordinate time t = 22, about the
//    light travel time from the orbit, so it sees the sphere near phi = 40 deg (where it was
//    at t = 0) beside the black hole's shadow;
//  * the sky is a sphere of radius 45 M with a 10-degree checker grid.
const std::string& default_scene_text() {
  static const std::string text = R"SCM(
;; geovis built-in scene: a checkered sphere orbiting a Schwarzschild black hole.

(define r_obs  30.0)
(define incl   80.0)
(define t_obs  22.0)
(define r_obj  10.0)
(define v_orb  (sqrt (/ 1.0 (- r_obj 2.0))))   ; circular orbit, local velocity
(define phi0   (* 40.0 DEG_TO_RAD))

(init-metric '(type "Schwarzschild") '(mass 1.0) '(id "metric"))

(init-solver '(type "GSL_RK_Cash-Karp")
             '(geodType "lightlike")
             '(eps_abs 1.0e-6)
             '(step_size 0.01)
             '(id "raytracing"))

(init-camera '(type "PinHoleCam")
             '(dir #(1.0 0.0 0.0))
             '(vup #(0.0 0.0 1.0))
             '(fov #(50.0 37.5))
             '(res #(256 192))
             '(filter "FilterRGB")
             '(id "cam"))

;; A backward-traced ray that comes below r = 2.5 M can never turn back out: null geodesics
;; have turning points only at r > 3 M (photon sphere; b^2 = r^3 / (r - 2M) is minimal at 3M),
;; so stopping there is exact and saves integrating into the horizon.
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) 2.5 (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vector gpDBLMAX 50.0 gpDBLMAX gpDBLMAX))
             '(solver "raytracing")
             '(maxNumPoints 3000))

(local-tetrad `(pos ,(vector t_obs r_obs (* incl DEG_TO_RAD) 0.0))
              '(e0 #(1.0  0.0  0.0  0.0))
              '(e1 #(0.0 -1.0  0.0  0.0))
              '(e2 #(0.0  0.0  0.0 -1.0))
              '(e3 #(0.0  0.0 -1.0  0.0))
              '(incoords #f)
              '(id "locTedObs"))

(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))

(init-light-mgr '(ambient #(1.0 1.0 1.0)))

;; --- sky: a 10-degree grid of two colours
(init-texture '(type "UniTex") '(color #(0.08 0.10 0.25)) '(id "skyDark"))
(init-texture '(type "UniTex") '(color #(0.55 0.60 0.85)) '(id "skyLight"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D")
                                       '(texture "skyDark")
                                       '(texture "skyLight")
                                       `(transform ,(scale-obj #(36.0 18.0)))))
             '(ambient 1.0)
             '(id "skyShader"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords)
                 '(center #(0.0 0.0 0.0))
                 '(axlen #(45.0 45.0 45.0))
                 '(shader "skyShader")
                 '(id "sky"))

;; --- the orbiting sphere
(init-texture '(type "UniTex") '(color #(0.8 0.16 0.16)) '(id "red"))
(init-texture '(type "UniTex") '(color #(0.9 0.63 0.63)) '(id "pink"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D")
                                       '(texture "red")
                                       '(texture "pink")
                                       `(transform ,(scale-obj #(12.0 6.0)))))
             '(ambient 0.3)
             '(diffuse 0.8)
             '(id "sphereShader"))
(solid-ellipsoid `(objtype ,gpObjTypeLocal)
                 '(center #(0.0 0.0 0.0))
                 '(axlen #(1.0 1.0 1.0))
                 '(shader "sphereShader")
                 '(id "sphere"))

(init-solver '(type "GSL_RK_Cash-Karp")
             '(geodType "timelike")
             '(step_ctrl #f)
             '(step_size 0.1)
             '(id "gsolver"))

(init-motion '(type "Geodesic")
             '(solver "gsolver")
             `(pos ,(vector 0.0 r_obj PIhalf phi0))
             `(localvel ,(vector 0.0 0.0 v_orb))
             '(e0 #(1.0 0.0  0.0  0.0))
             '(e1 #(0.0 0.0 -1.0  0.0))
             '(e2 #(0.0 0.0  0.0 -1.0))
             '(e3 #(0.0 1.0  0.0  0.0))
             '(maxnumpoints 2000)
             '(forward 60.0)
             '(backward 60.0)
             '(id "orbit"))

(local-comp-object '(obj "sphere") '(motion "orbit") '(id "movingSphere"))

(comp-object '(obj "sky") '(obj "movingSphere") '(id "scene"))

(init-device '(type "standard") '(obj "scene") '(camera "cam"))
)SCM";
  return text;
}

const std::string& default_scene_name() {
  static const std::string name = "geovis_default";
  return name;
}

}  // namespace geovis
