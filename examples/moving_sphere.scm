;; ---------------------------------------------------------------------
;;  Terrell-Penrose rotation (paper §1, refs. [2, 3]): a checkered sphere
;;  of radius 1 moves with beta = 0.5 along +y in Minkowski spacetime,
;;  passing x = y = 0 at t = 0; an identical sphere rests 2.5 above it
;;  as the reference. The observer sits at x = -10 and looks along +x.
;;  At t = 10 (frame 3) the light reaching the image centre left the
;;  moving sphere when it crossed the line of sight: it still looks like
;;  a sphere, but rotated by arcsin(beta) = 30 deg about the vertical
;;  axis (its trailing side shows; tests/render/test_relativity_effects.cpp
;;  measures this angle).
;;
;;  Rendered (7 frames, 160x120, one core: a few seconds) with
;;    geovis render examples/moving_sphere.scm --threads 1 -o /tmp/ms/f_%04d.png
;; ---------------------------------------------------------------------

(define beta 0.5)
(define times (map (lambda (n) (+ 4.0 (* 2.0 n))) (iota 7)))   ; t = 4 ... 16

(init-metric '(type "Minkowski") '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp")
             '(geodType "lightlike")
             '(step_ctrl #f)
             '(step_size 1.0)
             '(id "raytracing"))

(init-camera '(type "PinHoleCam")
             '(dir #(1.0 0.0 0.0))
             '(vup #(0.0 0.0 1.0))
             '(fov #(60.0 45.0))
             '(res #(160 120))
             '(id "cam"))

(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) -50.0 -50.0 -50.0))
             `(boundBoxUR ,(vector gpDBLMAX 50.0 50.0 50.0))
             '(solver "raytracing")
             '(maxNumPoints 3000))

(local-tetrad '(pos #(0.0 -10.0 0.0 0.0))
              '(e0 #(1.0 0.0 0.0 0.0))
              '(e1 #(0.0 1.0 0.0 0.0))
              '(e2 #(0.0 0.0 1.0 0.0))
              '(e3 #(0.0 0.0 0.0 1.0))
              '(incoords #f)
              '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.05 0.05 0.1)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

(init-texture '(type "UniTex") '(color #(0.8 0.16 0.16)) '(id "red"))
(init-texture '(type "UniTex") '(color #(0.9 0.63 0.63)) '(id "pink"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "red") '(texture "pink")
                                       `(transform ,(scale-obj #(12.0 6.0)))))
             '(ambient 1.0) '(diffuse 0.0) '(id "sphereShader"))

;; Uniform motion: the sphere's rest frame moves with beta along +y.
(init-motion '(type "ConstVelocity") `(boost ,(vector 0.0 beta 0.0)) '(id "move"))

(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0)) '(axlen #(1.0 1.0 1.0))
                 '(shader "sphereShader") '(motion "move") '(id "moving"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 2.5)) '(axlen #(1.0 1.0 1.0))
                 '(shader "sphereShader") '(id "resting"))
(comp-object '(obj "moving") '(obj "resting") '(id "scene"))

(for-each (lambda (t)
            (init-device '(type "standard") '(obj "scene") '(camera "cam")
                         `(setparam ("locTedObs" "time" ,t))))
          times)
