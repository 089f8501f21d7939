;; ---------------------------------------------------------------------
;;  Text output and the scene-language helpers, around a small image of
;;  a Schwarzschild black hole seen from r = 15M in front of a
;;  solid-background sky:
;;   * calc-ray        one light ray from a local tetrad, given by the
;;                     angles (xi, chi) -> ray_tetrad.txt (t r theta phi
;;                     per point);
;;   * calc-proj-ray   one light ray from the projector's tetrad in a
;;                     local direction, with the parallel-transported
;;                     tetrad, in Cartesian coordinates -> ray_proj.txt;
;;   * gvs-print-motion the worldline and tetrads of a timelike geodesic
;;                     (an eccentric orbit) -> orbit.txt;
;;   * FilterRGBpdz    per-pixel hit data next to each image (NAME.pdz);
;;   * gvs-print, get-parameter, set-parameter, vec3, vec4, set-changeobj,
;;     m4d-metriclist and m4d-solverlist (printed while the scene is read).
;;  The files are written into the working folder when rendering
;;  (`geovis check` reads the scene without writing them).
;;
;;    geovis render examples/rays_and_worldlines.scm -o bh.png
;; ---------------------------------------------------------------------

(define r_obs 15.0)

(init-metric '(type "Schwarzschild") '(mass 1.0) '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-8)
             '(step_size 0.01) '(id "raytracing"))
;; FilterRGBpdz: besides the image, NAME.pdz holds per pixel the hit point,
;; the light direction there, the object number and the frequency shift.
(init-camera '(type "PinHoleCam") `(dir ,(vec3 1.0 0.0 0.0)) `(vup ,(vec3 0.0 0.0 1.0))
             '(fov #(50.0 50.0)) '(res #(96 96)) '(filter "FilterRGBpdz") '(id "cam"))
;; r > 2.05: rays that get this close never come back out (see fig2).
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vec4 (- gpDBLMAX) 2.05 (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vec4 gpDBLMAX 50.0 gpDBLMAX gpDBLMAX))
             '(solver "raytracing") '(maxNumPoints 3000) '(id "raygen"))

;; Static observer: e1 = -e_r (towards the hole), e2 = -e_phi, e3 = -e_theta.
(local-tetrad `(pos ,(vec4 0.0 r_obs PIhalf 0.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
              '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0))
              '(incoords #f) '(id "observer"))
(init-projector '(localTetrad "observer") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

;; The sky: solid-background (a unit sphere, scaled here to radius 45 by
;; its transform) with the grid image.
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "Image") '(file "textures/sky_grid.png")
                                       `(transform ,(scale-obj #(-1.0 -1.0)))))
             '(ambient 1.0) '(id "skyShader"))
(solid-background '(shader "skyShader") `(transform ,(scale-obj #(45.0 45.0 45.0))) '(id "sky"))

;; A small sphere on the far side of the hole (its Einstein ring) ...
(init-texture '(type "UniTex") '(color #(0.9 0.5 0.1)) '(id "orange"))
(init-shader '(type "SurfShader") '(objcolor "orange") '(ambient 1.0) '(id "ballShader"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(-20.0 0.0 0.0)) '(axlen #(1.0 1.0 1.0))
                 '(shader "ballShader") '(id "ball"))
;; ... made bigger by set-parameter (read back with get-parameter).
(set-parameter '(id "ball") '(axlen #(2.0 2.0 2.0)))
(display "ball axlen after set-parameter: ")
(display (get-parameter '(id "ball") '(param "axlen")))
(newline)
(gvs-print '(id "ball"))

;; A timelike geodesic (an eccentric bound orbit starting at periapsis
;; r = 8 with 0.42c along e_phi) written with its tetrads to orbit.txt.
(init-solver '(type "GSL_RK_Fehlberg") '(geodType "timelike") '(step_ctrl #f)
             '(step_size 0.1) '(id "orbitSolver"))
(init-motion '(type "Geodesic") '(solver "orbitSolver")
             `(pos ,(vec4 0.0 8.0 PIhalf 0.0)) `(localvel ,(vec3 0.0 0.0 0.42))
             '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 1.0 0.0 0.0))
             '(e2 #(0.0 0.0 1.0 0.0)) '(e3 #(0.0 0.0 0.0 1.0))
             '(maxnumpoints 2000) '(forward 150.0) '(backward 0.0) '(id "orbit"))
(gvs-print-motion '(id "orbit") '(file "orbit.txt"))

;; One light ray from the observer's tetrad: xi = 0, chi = 80 deg from e3
;; (towards the hole, passing it on the upper side).
(calc-ray '(filename "ray_tetrad.txt") '(raygen "raygen") '(locted "observer") '(dir #(0.0 80.0)))
;; The same kind of ray from the projector, 10 deg to the side of the
;; hole, in Cartesian coordinates.
(calc-proj-ray '(filename "ray_proj.txt") '(raygen "raygen") '(projector "proj")
               `(dir ,(vec3 (cos (radians 10.0)) (sin (radians 10.0)) 0.0)) '(cartesian #t))

;; The metric and solver databases (printed while the scene is read).
(m4d-metriclist)
(m4d-solverlist)

(comp-object '(obj "ball") '(obj "sky") '(id "scene"))
;; Two frames: the second moves the observer in to r = 10 through
;; set-changeobj (an extra setparam of an existing device).
(init-device '(type "standard") '(obj "scene") '(camera "cam") '(id "far"))
(init-device '(type "standard") '(obj "scene") '(camera "cam") '(id "near"))
(set-changeobj '(device "near") `(setparam ("observer" "pos" ,(vec4 0.0 10.0 PIhalf 0.0))))
