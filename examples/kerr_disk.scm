;; ---------------------------------------------------------------------
;;  Paper §4.2, Fig. 3: a thin "accretion disk" 3M <= r <= 15M in the
;;  equatorial plane of a Kerr black hole (Boyer-Lindquist coordinates,
;;  paper eq. 10), seen from r = 50M at inclination 80 degrees. The disk
;;  is a coordinate object (plane-ring) with a checker texture in
;;  (phi, r); the higher-order images of the disk wrap around the shadow.
;;  Try --define incl=2 for the face-on view, --define a=0.0 for
;;  Schwarzschild.
;;
;;    geovis render examples/kerr_disk.scm -o kerr_disk.png
;; ---------------------------------------------------------------------

(define a     0.99)
(define r_obs 50.0)
(define incl  80.0)
(define fview 38.0)

(init-metric '(type "KerrBL") '(mass 1.0) `(angmom ,a) '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-8)
             '(step_size 0.01) '(id "raytracing"))
(init-camera '(type "PinHoleCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0))
             `(fov ,(vector fview fview)) '(res #(256 256)) '(id "cam"))
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) 0.0 (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vector gpDBLMAX 70.0 gpDBLMAX gpDBLMAX))
             '(solver "raytracing") '(maxNumPoints 3000))
(local-tetrad `(pos ,(vector 0.0 r_obs (radians incl) 0.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
              '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0))
              '(incoords #f) '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.1 0.1 0.15)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

(init-texture '(type "UniTex") '(color #(0.95 0.55 0.1)) '(id "hot"))
(init-texture '(type "UniTex") '(color #(0.6 0.15 0.05)) '(id "cool"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "hot") '(texture "cool")
                                       `(transform ,(scale-obj #(36.0 6.0)))))
             '(ambient 1.0) '(diffuse 0.0) '(id "diskShader"))

(plane-ring `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0)) '(normal #(0.0 0.0 1.0))
            '(rin 3.0) '(rout 15.0) '(shader "diskShader") '(id "disk"))
(comp-object '(obj "disk") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
