;; ---------------------------------------------------------------------
;;  Gallery: pinhole camera (PinHoleCam, paper eq. 3). A static observer
;;  at r = 30M, 10 degrees above the plane of a thin checkered disk
;;  (6M <= r <= 12M) around a Schwarzschild black hole, in front of the
;;  grid sky at r = 45M. The far side of the disk is lensed over the top
;;  of the shadow, its underside appears below it, and the grid sky shows
;;  the Einstein ring around the shadow.
;;
;;    geovis render examples/gallery/pinhole_schwarzschild.scm -o pinhole.png
;; ---------------------------------------------------------------------

(define r_obs 30.0)
(define incl  80.0)
(define fview 36.0)

(init-metric '(type "Schwarzschild") '(mass 1.0) '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-8)
             '(step_size 0.01) '(id "raytracing"))
(init-camera '(type "PinHoleCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0))
             `(fov ,(vector (* fview 4/3) fview)) '(res #(320 240)) '(id "cam"))
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) 0.0 (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vector gpDBLMAX 54.0 gpDBLMAX gpDBLMAX))
             '(solver "raytracing") '(maxNumPoints 5000))
;; e1 = -e_r (towards the hole), e2 = -e_phi, e3 = -e_theta (up).
(local-tetrad `(pos ,(vector 0.0 r_obs (radians incl) 0.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
              '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0))
              '(incoords #f) '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

(init-texture '(type "UniTex") '(color #(0.95 0.55 0.1)) '(id "hot"))
(init-texture '(type "UniTex") '(color #(0.55 0.12 0.04)) '(id "cool"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "hot") '(texture "cool")
                                       `(transform ,(scale-obj #(24.0 4.0)))))
             '(ambient 1.0) '(diffuse 0.0) '(id "diskShader"))
(plane-ring `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0)) '(normal #(0.0 0.0 1.0))
            '(rin 6.0) '(rout 12.0) '(shader "diskShader") '(id "disk"))

(define sky_radius 45.0)
;; the grid sky of ../include/grid_sky.scm (its texture path is relative to the scene folder)
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "Image") '(file "../textures/sky_grid.png")
                                       `(transform ,(scale-obj #(-1.0 -1.0)))))
             '(ambient 1.0) '(diffuse 0.0) '(id "skyShader"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0))
                 `(axlen ,(vector sky_radius sky_radius sky_radius)) '(shader "skyShader") '(id "sky"))
(comp-object '(obj "disk") '(obj "sky") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
