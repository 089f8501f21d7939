;; ---------------------------------------------------------------------
;;  geovis example helper: a celestial sphere with a latitude/longitude
;;  grid texture (textures/sky_grid.png, 15 degree lines, one colour per
;;  quadrant so that orientation is visible).
;;
;;  Define `sky_radius` before loading this file. It creates the shader
;;  "skyShader" and the coordinate object "sky".
;; ---------------------------------------------------------------------

(init-shader '(type "SurfShader")
             `(objcolor ,(init-texture '(type "Image")
                                       '(file "textures/sky_grid.png")
                                       `(transform ,(scale-obj #(-1.0 -1.0)))))
             '(ambient 1.0)
             '(diffuse 0.0)
             '(id "skyShader"))

(solid-ellipsoid `(objtype ,gpObjTypeInCoords)
                 '(center #(0.0 0.0 0.0))
                 `(axlen ,(vector sky_radius sky_radius sky_radius))
                 '(shader "skyShader")
                 '(id "sky"))
