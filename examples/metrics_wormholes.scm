;; ---------------------------------------------------------------------
;;  Wormholes: a rotating Teo wormhole (TeoSimpleWH, throat b0 = 1) seen
;;  from l = 6 in the upper universe; the lower universe (l < 0, chart 1)
;;  has no sky and stays black, so the throat shows as a dark disk with
;;  the lensed upper sky around it. --define 'spacetime="MorrisThorne"'
;;  for the static wormhole of paper eq. 11.
;;
;;    geovis render examples/metrics_wormholes.scm -o wormhole_teo.png
;; ---------------------------------------------------------------------

(define spacetime "TeoSimpleWH")
(define coords 'spherical)
(define r_obs 6.0)
(define sky_radius 40.0)
(define fview 60.0)
(define res 200)
(define eps 1.0e-8)
(init-metric `(type ,spacetime) '(b0 1.0) '(id "metric"))
(load "include/lensing_view.scm")
