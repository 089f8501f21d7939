;; ---------------------------------------------------------------------
;;  Planetarium "DomeMaster" fisheye (2PICam, paper eq. 6): a static
;;  observer at r = 12M next to a Schwarzschild black hole, looking
;;  towards the hole (pitch -90 turns the dome's zenith to the horizon,
;;  onto the local direction e1 = -e_r).
;;  Pixels outside the dome circle are not traced.
;;
;;    geovis render examples/dome_schwarzschild.scm -o dome.png
;; ---------------------------------------------------------------------

(define r_obs 12.0)

(init-metric '(type "Schwarzschild") '(mass 1.0) '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-8)
             '(step_size 0.01) '(id "raytracing"))
(init-camera '(type "2PICam") '(heading 0.0) '(pitch -90.0) '(res #(256 256)) '(id "dome"))
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) 0.0 (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vector gpDBLMAX 50.0 gpDBLMAX gpDBLMAX))
             '(solver "raytracing") '(maxNumPoints 3000))
(local-tetrad `(pos ,(vector 0.0 r_obs PIhalf 0.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
              '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0))
              '(incoords #f) '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))
(define sky_radius 45.0)
(load "include/grid_sky.scm")
(comp-object '(obj "sky") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "dome"))
