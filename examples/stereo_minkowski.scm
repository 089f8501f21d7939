;; ---------------------------------------------------------------------
;;  Stereo pinhole pair (PinHoleStereoCam, eye separation `sep`) in flat
;;  spacetime: a checkered sphere, a die-textured box and a triangle in
;;  front of the grid sky. One device gives two images,
;;  NAME.left.png and NAME.right.png.
;;
;;    geovis render examples/stereo_minkowski.scm -o stereo.png
;; ---------------------------------------------------------------------

(init-metric '(type "Minkowski") '(id "metric"))
(init-solver '(type "RK4") '(geodType "lightlike") '(step_ctrl #f) '(step_size 2.0) '(id "raytracing"))
(init-camera '(type "PinHoleStereoCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0))
             '(fov #(50.0 40.0)) '(res #(200 160)) '(sep 0.3) '(id "stereo"))
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) -60.0 -60.0 -60.0))
             `(boundBoxUR ,(vector gpDBLMAX 60.0 60.0 60.0))
             '(solver "raytracing") '(maxNumPoints 3000))
(local-tetrad '(pos #(0.0 -8.0 0.0 1.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 1.0 0.0 0.0))
              '(e2 #(0.0 0.0 1.0 0.0)) '(e3 #(0.0 0.0 0.0 1.0))
              '(incoords #f) '(id "eye"))
(init-projector '(localTetrad "eye") '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

(init-texture '(type "UniTex") '(color #(0.2 0.4 0.9)) '(id "blue"))
(init-texture '(type "UniTex") '(color #(0.9 0.9 0.9)) '(id "white"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "CheckerT2D") '(texture "blue") '(texture "white")
                                       `(transform ,(scale-obj #(16.0 8.0)))))
             '(ambient 0.3) '(diffuse 0.8) '(id "checker"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "DieT2D") '(texture "white") '(texture "blue")))
             '(ambient 0.4) '(diffuse 0.7) '(id "die"))
(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "UniTex") '(color #(0.9 0.7 0.1))))
             '(ambient 0.4) '(diffuse 0.7) '(id "gold"))

(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0.0 -1.5 1.0)) '(axlen #(1.2 1.2 1.2))
                 '(shader "checker") '(id "ball"))
(solid-box `(objtype ,gpObjTypeInCoords) '(cornerLL #(-1.0 1.0 0.0)) '(cornerUR #(1.0 3.0 2.0))
           `(transform ,(rotate-obj "z" 30.0)) '(shader "die") '(id "box"))
(plane-triangle `(objtype ,gpObjTypeInCoords) '(p1 #(3.0 -3.0 -0.5)) '(p2 #(3.0 3.0 -0.5))
                '(p3 #(3.0 0.0 3.5)) '(shader "gold") '(id "tri"))
(define sky_radius 50.0)
(load "include/grid_sky.scm")
(comp-object '(obj "ball") '(obj "box") '(obj "tri") '(obj "sky") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "stereo"))
