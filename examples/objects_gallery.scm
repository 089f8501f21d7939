;; ---------------------------------------------------------------------
;;  Every kind of scene object and texture in flat spacetime, so that
;;  the geometry can be compared with intuition before adding gravity:
;;  ellipsoid, box, cylinder, solid ring, plane ring, triangle, an OBJ
;;  mesh, CSG difference/union/intersection, a compound with an octree,
;;  a local object in a rotated local tetrad; textures UniTex,
;;  CheckerT2D, ChequeredT2D, DieT2D, ColorGradTex and an image.
;;  The curved-spacetime counterparts are the metrics_*.scm examples.
;;
;;    geovis render examples/objects_gallery.scm -o objects.png
;; ---------------------------------------------------------------------

(init-metric '(type "Minkowski") '(id "metric"))
(init-solver '(type "RK4") '(geodType "lightlike") '(step_ctrl #f) '(step_size 2.0) '(id "raytracing"))
(init-camera '(type "PinHoleCam") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0))
             '(fov #(60.0 40.0)) '(res #(300 200)) '(id "cam"))
(init-raygen '(type "RayGenSimple")
             `(boundBoxLL ,(vector (- gpDBLMAX) -60.0 -60.0 -60.0))
             `(boundBoxUR ,(vector gpDBLMAX 60.0 60.0 60.0))
             '(solver "raytracing") '(maxNumPoints 3000))
(local-tetrad '(pos #(0.0 -14.0 0.0 4.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 0.96 0.0 -0.28))
              '(e2 #(0.0 0.0 1.0 0.0)) '(e3 #(0.0 0.28 0.0 0.96))
              '(incoords #f) '(id "eye"))
(init-projector '(localTetrad "eye") '(color #(0.1 0.1 0.12)) '(id "proj"))
(init-light-mgr '(ambient #(1.0 1.0 1.0)))

;; --- textures
(init-texture '(type "UniTex") '(color #(0.85 0.2 0.15)) '(id "red"))
(init-texture '(type "UniTex") '(color #(0.95 0.95 0.9)) '(id "white"))
(init-texture '(type "UniTex") '(color #(0.15 0.3 0.8)) '(id "blue"))
(init-texture '(type "UniTex") '(colorgray 0.25) '(id "grey"))
(define (shader id tex amb dif)
  (init-shader '(type "SurfShader") `(objcolor ,tex) `(ambient ,amb) `(diffuse ,dif) `(id ,id)))
(shader "checker" (init-texture '(type "CheckerT2D") '(texture "red") '(texture "white")
                                `(transform ,(scale-obj #(12.0 6.0)))) 0.3 0.8)
(shader "chequered" (init-texture '(type "ChequeredT2D") '(texture "blue") '(texture "white")
                                  '(width 0.2) `(transform ,(scale-obj #(8.0 8.0)))) 0.3 0.8)
(shader "die" (init-texture '(type "DieT2D") '(texture "white") '(texture "red")) 0.4 0.7)
(shader "gradient" (init-texture '(type "ColorGradTex") '(color1 #(0.1 0.2 0.9)) '(color2 #(0.9 0.8 0.1))
                                 '(start #(0.0 0.0)) '(end #(1.0 0.0))) 0.4 0.7)
(shader "image" (init-texture '(type "Image") '(file "textures/sky_grid.png")) 0.5 0.6)
(shader "plain" "grey" 0.5 0.6)

;; --- primitives in the metric's (pseudo-)Cartesian coordinates
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0.0 -6.0 1.2)) '(axlen #(1.2 1.2 1.2))
                 '(shader "checker") '(id "ellipsoid"))
(solid-box `(objtype ,gpObjTypeInCoords) '(cornerLL #(-1.0 -3.0 0.0)) '(cornerUR #(1.0 -1.0 2.0))
           `(transform ,(rotate-obj "z" 25.0)) '(shader "die") '(id "box"))
(solid-cylinder `(objtype ,gpObjTypeInCoords) '(base #(0.0 1.5 0.0)) '(top #(0.0 1.5 2.5))
                '(radii #(0.8 0.8)) '(shader "chequered") '(id "cylinder"))
(solid-ring `(objtype ,gpObjTypeInCoords) '(base #(0.0 5.0 0.0)) '(top #(0.0 5.0 0.8))
            '(radii #(1.4 1.4)) '(innerradii #(0.9 0.9)) '(shader "gradient") '(id "ring"))
(plane-ring `(objtype ,gpObjTypeInCoords) '(center #(4.0 0.0 4.5)) '(normal #(-1.0 0.0 0.3))
            '(rin 1.0) '(rout 2.2) '(shader "checker") '(id "annulus"))
(plane-triangle `(objtype ,gpObjTypeInCoords) '(p1 #(4.0 -7.0 3.0)) '(p2 #(4.0 -4.0 3.0))
                '(p3 #(4.0 -5.5 5.5)) '(shader "gradient") '(id "triangle"))
;; geovis extension (not in GeoViS): the parallelogram p1, p2, p3, p2 + p3 - p1
(plane-parallelogram `(objtype ,gpObjTypeInCoords) '(p1 #(4.0 -3.9 3.2)) '(p2 #(4.0 -2.8 3.2))
                     '(p3 #(4.0 -3.4 5.0)) '(shader "chequered") '(id "parallelogram"))
(mesh-obj `(objtype ,gpObjTypeInCoords) '(pathname "meshes") '(filename "icosahedron.obj")
          `(transform ,(translate-obj #(0.0 8.5 1.3) (scale-obj #(1.3 1.3 1.3))))
          '(shader "image") '(id "mesh"))

;; --- constructive solid geometry
(solid-box `(objtype ,gpObjTypeInCoords) '(cornerLL #(3.0 2.0 0.0)) '(cornerUR #(5.0 4.0 2.0))
           '(shader "plain") '(id "csgBox"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(3.0 3.0 2.0)) '(axlen #(1.2 1.2 1.2))
                 '(shader "checker") '(id "csgBall"))
(csg-object `(csgtype ,gpCSGDifferObj) '(obj1 "csgBox") '(obj2 "csgBall") '(id "bitten"))
;; union: two overlapping balls (upper left)
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(3.0 5.2 3.7)) '(axlen #(0.7 0.7 0.7))
                 '(shader "gradient") '(id "unionA"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(3.0 6.1 3.7)) '(axlen #(0.7 0.7 0.7))
                 '(shader "checker") '(id "unionB"))
(csg-object `(csgtype ,gpCSGUnifiedObj) '(obj1 "unionA") '(obj2 "unionB") '(id "pair"))
;; intersection: a cube with rounded corners (box within a ball)
(solid-box `(objtype ,gpObjTypeInCoords) '(cornerLL #(2.4 2.6 3.4)) '(cornerUR #(3.6 3.8 4.6))
           '(shader "die") '(id "roundBox"))
(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(3.0 3.2 4.0)) '(axlen #(0.8 0.8 0.8))
                 '(shader "die") '(id "roundBall"))
(csg-object `(csgtype ,gpCSGIntersecObj) '(obj1 "roundBox") '(obj2 "roundBall") '(id "rounded"))

;; --- an octree compound of small spheres (a floor of beads)
(define beads '())
(do ((i 0 (+ i 1))) ((= i 12))
  (do ((j 0 (+ j 1))) ((= j 12))
    (set! beads (cons (solid-ellipsoid `(objtype ,gpObjTypeInCoords)
                                       `(center ,(vector (+ 6.0 (* 1.0 i)) (+ -6.0 (* 1.0 j)) -0.3))
                                       '(axlen #(0.3 0.3 0.3)) '(shader "chequered"))
                      beads))))
(apply comp-octree-object
       (append (map (lambda (b) (list 'obj b)) beads)
               (list '(lower #(5.0 -7.0 -1.0)) '(upper #(18.0 7.0 1.0)) '(subdivs 3) '(id "beads"))))

;; --- a local object: a box in a tilted local tetrad
(solid-box `(objtype ,gpObjTypeLocal) '(cornerLL #(-0.5 -0.5 -0.5)) '(cornerUR #(0.5 0.5 0.5))
           '(shader "die") '(id "localBox"))
(local-tetrad '(pos #(0.0 -2.0 -6.0 4.0))
              '(e0 #(1.0 0.0 0.0 0.0)) '(e1 #(0.0 0.7071068 0.7071068 0.0))
              '(e2 #(0.0 -0.7071068 0.7071068 0.0)) '(e3 #(0.0 0.0 0.0 1.0))
              '(incoords #f) '(id "boxFrame"))
(local-comp-object '(obj "localBox") '(localtetrad "boxFrame") '(id "tiltedBox"))

(define sky_radius 50.0)
(load "include/grid_sky.scm")
(comp-object '(obj "ellipsoid") '(obj "box") '(obj "cylinder") '(obj "ring") '(obj "annulus")
             '(obj "triangle") '(obj "parallelogram") '(obj "mesh") '(obj "bitten") '(obj "pair") '(obj "rounded")
             '(obj "beads") '(obj "tiltedBox")
             '(obj "sky") '(id "scene"))
(init-device '(type "standard") '(obj "scene") '(camera "cam"))
