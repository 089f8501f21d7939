;; ---------------------------------------------------------------------
;;  Gallery: planetarium dome camera (2PICam, paper eq. 6). A static
;;  observer at r = 8M looks straight at a Schwarzschild black hole: the
;;  dome shows the whole hemisphere in front of the observer. 2PICam maps
;;  the angle psi from the dome centre to the image radius sin(psi), so
;;  the shadow (angular radius arcsin(3 sqrt(3) M/r sqrt(1 - 2M/r)) =
;;  34.2 degrees) has 0.5625 times the dome radius; the grid sky at
;;  r = 45M forms the Einstein ring around it. Pixels outside the dome
;;  circle are not traced (background colour).
;;
;;  With this observer tetrad (e1 = -e_r) the dome centre is +e1 for
;;  pitch -90 (GeoViS Gvs2PICam: d = Rz(-heading) Ry(-pitch) Rz(3 pi/2) s).
;;
;;    geovis render examples/gallery/dome_schwarzschild_hole.scm -o dome.png
;; ---------------------------------------------------------------------

(define r_obs 8.0)

(init-metric '(type "Schwarzschild") '(mass 1.0) '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-8)
             '(step_size 0.01) '(id "raytracing"))
(init-camera '(type "2PICam") '(heading 0.0) '(pitch -90.0) '(res #(256 256)) '(id "dome"))
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) 0.0 (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vector gpDBLMAX 54.0 gpDBLMAX gpDBLMAX))
             '(solver "raytracing") '(maxNumPoints 5000))
;; e1 = -e_r (towards the hole), e2 = -e_phi, e3 = -e_theta (up).
(local-tetrad `(pos ,(vector 0.0 r_obs PIhalf 0.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
              '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0))
              '(incoords #f) '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

(define sky_radius 45.0)
;; the grid sky of ../include/grid_sky.scm (its texture path is relative to the scene folder)
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "Image") '(file "../textures/sky_grid.png")
                                       `(transform ,(scale-obj #(-1.0 -1.0)))))
             '(ambient 1.0) '(diffuse 0.0) '(id "skyShader"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0))
                 `(axlen ,(vector sky_radius sky_radius sky_radius)) '(shader "skyShader") '(id "sky"))
(comp-object '(obj "sky") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "dome"))
