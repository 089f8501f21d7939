;; ---------------------------------------------------------------------
;;  Gallery: panorama camera (PanoramaCam, paper eq. 5). A static observer
;;  at r = 5M next to a Schwarzschild black hole, 360 x 100 degree field
;;  of view, the hole in the middle of the strip. The shadow's angular
;;  radius is arcsin(3 sqrt(3) M/r sqrt(1 - 2M/r)) = 53.6 degrees
;;  (Synge 1966), so it covers a 107 degree wide stretch of the horizon;
;;  the grid sky at r = 45M is squeezed into the Einstein ring around it,
;;  and the view away from the hole (left and right ends) is the sky
;;  seen almost undistorted.
;;
;;    geovis render examples/gallery/panorama_schwarzschild.scm -o panorama.png
;; ---------------------------------------------------------------------

(define r_obs 5.0)

(init-metric '(type "Schwarzschild") '(mass 1.0) '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-8)
             '(step_size 0.01) '(id "raytracing"))
(init-camera '(type "PanoramaCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0))
             '(fov #(360.0 100.0)) '(res #(360 100)) '(id "cam"))
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
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
