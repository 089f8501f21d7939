;; ---------------------------------------------------------------------
;;  Paper §5, Fig. 9: a thin accretion disk 3 r_s <= r <= 7.5 r_s around
;;  a Schwarzschild black hole (M = 1, r_s = 2), seen from r = 50M at
;;  inclination 80 degrees. The disk matter moves on circular Keplerian
;;  orbits (plane-ring key emitter "keplerian", a geovis extension: the
;;  emitter four-velocity u = gamma (e_t + beta e_phi) of paper §5 enters
;;  1+z of paper eq. 15). The camera filter FilterRGBpdz writes the GeoViS
;;  .pdz file and the OpenEXR data file next to the image; the pictures of
;;  Fig. 9 then come from the data without tracing again:
;;
;;    geovis render examples/fig9_disk_flux.scm -o fig9.png
;;    geovis post fig9.exr --shader disk-flux -o fig9_flux.png --colorbar
;;    geovis post fig9.exr --shader redshift -o fig9_redshift.png --colorbar
;; ---------------------------------------------------------------------

(define M     1.0)
(define rs    (* 2.0 M))
(define r_obs 50.0)
(define incl  80.0)
(define fview 36.0)

(init-metric '(type "Schwarzschild") `(mass ,M) '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp") '(geodType "lightlike") '(eps_abs 1.0e-8)
             '(step_size 0.01) '(id "raytracing"))
(init-camera '(type "PinHoleCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0))
             `(fov ,(vector fview fview)) '(res #(256 256)) '(filter "FilterRGBpdz") '(id "cam"))
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) 0.0 (- gpDBLMAX) (- gpDBLMAX)))
             `(boundBoxUR ,(vector gpDBLMAX 70.0 gpDBLMAX gpDBLMAX))
             '(solver "raytracing") '(maxNumPoints 3000))
(local-tetrad `(pos ,(vector 0.0 r_obs (radians incl) 0.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 -1.0 0.0 0.0))
              '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0))
              '(incoords #f) '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.0 0.0 0.0)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

(init-texture '(type "UniTex") '(color #(0.95 0.55 0.1)) '(id "hot"))
(init-texture '(type "UniTex") '(color #(0.6 0.15 0.05)) '(id "cool"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "hot") '(texture "cool")
                                       `(transform ,(scale-obj #(36.0 6.0)))))
             '(ambient 1.0) '(diffuse 0.0) '(id "diskShader"))

(plane-ring `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0)) '(normal #(0.0 0.0 1.0))
            `(rin ,(* 3.0 rs)) `(rout ,(* 7.5 rs)) '(emitter "keplerian")
            '(shader "diskShader") '(id "disk"))
(comp-object '(obj "disk") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
