;; ---------------------------------------------------------------------
;;  Paper §4.4, Fig. 6: the shadows of two black holes (m1 = m2 = 1 at
;;  z = +-4) in the Kastor-Traschen spacetime (paper eq. 12) with Hubble
;;  parameter H = 0.02, seen from x = 40 at observation time t = 0.
;;  --define 'spacetime="DeSitterUniv"' shows the empty expanding
;;  universe instead.
;;
;;    geovis render examples/metrics_cosmology.scm -o kastor_traschen.png
;; ---------------------------------------------------------------------

(define spacetime "KastorTraschen")
(define coords 'cartesian)
(define r_obs 40.0)
(define sky_radius 150.0)
(define fview 40.0)
(define res 100)                     ; KastorTraschen is the slowest metric (~2 ms per ray)
(define eps 1.0e-9)
(if (string=? spacetime "KastorTraschen")
    (init-metric '(type "KastorTraschen") '(h 0.02) '(m1 1.0) '(m2 1.0) '(z1 4.0) '(z2 -4.0) '(id "metric"))
    (init-metric `(type ,spacetime) '(id "metric")))
(load "include/lensing_view.scm")
