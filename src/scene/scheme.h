// The GeoViS scene language: an embedded Guile 3.0 evaluator that runs a scene program and records
// every GeoViS command call as a parameter set (scene/description.h).
//
// Scenes are Scheme (define, let, do, quasiquote, string-append, getenv, load, ...) evaluated
// in a fresh module per scene (by default a sandbox, docs/security.md), with the GeoViS prelude (catalogue §1
// "Constants from Parser/init.scm") and every GeoViS command (catalogue §1) available. Like GeoViS's TinyScheme reader
// (catalogue, Conventions) symbols are folded to lower case, so keys and variable names are case-insensitive; strings
// keep their case.
//
// Every Guile error (syntax error, unbound variable, wrong argument, ...) and every malformed
// command argument becomes a geovis::Error / SceneError whose message starts with the scene
// file's "file:line" (reader errors keep Guile's "file:line:column"). Checking keys and values
// against the plugins' ParamSpecs is the builder's job (scene/builder.h).
//
// Transform matrices (translate-obj, rotate-obj, scale-obj) become core/params.h Transform values.
// A 2D (2x3, texture-coordinate) matrix [[a b tx] [c d ty]] is stored as the 4x4
// [[a b 0 tx] [c d 0 ty] [0 0 1 0] [0 0 0 1]] with dim = 2, so that it acts on (u, v, 0, 1).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "scene/description.h"

namespace geovis {

struct SchemeOptions {
  /// `--define NAME=VALUE` overrides: the scene's top-level `(define NAME ...)` gets VALUE (read
  /// as a Scheme datum: 30, 2.5, "text", #t) instead of its own expression. Names are
  /// case-insensitive. An override whose name the scene never defines is a warning in `diag`.
  std::vector<std::pair<std::string, std::string>> defines;
  /// Receives warnings (unused --define, unset environment variable in getenv). May be null.
  Diagnostics* diag = nullptr;
  /// Safety limit on the number of recorded command calls (a runaway loop fails with a clear
  /// error instead of exhausting memory).
  size_t max_calls = 5'000'000;
  /// Wall-clock limit for evaluating the scene in seconds (0 = none): an endless Scheme loop
  /// fails with a clear error instead of hanging (--scene-time-limit).
  double time_limit_seconds = 60;
  /// Limit on the Scheme heap the evaluation may add, in bytes (0 = none): an unbounded
  /// allocation fails with a clear error instead of exhausting the machine (--scene-memory-limit).
  size_t memory_limit_bytes = size_t{2} << 30;
  /// false (the default): the scene runs in the sandbox of docs/security.md (only the scene
  /// language, pure Scheme, display/newline, confined load and getenv). true (--trust-scene):
  /// full Guile, as GeoViS.
  bool trusted = false;
  /// Folders besides the scene's own from which `load` may read (--scene-path); a relative name
  /// that is not found next to the loading file is looked up in them, in order.
  std::vector<std::string> load_paths;
  /// false (-q): what the scene prints (display, m4d-metriclist, ...) is discarded.
  bool print_output = true;
};

/// The environment variables a sandboxed scene may read with getenv (docs/security.md): HOME,
/// USER, LOGNAME and every GEOVIS_* variable.
bool scene_may_read_env(const std::string& name);

/// Thrown when the scene calls (exit [code]): evaluation stops and nothing must be rendered
/// (GeoViS terminates the program there). The CLI exits with code() without an error report.
class SceneExit : public Error {
 public:
  SceneExit(const std::string& msg, int code);
  int code() const { return code_; }

 private:
  int code_ = 0;
};

/// Evaluates the scene file `path`. `load` inside it is relative to the loading file's folder.
/// Throws Error / SceneError with "file:line" on any problem; never terminates the process.
SceneDescription evaluate_scene_file(const std::string& path, const SchemeOptions& opts = {});

/// Evaluates scene text; `name` is used as the file name in messages and its folder (if any) as
/// the base for `load`.
SceneDescription evaluate_scene_string(const std::string& text, const std::string& name,
                                       const SchemeOptions& opts = {});

/// The GeoViS commands that record a call (init-metric, ..., gvs-print), in catalogue order.
const std::vector<std::string>& scene_command_names();
/// The recording commands that geovis adds to GeoViS's (plane-parallelogram); a subset of
/// scene_command_names().
const std::vector<std::string>& scene_extension_command_names();

/// Every name the scene language defines beyond standard Scheme: the recording commands, the
/// immediate commands (vec3, rotate-obj, get-parameter, m4d-metriclist, exit, ...) and the prelude
/// constants/functions (gpObjTypeInCoords, PI, DEG_TO_RAD, calcHFoV, ...), lower case.
const std::vector<std::string>& scene_language_names();

}  // namespace geovis
