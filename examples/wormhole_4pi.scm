;; ---------------------------------------------------------------------
;;  Paper §4.3: a Morris-Thorne wormhole (paper eq. 11, throat b0 = 1).
;;  Each universe has its own celestial sphere: chart 0 (l > 0) shows the
;;  grid sky, chart 1 (l <= 0) the same sky tinted by a colour gradient
;;  texture. A full-sky 4PI camera (equirectangular, paper eq. 4) at
;;  l = 3 sees the other universe through the throat.
;;
;;    geovis render examples/wormhole_4pi.scm -o wormhole.png
;; ---------------------------------------------------------------------

(define l_obs 3.0)

(init-metric '(type "MorrisThorne") '(b0 1.0) '(id "metric"))
(init-solver '(type "GSL_RK_Fehlberg") '(geodType "lightlike") '(eps_abs 1.0e-8)
             '(step_size 0.01) '(id "raytracing"))
(init-camera '(type "4PICam") '(res #(320 160)) '(id "cam"))
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) -60.0 -60.0 -60.0))
             `(boundBoxUR ,(vector gpDBLMAX 60.0 60.0 60.0))
             '(solver "raytracing") '(maxNumPoints 3000))
(local-tetrad `(pos ,(vector 0.0 l_obs PIhalf 0.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
              '(e2 #(0.0 0.0 0.0 1.0)) '(e3 #(0.0 0.0 -1.0 0.0))
              '(incoords #f) '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

(define sky_radius 50.0)
(load "include/grid_sky.scm")

(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "ColorGradTex")
                                       '(color1 #(0.1 0.5 0.2)) '(color2 #(0.9 0.9 0.3))
                                       '(start #(0.0 0.0)) '(end #(0.0 1.0))))
             '(ambient 1.0) '(id "lowerShader"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0))
                 '(axlen #(50.0 50.0 50.0)) '(shader "lowerShader") '(chart 1) '(id "lowerSky"))

(comp-object '(obj "sky") '(obj "lowerSky") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
