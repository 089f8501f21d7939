;; ---------------------------------------------------------------------
;;  Exotic spacetimes: the global monopole of Barriola and Vilenkin
;;  (k = 0.8: a solid-angle deficit, the whole sky appears shrunk towards
;;  the centre without any shadow). Other choices:
;;    --define 'spacetime="AlcubierreWarpSimple"' (warp bubble, cartesian)
;;    --define 'spacetime="RotDihole"'            (two extreme charged holes)
;;
;;    geovis render examples/metrics_exotic.scm -o monopole.png
;; ---------------------------------------------------------------------

(define spacetime "BarriolaVilenkin")
(define r_obs 20.0)
(define sky_radius 45.0)
(define fview 50.0)
(define res 200)
(define eps 1.0e-8)
(define coords (if (member spacetime '("AlcubierreWarpSimple" "RotDihole")) 'cartesian 'spherical))
(init-metric `(type ,spacetime) '(id "metric"))
(load "include/lensing_view.scm")
