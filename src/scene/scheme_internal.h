// Internals shared by scheme.cpp (Guile setup, evaluation driver, error conversion) and
// scheme_commands.cpp (the GeoViS commands). Not part of the scene layer's interface.
#pragma once

#include <libguile.h>

#include <exception>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/scheme.h"

namespace geovis::scheme_detail {

/// The Scheme source of the prelude module (geovis prelude), read with symbols folded to lower case.
extern const char* const kPreludeSource;

/// One file being evaluated (the scene, or a file it loads): where its current top-level form is.
struct FileFrame {
  std::string file;   ///< as it appears in messages
  std::string dir;    ///< base folder for `load`
  int form_line = 0;  ///< 1-based line of the top-level form being evaluated
};

/// State of the one evaluation in progress on this thread (evaluations are serialised).
struct EvalContext {
  SceneDescription desc;
  const SchemeOptions* opts = nullptr;
  std::vector<FileFrame> files;
  std::unordered_map<std::string, size_t> ids;  ///< object id -> index of its call in desc.calls
  std::vector<std::string> defines;             ///< top-level define names seen, in order
  std::set<std::string> used_overrides;
  std::exception_ptr pending;  ///< C++ error raised inside a primitive
  int generated_ids = 0;
};

EvalContext& context();  ///< the current evaluation (only valid while one runs)

/// Defines the C primitives (%gv-call, ...) in the current module. Called once, inside the
/// (geovis prelude) module definition.
void define_command_primitives();

/// Location of the top-level form being evaluated in the innermost file.
SourceLoc current_form_loc();

/// Stores the current C++ exception in the context and raises the Scheme exception
/// 'geovis-error, which the driver turns back into that C++ exception. Must be called from a
/// catch block's end (after every C++ object of the primitive is destroyed), never returns.
[[noreturn]] void raise_pending_in_scheme();

/// The end of every "... is not available in scenes" message (docs/security.md).
inline constexpr const char* kSandboxHint = "they run sandboxed; --trust-scene lifts this";

/// Short description of a Scheme value for error messages: "the number 3", "the symbol foo", ...
std::string describe_scm(SCM v);

}  // namespace geovis::scheme_detail
