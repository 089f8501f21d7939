;; ---------------------------------------------------------------------
;;  Paper Fig. 8 / §4.6: a wheel of radius 2 rolls with v = 0.8c along
;;  the negative y axis in Minkowski spacetime (the rim's top moves with
;;  2v/(1+v^2) = 0.9756c relative to the ground). The wheel is a CSG ring
;;  plus hub and eight spokes, all with a ConstVelocity motion (boost +
;;  rigid rotation omega = v/r = 0.4). A point light casts shadows on the
;;  checkered block (shadow rays are exact in Minkowski for objects at
;;  rest). The observer sits at (x, y, z) = (-15, 0, 4) and looks down
;;  18 degrees; 11 frames at observation times t = 8.6 ... 21.6, among them
;;  the paper's t = 13.8 and 20.3.
;;
;;  The default 128x90 renders all 11 frames in ~20 s user time on one
;;  core (examples/README.md). docs/gallery/fig8.gif was rendered at
;;  160x112 and assembled with
;;    geovis render examples/fig8_rolling_wheel.scm --threads 1 --res 160x112 -o /tmp/fig8/f_%04d.png
;;    ffmpeg -y -framerate 4 -i /tmp/fig8/f_%04d.png \
;;      -vf "split[a][b];[a]palettegen[p];[b][p]paletteuse" docs/gallery/fig8.gif
;; ---------------------------------------------------------------------

(define viewAngle -18.0)
;; observation times t = 8.6 + 1.3 n, n = 0..10; the paper's Fig. 8 shows
;; t = 13.8 (n = 4) and t = 20.3 (n = 9)
(define times (map (lambda (n) (+ 8.6 (* 1.3 n))) (iota 11)))

(init-metric '(type "Minkowski") '(id "metric"))
(init-solver '(type "GSL_RK_Cash-Karp")
             '(geodType "lightlike")
             '(step_ctrl #f)
             '(step_size 1.0)
             '(id "raytracing"))

(init-camera '(type "PinHoleCam")
             `(dir ,(vector (cos (radians viewAngle)) 0.0 (sin (radians viewAngle))))
             `(vup ,(vector (- (sin (radians viewAngle))) 0.0 (cos (radians viewAngle))))
             '(fov #(50.0 35.0))
             '(res #(128 90))
             '(id "cam"))

(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) -100.0 -100.0 -100.0))
             `(boundBoxUR ,(vector gpDBLMAX 100.0 100.0 100.0))
             '(solver "raytracing")
             '(maxNumPoints 3000))

(local-tetrad '(pos #(0.0 -15.0 0.0 4.0))
              '(e0 #(1.0 0.0 0.0 0.0))
              '(e1 #(0.0 1.0 0.0 0.0))
              '(e2 #(0.0 0.0 1.0 0.0))
              '(e3 #(0.0 0.0 0.0 1.0))
              '(incoords #f)
              '(id "locTedObs"))
(init-projector '(localTetrad "locTedObs") '(color #(0.05 0.05 0.1)) '(id "proj"))

(init-light '(type "PointLight")
            '(pos #(0.0 20.0 0.0 25.0))
            '(color #(1.0 1.0 1.0))
            '(atten #(0.0 0.0 0.0))
            '(id "lamp"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)) '(light "lamp") '(shadows #t))

(init-texture '(type "UniTex") '(color #(0.8 0.16 0.16)) '(id "red"))
(init-texture '(type "UniTex") '(color #(0.9 0.63 0.63)) '(id "pink"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "red") '(texture "pink")
                                       `(transform ,(scale-obj #(10.0 10.0)))))
             '(ambient 0.2) '(diffuse 0.8) '(id "wheelShader"))

(init-texture '(type "UniTex") '(color #(0.8 0.8 0.8)) '(id "light"))
(init-texture '(type "UniTex") '(color #(0.3 0.3 0.3)) '(id "dark"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "light") '(texture "dark")
                                       `(transform ,(scale-obj #(10.0 10.0)))))
             '(ambient 0.2) '(diffuse 0.0) '(id "floorShader"))

;; Rolling: boost v = 0.8 along -y, rotation omega = v / r = 0.4 about +x.
(init-motion '(type "ConstVelocity") '(boost #(0.0 -0.8 0.0)) '(rotation #(0.4 1.0 0.0 0.0)) '(id "roll"))

(solid-cylinder `(objtype ,gpObjTypeInCoords) '(base #(-0.15 0.0 0.0)) '(top #(0.15 0.0 0.0))
                '(radii #(2.0 2.0)) '(shader "wheelShader") '(motion "roll") '(id "rimOuter"))
(solid-cylinder `(objtype ,gpObjTypeInCoords) '(base #(-0.152 0.0 0.0)) '(top #(0.152 0.0 0.0))
                '(radii #(1.8 1.8)) '(shader "wheelShader") '(motion "roll") '(id "rimInner"))
(csg-object `(csgtype ,gpCSGDifferObj) '(obj1 "rimOuter") '(obj2 "rimInner") '(id "rim"))
(solid-cylinder `(objtype ,gpObjTypeInCoords) '(base #(-0.1 0.0 0.0)) '(top #(0.1 0.0 0.0))
                '(radii #(0.3 0.3)) '(shader "wheelShader") '(motion "roll") '(id "hub"))

(solid-box `(objtype ,gpObjTypeInCoords)
           '(cornerLL #(-5.0 -9.0 -5.0))
           '(cornerUR #(5.0 9.0 -2.0))
           '(shader "floorShader")
           '(id "block"))

(comp-object '(obj "rim") '(obj "hub") '(obj "block") '(id "scene"))

(do ((n 0 (+ n 1))) ((= n 8))
  (solid-cylinder `(objtype ,gpObjTypeInCoords)
                  '(base #(0.0 0.0 0.0)) '(top #(0.0 0.0 1.9)) '(radii #(0.05 0.05))
                  '(shader "wheelShader") '(motion "roll")
                  `(transform ,(rotate-obj "x" (* 45.0 n)))
                  `(id ,(string-append "spoke" (number->string n))))
  (add-object '(add-to "scene") `(obj ,(string-append "spoke" (number->string n)))))

(for-each (lambda (t)
            (init-device '(type "standard") '(obj "scene") '(camera "cam")
                         `(setparam ("locTedObs" "time" ,t))))
          times)
