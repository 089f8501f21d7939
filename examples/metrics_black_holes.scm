;; ---------------------------------------------------------------------
;;  Black holes beyond Schwarzschild: the shadow and the lensed grid sky
;;  of a Reissner-Nordstrom black hole (charge Q = 0.9M; photon sphere
;;  r = (3M + sqrt(9M^2 - 8Q^2))/2). Switch the spacetime with
;;    --define 'spacetime="TaubNUT"'   (or "Kottler", "KerrBL",
;;    "JanisNewmanWinicour", "Ernst", "Schwarzschild")
;;
;;    geovis render examples/metrics_black_holes.scm -o black_hole.png
;; ---------------------------------------------------------------------

(define spacetime "ReissnerNordstrom")
(define coords 'spherical)
(define r_obs 25.0)
(define sky_radius 45.0)
(define fview 40.0)
(define res 150)
(define eps 1.0e-8)

(cond ((string=? spacetime "ReissnerNordstrom")
       (init-metric '(type "ReissnerNordstrom") '(mass 1.0) '(charge 0.9) '(id "metric")))
      ((string=? spacetime "TaubNUT")
       (init-metric '(type "TaubNUT") '(mass 1.0) '(l 0.5) '(id "metric")))
      ((string=? spacetime "Kottler")
       (init-metric '(type "Kottler") '(mass 1.0) '(lambda 0.0005) '(id "metric")))
      ((string=? spacetime "KerrBL")
       (init-metric '(type "KerrBL") '(mass 1.0) '(angmom 0.9) '(id "metric")))
      ((string=? spacetime "JanisNewmanWinicour")
       (init-metric '(type "JanisNewmanWinicour") '(mass 1.0) '(gamma 0.8) '(id "metric")))
      ((string=? spacetime "Ernst")
       (init-metric '(type "Ernst") '(mass 1.0) '(b 0.02) '(id "metric")))
      (else
       (init-metric `(type ,spacetime) '(mass 1.0) '(id "metric"))))

(load "include/lensing_view.scm")
