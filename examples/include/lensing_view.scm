;; ---------------------------------------------------------------------
;;  geovis example helper: a static observer looking at the centre of a
;;  spacetime, with the grid sky behind it. Define before loading:
;;    coords     'spherical (t r theta phi) or 'cartesian (t x y z)
;;    r_obs      distance of the observer (on the x axis / at theta = 90)
;;    sky_radius radius of the celestial sphere (bounding box: 1.2 x)
;;    fview      vertical field of view in degrees
;;    res        image width = height in pixels
;;    eps        integration tolerance
;; ---------------------------------------------------------------------

(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") `(eps_abs ,eps)
             '(step_size 0.01) '(id "raytracing"))
(init-camera '(type "PinHoleCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0))
             `(fov ,(vector fview fview)) `(res ,(vector res res)) '(id "cam"))
(define box (* 1.2 sky_radius))
(if (eq? coords 'spherical)
    (begin
      (init-raygen '(type "RayGenSimple")
                   `(boundBoxLL ,(vector (- gpDBLMAX) (- box) (- gpDBLMAX) (- gpDBLMAX)))
                   `(boundBoxUR ,(vector gpDBLMAX box gpDBLMAX gpDBLMAX))
                   '(solver "raytracing") '(maxNumPoints 5000))
      (local-tetrad `(pos ,(vector 0.0 r_obs PIhalf 0.0))
                    '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
                    '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0))
                    '(incoords #f) '(id "observer")))
    (begin
      (init-raygen '(type "RayGenSimple")
                   `(boundBoxLL ,(vector (- gpDBLMAX) (- box) (- box) (- box)))
                   `(boundBoxUR ,(vector gpDBLMAX box box box))
                   '(solver "raytracing") '(maxNumPoints 5000))
      (local-tetrad `(pos ,(vector 0.0 r_obs 0.0 0.0))
                    '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
                    '(e2 #(0.0 0.0 -1.0 0.0)) '(e3 #(0.0 0.0 0.0 1.0))
                    '(incoords #f) '(id "observer"))))
(init-projector '(localTetrad "observer") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))
(load "grid_sky.scm")             ; relative to this file's folder (examples/include)
(comp-object '(obj "sky") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
