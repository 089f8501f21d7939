;; ---------------------------------------------------------------------
;;  Paper Fig. 2 / §4.1: a small checkered sphere on the last stable
;;  circular orbit (r = 6M = 3 r_s) of a Schwarzschild black hole, seen by
;;  a static observer at r = 30M. The sphere is a local object riding a
;;  parallel-transported tetrad along a timelike geodesic (init-motion
;;  "Geodesic"); the observation times start at the light travel time
;;  t_0 = 27.8918 (paper eq. 9) so that frame 0 shows the sphere between
;;  hole and observer; t_step covers one orbit (t_2pi = 92.3436) in
;;  `frames` images. The sphere appears rotated by arcsin(0.5) = 30 deg
;;  (finite speed of light) and precesses by 105.44 deg per orbit.
;;
;;  Rendered (all 16 frames, 72x72, one core: ~23 s user time) and assembled with
;;    geovis render examples/fig2_orbiting_sphere.scm --threads 1 -o /tmp/fig2/f_%04d.png
;;    ffmpeg -y -framerate 8 -i /tmp/fig2/f_%04d.png \
;;      -vf "scale=144:144:flags=neighbor,split[a][b];[a]palettegen[p];[b][p]paletteuse" \
;;      docs/gallery/fig2.gif
;; ---------------------------------------------------------------------

(define r_obs  30.0)
(define r_obj   6.0)
(define fview  30.0)
(define frames 16)
(define t_start 27.8918)
(define t_step (/ 92.3436 frames))

(init-metric '(type "Schwarzschild") '(mass 1.0) '(id "metric"))

(init-solver '(type "GSL_RK_Cash-Karp")
             '(geodType "lightlike")
             '(eps_abs 1.0e-8)
             '(step_size 0.01)
             '(id "raytracing"))

(init-camera '(type "PinHoleCam")
             '(dir #(1.0 0.0 0.0))
             '(vup #(0.0 0.0 1.0))
             `(fov ,(vector fview fview))
             '(res #(72 72))
             '(id "cam"))

;; r > 2.05: a ray that gets this close to the horizon never comes back out
;; (it is inside the photon sphere r = 3M), and in Schwarzschild coordinates
;; the step size shrinks without bound towards r = 2M, so stopping it here
;; saves thousands of steps per shadow pixel without changing a pixel.
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) 2.05 (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vector gpDBLMAX 50.0 gpDBLMAX gpDBLMAX))
             '(solver "raytracing")
             '(maxNumPoints 3000))

;; Observer: e1 = -e_r (towards the hole), e2 = -e_phi, e3 = -e_theta (up = +z).
(local-tetrad `(pos ,(vector 0.0 r_obs PIhalf 0.0))
              '(e0 #(1.0  0.0 0.0  0.0))
              '(e1 #(0.0 -1.0 0.0  0.0))
              '(e2 #(0.0  0.0 0.0 -1.0))
              '(e3 #(0.0  0.0 -1.0 0.0))
              '(incoords #f)
              '(id "locTedObs"))

(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

(init-texture '(type "UniTex") '(color #(0.8 0.16 0.16)) '(id "red"))
(init-texture '(type "UniTex") '(color #(0.9 0.63 0.63)) '(id "pink"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D")
                                       '(texture "red") '(texture "pink")
                                       `(transform ,(scale-obj #(20.0 10.0)))))
             '(ambient 0.3)
             '(diffuse 1.0)
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

;; Circular orbit at r = 6: local velocity 0.5 along e_phi (paper §4.1).
(init-motion '(type "Geodesic")
             '(solver "gsolver")
             `(pos ,(vector 0.0 r_obj PIhalf 0.0))
             '(localvel #(0.0 0.0 0.5))
             '(e0 #(1.0 0.0 0.0 0.0))
             '(e1 #(0.0 0.0 -1.0 0.0))
             '(e2 #(0.0 0.0 0.0 -1.0))
             '(e3 #(0.0 1.0 0.0 0.0))
             '(maxnumpoints 3000)
             '(forward 150.0)
             '(backward 50.0)
             '(id "motion"))

(local-comp-object '(obj "sphere") '(motion "motion") '(id "orbiter"))

(define sky_radius 45.0)
(load "include/grid_sky.scm")

(comp-object '(obj "orbiter") '(obj "sky") '(id "scene"))

(do ((n 0 (+ n 1))) ((= n frames))
  (init-device '(type "standard")
               '(obj "scene")
               '(camera "cam")
               `(setparam ("locTedObs" "time" ,(+ t_start (* t_step n))))))
