// The GeoViS prelude: the constants and helpers of GeoViS's Parser/init.scm (catalogue §1
// "Constants from Parser/init.scm"), the command syntax of the scene language (catalogue §1), a
// TinyScheme-compatible `do`, scene-relative `load`, and the evaluation driver.
//
// This text is evaluated once per process in the module (geovis prelude); every scene gets a fresh
// module into which the names listed in %gv-scene-bindings are copied (so a scene redefining PI or
// init-metric changes only its own module). It is read with symbols folded to lower case, like a
// scene, so `PIhalf` here is the symbol `pihalf`.
#include "scene/scheme_internal.h"

namespace geovis::scheme_detail {

const char* const kPreludeSource = R"SCM(
(use-modules (system syntax) (system vm vm) (ice-9 sandbox))

;; Guile 3.0's list->typed-array (and list->array, which calls it in C) crashes the process with a
;; segmentation fault while raising its own out-of-range error when its shape is an integer rank
;; below 0 or beyond 64 bits; the reader makes that call for an array literal such as
;; #55555555555555555555(1 2), which the fuzzer put into a scene (fuzz_smoke). The guarded versions
;; raise the error themselves. Set in (guile), so that the reader (ice-9 read), the sandbox's copies
;; of the bindings and trusted scenes all call them.
(let ((guile (resolve-module '(guile))))
  (define (check-rank who shape)
    (when (and (exact-integer? shape) (not (<= 0 shape most-positive-fixnum)))
      (scm-error 'out-of-range who "array rank out of range (0 to ~a): ~a"
                 (list most-positive-fixnum shape) (list shape))))
  (let ((list->typed-array (module-ref guile 'list->typed-array))
        (list->array (module-ref guile 'list->array)))
    (module-set! guile 'list->typed-array
                 (lambda (type shape lst)
                   (check-rank "list->typed-array" shape)
                   (list->typed-array type shape lst)))
    (module-set! guile 'list->array
                 (lambda (shape lst)
                   (check-rank "list->array" shape)
                   (list->array shape lst)))))

;; ---------------------------------------------------------------------------------------------
;; Constants and helpers of GeoViS Parser/init.scm (catalogue §1).
(define gpObjTypeLocal 0)     ; object given in a local (tetrad) frame, wrapped by local-comp-object
(define gpObjTypeInCoords 1)  ; object given in the metric's pseudo-Cartesian coordinates

(define gpCSGDifferObj 1)
(define gpCSGUnifiedObj 2)
(define gpCSGIntersecObj 3)

;; Index into Motion4D's enum_nat_tetrad_type (catalogue §1), used as '(localframe N).
(define gpTetradDefault    0)
(define gpTetradStatic     1)
(define gpTetradLNRF       2)
(define gpTetradFreefall   3)
(define gpTetradComoving   4)
(define gpTetradCylinder   5)
(define gpTetradCartesian  6)

;; The values of init.scm, digit for digit (PIhalf and PI2 are rounded there as here).
(define PI     3.141592653589793)
(define PIhalf 1.570796326794897)
(define PI2    6.283185307179586)
(define gpDBLMAX 1.844674407370955616e19)
(define DEG_TO_RAD  0.017453292519943295770)
(define RAD_TO_DEG 57.295779513082320875)

(define (radians val) (* val DEG_TO_RAD))
(define (degrees val) (* val RAD_TO_DEG))

;; Horizontal field of view (degrees) of a pinhole camera with square pixels, resolution
;; resX x resY and vertical field of view vfov (degrees): the image-plane half extents at unit
;; distance are tan(hfov/2) and tan(vfov/2) and their ratio is resX/resY.
(define (calcHFoV resX resY vfov)
  (* 2.0 RAD_TO_DEG (atan (* (/ resX resY) (tan (* 0.5 vfov DEG_TO_RAD))))))

;; ---------------------------------------------------------------------------------------------
;; `do` as TinyScheme's: the body may contain definitions (minkWheel.scm does
;; (do (...) (...) (define angle ...) ...)), which R7RS `do` forbids.
(define-syntax gv-do
  (syntax-rules ()
    ((_ ((var init step ...) ...) (test expr ...) command ...)
     (let loop ((var init) ...)
       (if test
           (begin (if #f #f) expr ...)
           (begin
             (let () command ... (if #f #f))
             (loop (gv-do "step" var step ...) ...)))))
    ((_ "step" x) x)
    ((_ "step" x y) y)))

;; ---------------------------------------------------------------------------------------------
;; Command syntax. Each GeoViS command is a macro so that the call records where it was made:
;; (init-metric '(type "Kerr") ...) expands to
;; (%gv-call "init-metric" '#(file line line-of-arg1 ...) (list '(type "Kerr") ...)).
;; Used as a value (e.g. (map init-texture ...)) it is a procedure without location.
(define (%gv-source-line s)
  (let ((src (syntax-source s)))
    (if (and src (assq-ref src 'line)) (+ 1 (assq-ref src 'line)) 0)))

(define (%gv-source-file s)
  (let ((src (syntax-source s)))
    (and src (assq-ref src 'filename))))

(define (%gv-form-locations form args)
  (list->vector (cons* (%gv-source-file form) (%gv-source-line form) (map %gv-source-line args))))

(define-syntax %gv-define-command
  (syntax-rules ()
    ((_ name str)
     (define-syntax name
       (lambda (x)
         (syntax-case x ()
           ((_ arg (... ...))
            (with-syntax ((locs (datum->syntax x (%gv-form-locations x #'(arg (... ...))))))
              #'(%gv-call str 'locs (list arg (... ...)))))
           (id (identifier? #'id)
            #'(lambda args (%gv-call str #f args)))))))))

;; The commands of the scene language, each a macro as above, and %gv-scene-bindings: the names
;; every scene module gets, (scene-name . prelude-name). Both are generated from the command table
;; (command_table.cpp) and spliced in here when the prelude is evaluated (scheme.cpp).
;; @GEOVIS-COMMANDS@
(%gv-define-command gv-exit "exit")
(%gv-define-command gv-getenv "getenv")

;; Transform matrices (translate-obj, rotate-obj, scale-obj): dim 2 or 3 and the 16 entries of
;; the homogeneous 4x4 matrix, row-major (core/params.h Transform).
(define <gv-matrix>
  (make-record-type 'gv-matrix '(dim elements)
    (lambda (m port)
      (format port "#<~aD transform ~a>" ((record-accessor <gv-matrix> 'dim) m)
              ((record-accessor <gv-matrix> 'elements) m)))))
(define %gv-make-matrix (record-constructor <gv-matrix>))
(define %gv-matrix? (record-predicate <gv-matrix>))
(define %gv-matrix-dim (record-accessor <gv-matrix> 'dim))
(define %gv-matrix-elements (record-accessor <gv-matrix> 'elements))

;; ---------------------------------------------------------------------------------------------
;; Evaluation driver.
(define %gv-scene-module #f)
(define %gv-overrides '())     ; ((symbol . datum) ...) from --define NAME=VALUE
(define %gv-current-form #f)   ; top-level form being evaluated (for locating unbound names)

;; ice-9/read.scm keeps per-port reader options in 2-bit fields (#b11 = inherit the global
;; option); field 2 is case-insensitive. #xFFF7 = inherit everything, fold case on.
(define %gv-fold-case-options #xFFF7)

(define (%gv-fold-case! port)
  (%set-port-property! port 'port-read-options %gv-fold-case-options))

;; (define NAME expr) with NAME overridden by --define becomes (define NAME 'VALUE).
(define (%gv-apply-override form)
  (let ((d (syntax->datum form)))
    (if (and (pair? d) (eq? (car d) 'define) (pair? (cdr d)) (symbol? (cadr d)))
        (let ((name (cadr d)))
          (%gv-note-define (symbol->string name))
          (let ((o (assq name %gv-overrides)))
            (if o
                (begin
                  (%gv-note-override-used (symbol->string name))
                  (list 'define name (list 'quote (cdr o))))
                form)))
        form)))

;; Skips white space and ; comments, so that the port's line is that of the next form: an error
;; the reader raises without a location of its own (the array-rank guard above) names that line.
(define (%gv-skip-blank port)
  (let ((c (peek-char port)))
    (cond ((eof-object? c))
          ((char-whitespace? c) (read-char port) (%gv-skip-blank port))
          ((eqv? c #\;)
           (let drop ((c (read-char port)))
             (unless (or (eof-object? c) (eqv? c #\newline)) (drop (read-char port))))
           (%gv-skip-blank port)))))

(define (%gv-eval-port port)
  (%gv-fold-case! port)
  (let loop ()
    (%gv-skip-blank port)
    (%gv-set-form-line! (+ 1 (port-line port)))
    (let ((form (read-syntax port)))
      (unless (eof-object? form)
        (set! %gv-current-form form)
        (%gv-set-form-line! (%gv-source-line form))
        (eval (%gv-apply-override form) %gv-scene-module)
        (loop)))))

(define (%gv-eval-file path)
  (call-with-input-file path %gv-eval-port #:encoding "UTF-8"))

(define (%gv-eval-string text name)
  (let ((port (open-input-string text)))
    (set-port-filename! port name)
    (%gv-eval-port port)))

;; `load` relative to the folder of the file containing the call.
(define (gv-load file)
  (let ((path (%gv-enter-file file))
        (outer-form %gv-current-form))
    (%gv-eval-file path)
    (set! %gv-current-form outer-form)
    (%gv-leave-file)
    (if #f #f)))

(define (gv-quit . args) (apply gv-exit args))

;; Reads the --define values: ((name-string . text) ...) -> ((symbol . datum) ...). A reader
;; error names the option, not the string port ("#<unknown port>:1:2: ...").
(define (%gv-read-define d port)
  (catch 'read-error
    (lambda () (read port))
    (lambda (key subr msg args . rest)
      (let* ((text (%gv-safe-format msg args))
             (colon (string-contains text ": ")))
        (%gv-define-error (car d) (cdr d)
                          (string-append "the value is not a Scheme datum ("
                                         (if colon (substring text (+ colon 2)) text) ")"))))))

(define (%gv-read-overrides defs)
  (map (lambda (d)
         (let* ((port (open-input-string (cdr d)))
                (_ (%gv-fold-case! port))
                (datum (%gv-read-define d port))
                (rest (%gv-read-define d port)))
           (when (eof-object? datum)
             (%gv-define-error (car d) (cdr d) "the value is empty"))
           (unless (eof-object? rest)
             (%gv-define-error (car d) (cdr d) "the value must be a single Scheme datum (a number, \"a string\", #t or #f)"))
           (cons (string->symbol (string-downcase (car d))) datum)))
       defs))

;; Innermost occurrence (with a source position) of identifier `sym` in form `x`, as a line.
;; read-syntax gives syntax objects whose expressions are lists of syntax objects.
(define (%gv-find-identifier-line x sym)
  (let walk ((x x) (depth 0))
    (and (< depth 100000)
         (cond
          ((pair? x) (or (walk (car x) (+ depth 1)) (walk (cdr x) (+ depth 1))))
          ((syntax? x)
           (syntax-case x ()
             (id (identifier? #'id)
                 (and (eq? (syntax->datum #'id) sym)
                      (let ((l (%gv-source-line #'id))) (and (> l 0) l))))
             ((a . b) (or (walk #'a (+ depth 1)) (walk #'b (+ depth 1))))
             (_ #f)))
          (else #f)))))

(define (%gv-safe-format fmt args)
  (catch #t
    (lambda () (if (and (string? fmt) (list? args)) (apply format #f fmt args) (format #f "~s" fmt)))
    (lambda _ (format #f "~s ~s" fmt args))))

;; Turns a caught exception into (kind message line column name):
;;   kind: geovis (a C++ error of a primitive), exit, read, syntax, unbound, stack, other.
(define (%gv-describe-exception key args)
  (case key
    ((geovis-error) (list 'geovis "" 0 0 #f))
    ((geovis-exit) (list 'exit (if (pair? args) (car args) 0) 0 0 #f))
    ((out-of-memory) (list 'memory "" 0 0 #f))
    ((read-error)
     ;; args: (subr message format-args rest); the message starts with file:line:column.
     (list 'read (if (and (pair? args) (pair? (cdr args)) (pair? (cddr args)))
                     (%gv-safe-format (cadr args) (caddr args))
                     (%gv-safe-format "~s" (list args)))
           0 0 #f))
    ((syntax-error)
     ;; args: (who message source form subform)
     (let* ((who (and (pair? args) (car args)))
            (msg (if (and (pair? args) (pair? (cdr args))) (cadr args) "syntax error"))
            (src (and (pair? args) (pair? (cdr args)) (pair? (cddr args)) (caddr args)))
            (form (and (pair? args) (pair? (cdr args)) (pair? (cddr args)) (pair? (cdddr args))
                       (cadddr args)))
            (line (if (and (pair? src) (assq-ref src 'line)) (+ 1 (assq-ref src 'line)) 0))
            (col (if (and (pair? src) (assq-ref src 'column)) (+ 1 (assq-ref src 'column)) 0)))
       (list 'syntax
             (string-append
              (if (and who (symbol? who)) (string-append (symbol->string who) ": ") "")
              (if (string? msg) msg (%gv-safe-format "~s" (list msg)))
              (if form (string-append " in " (%gv-safe-format "~s" (list (syntax->datum form)))) ""))
             line col #f)))
    ((unbound-variable)
     (let ((name (and (pair? args) (pair? (cdr args)) (pair? (cddr args)) (pair? (caddr args))
                      (car (caddr args)))))
       (list (if (and (symbol? name) %gv-sandboxed (%gv-forbidden-name? name)) 'forbidden 'unbound)
             ""
             (or (and name (symbol? name) %gv-current-form
                      (%gv-find-identifier-line %gv-current-form name))
                 0)
             0
             (if (symbol? name) (symbol->string name) (%gv-safe-format "~s" (list name))))))
    (else
     (let* ((subr (and (pair? args) (car args)))
            (msg (if (and (pair? args) (pair? (cdr args)) (pair? (cddr args)))
                     (%gv-safe-format (cadr args) (caddr args))
                     (%gv-safe-format "~s" (list args)))))
       (list 'other
             (string-append
              (if (or (string? subr) (symbol? subr))
                  (string-append "in procedure " (if (symbol? subr) (symbol->string subr) subr) ": ")
                  "")
              msg
              (if (memq key '(misc-error wrong-type-arg out-of-range wrong-number-of-args
                              unbound-variable system-error numerical-overflow))
                  ""
                  (string-append " (" (%gv-safe-format "~s" (list key)) ")")))
             0 0 #f)))))

;; The expander names an anonymous module when it first expands code in it (boot-9
;; `module-name`: a gensym, registered in the module root so that `resolve-module` finds it);
;; unregister the finished scene's module so that it and everything it holds can be collected.
(define (%gv-forget-scene-module)
  (let ((m %gv-scene-module))
    (set! %gv-scene-module #f)
    (set! %gv-current-form #f)
    (when (module? m)
      (let ((name (module-name m))
            (root (resolve-module '() #f)))
        (when (and (pair? name) (null? (cdr name))
                   (eq? (hashq-ref (module-submodules root) (car name)) m))
          (hashq-remove! (module-submodules root) (car name)))))))

;; The limits (time, stack) stop the scene by aborting to this prompt rather than by throwing,
;; so that a scene's own (catch #t ...) cannot swallow them (as (ice-9 sandbox) does).
(define %gv-limit-tag (make-prompt-tag "geovis-limit"))
(define (%gv-abort-limit kind) (abort-to-prompt %gv-limit-tag kind))

;; Runs thunk; returns #t or the description of the exception that stopped it. The stack limit
;; turns runaway recursion into an error instead of exhausting memory. Without print-output the
;; scene's own printing (display, ...) goes to a void port (-q).
(define (%gv-run thunk stack-limit print-output)
  (let ((result
         (call-with-prompt %gv-limit-tag
           (lambda ()
             (catch #t
               (lambda ()
                 (call-with-stack-overflow-handler stack-limit
                   (if print-output
                       thunk
                       (lambda () (with-output-to-port (%make-void-port "w") thunk)))
                   (lambda () (%gv-abort-limit 'stack)))
                 #t)
               (lambda (key . args) (%gv-describe-exception key args))))
           (lambda (k kind)
             (list kind (if (eq? kind 'stack) "stack overflow (infinite recursion?)" "") 0 0 #f)))))
    (%gv-forget-scene-module)
    ;; What the scene displayed appears now, before anything the program prints next.
    (false-if-exception (force-output (current-output-port)))
    (false-if-exception (force-output (current-error-port)))
    result))


(define %gv-prelude-module (current-module))  ; evaluated while (geovis prelude) is being defined

;; ---------------------------------------------------------------------------------------------
;; The sandbox (docs/security.md). A sandboxed scene sees only the GeoViS names above, pure
;; Scheme ((ice-9 sandbox)'s binding sets: no ports, files, processes, modules or eval), set! and
;; printing to the terminal. Procedures are copied into the scene's module, so that its set!
;; changes only its own copy; syntax (define, cond, else, ...) stays imported, because literals
;; such as `else` are recognised by their binding, and set! of syntax is an error.
(define %gv-sandboxed #t)  ; the scene being evaluated runs in the sandbox

(define %gv-sandbox-bindings
  (append all-pure-and-impure-bindings
          ;; inexact->exact is missing from (ice-9 sandbox)'s number set; display and friends
          ;; print to the terminal (a scene has no way to name another port).
          '(((guile) set! inexact->exact display newline write write-char simple-format format))))

;; Names of full Guile that the sandbox leaves out (for the "not available" error).
(define (%gv-forbidden-name? sym)
  (or (module-variable (resolve-module '(guile)) sym)
      (or-map (lambda (name)
                (false-if-exception (module-variable (resolve-interface name) sym)))
              '((ice-9 popen) (ice-9 rdelim) (ice-9 ftw) (ice-9 textual-ports) (ice-9 binary-ports)
                (ice-9 ports) (ice-9 sandbox) (ice-9 threads) (ice-9 eval-string)))))

(define (%gv-make-sandbox-module)
  (let ((m (make-sandbox-module %gv-sandbox-bindings)))
    (for-each
     (lambda (set)
       (let ((iface (resolve-interface (car set))))
         (for-each (lambda (import)  ; NAME or (NAME-IN-MODULE . NAME-IN-SCENE)
                     (let ((v (module-ref iface (if (pair? import) (car import) import))))
                       (unless (macro? v)
                         (module-define! m (if (pair? import) (cdr import) import) v))))
                   (cdr set))))
     %gv-sandbox-bindings)
    m))

(define (%gv-make-scene-module sandboxed)
  (let ((m (if sandboxed (%gv-make-sandbox-module) (make-fresh-user-module)))
        (here %gv-prelude-module))
    (set! %gv-sandboxed sandboxed)
    (for-each (lambda (b) (module-define! m (car b) (module-ref here (cdr b))))
              %gv-scene-bindings)
    m))
)SCM";

}  // namespace geovis::scheme_detail
