// Embedded Guile 3.0: process-wide initialisation, one fresh module per scene, and the conversion of
// every Guile exception into a geovis::Error with the scene's file:line.
//
// Control flow: evaluate_* takes a process-wide lock, enters Guile mode (scm_with_guile), and
// calls the prelude's %gv-run, which catches every Scheme exception and returns a description of
// it. No C++ exception ever crosses a Guile frame: primitives store their C++ exception in the
// context and raise the Scheme exception 'geovis-error (scheme_commands.cpp); the driver rethrows
// the stored exception once Guile has returned.
#include <chrono>
#include <cstdlib>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <mutex>
#include <thread>
#include <sstream>

#include <gc/gc.h>

#include "scene/command_table.h"
#include "scene/scheme_internal.h"

namespace geovis {

SceneExit::SceneExit(const std::string& msg, int code) : Error(msg), code_(code) {}

namespace scheme_detail {
namespace {

std::mutex g_eval_mutex;       // one evaluation at a time (the context and prelude state are global)
bool g_prelude_ready = false;  // guarded by g_eval_mutex
SCM g_prelude_module = SCM_BOOL_F;
thread_local EvalContext* g_ctx = nullptr;

// Scheme procedures of the prelude used by the driver (looked up once).
SCM g_run_proc = SCM_BOOL_F;
SCM g_eval_file_proc = SCM_BOOL_F;
SCM g_eval_string_proc = SCM_BOOL_F;
SCM g_make_module_proc = SCM_BOOL_F;
SCM g_read_overrides_proc = SCM_BOOL_F;
SCM g_abort_limit_proc = SCM_BOOL_F;

// 2M words (16 MB) of Scheme stack for the scene: far more than any scene needs, small enough
// to stop infinite recursion quickly.
constexpr long kStackLimitWords = 2'000'000;

// ---- time limit: a watchdog thread interrupts the evaluating thread with a Guile async --------
std::mutex g_watch_mutex;
std::condition_variable g_watch_cv;
bool g_evaluating = false;       // %gv-run is running (guarded by g_watch_mutex)
bool g_watch_done = false;       // the evaluation is over; the watchdog must stop
SCM g_eval_thread = SCM_BOOL_F;  // the Guile thread running %gv-run
SCM g_time_limit_proc = SCM_BOOL_F;

// Runs as an async in the evaluating thread: stops it, unless that evaluation already ended.
// It aborts to the driver's prompt (%gv-abort-limit), which the scene's own catch cannot stop.
SCM time_limit_reached() {
  bool fire = false;
  {
    std::lock_guard<std::mutex> lock(g_watch_mutex);
    fire = g_evaluating;
  }
  if (fire) scm_call_1(g_abort_limit_proc, scm_from_utf8_symbol("time"));
  return SCM_UNSPECIFIED;
}

// ---- memory limit: the collector may not grow the heap beyond its size at the start plus the
// limit; an allocation beyond it raises Guile's out-of-memory exception (not a process-wide
// rlimit, which would also limit the render). The collector's "Out of Memory" warning is
// silenced meanwhile: the driver reports the limit.
void silent_gc_warning(char*, GC_word) {}
GC_warn_proc g_default_gc_warn = nullptr;

void set_heap_limit(size_t bytes) {
  if (bytes == 0) return;
  GC_set_max_heap_size(GC_get_heap_size() + bytes);
  g_default_gc_warn = GC_get_warn_proc();
  GC_set_warn_proc(silent_gc_warning);
}

void clear_heap_limit() {
  GC_set_max_heap_size(0);  // 0 = unlimited
  if (g_default_gc_warn) GC_set_warn_proc(g_default_gc_warn);
  g_default_gc_warn = nullptr;
}

void* mark_time_limit(void*) {
  std::unique_lock<std::mutex> lock(g_watch_mutex);
  if (g_evaluating) {
    SCM thread = g_eval_thread;
    lock.unlock();
    scm_system_async_mark_for_thread(g_time_limit_proc, thread);
  }
  return nullptr;
}

void watchdog(double seconds) {
  std::unique_lock<std::mutex> lock(g_watch_mutex);
  g_watch_cv.wait(lock, [] { return g_evaluating || g_watch_done; });
  if (g_watch_done) return;
  const auto limit = std::chrono::duration<double>(seconds);
  if (g_watch_cv.wait_for(lock, limit, [] { return g_watch_done; })) return;
  lock.unlock();
  scm_with_guile(mark_time_limit, nullptr);
}

void init_prelude_module(void*) {
  define_command_primitives();
  g_time_limit_proc =
      scm_c_make_gsubr("%gv-time-limit-reached", 0, 0, 0, reinterpret_cast<scm_t_subr>(time_limit_reached));
  scm_gc_protect_object(g_time_limit_proc);
  // Read the prelude with symbols folded to lower case, like a scene, and evaluate it here.
  std::string source = kPreludeSource;
  const std::string marker = ";; @GEOVIS-COMMANDS@";
  source.replace(source.find(marker), marker.size(), scheme_command_definitions());
  SCM port = scm_open_input_string(scm_from_utf8_string(source.c_str()));
  scm_set_port_filename_x(port, scm_from_utf8_string("geovis-prelude.scm"));
  // ice-9/read.scm per-port reader options: #xFFF7 = inherit all, case-insensitive on.
  scm_call_3(scm_c_public_ref("guile", "%set-port-property!"), port, scm_from_utf8_symbol("port-read-options"),
             scm_from_int(0xFFF7));
  SCM module = scm_current_module();
  for (;;) {
    SCM form = scm_read(port);
    if (scm_is_true(scm_eof_object_p(form))) break;
    scm_eval(form, module);
  }
}

struct PreludeInit {
  std::string error;
};

SCM init_prelude_body(void* data) {
  (void)data;
  g_prelude_module = scm_c_define_module("geovis prelude", init_prelude_module, nullptr);
  scm_gc_protect_object(g_prelude_module);
  auto ref = [](const char* name) {
    SCM v = scm_variable_ref(scm_c_module_lookup(g_prelude_module, name));
    scm_gc_protect_object(v);
    return v;
  };
  g_run_proc = ref("%gv-run");
  g_eval_file_proc = ref("%gv-eval-file");
  g_eval_string_proc = ref("%gv-eval-string");
  g_make_module_proc = ref("%gv-make-scene-module");
  g_read_overrides_proc = ref("%gv-read-overrides");
  g_abort_limit_proc = ref("%gv-abort-limit");
  return SCM_BOOL_T;
}

SCM init_prelude_handler(void* data, SCM key, SCM args) {
  auto* out = static_cast<PreludeInit*>(data);
  SCM s = scm_simple_format(SCM_BOOL_F, scm_from_utf8_string("~s ~s"), scm_list_2(key, args));
  char* c = scm_to_utf8_string(s);
  out->error = c;
  free(c);
  return SCM_BOOL_F;
}

// What one evaluation is asked to do (passed through scm_with_guile).
struct EvalRequest {
  bool from_file = true;
  std::string path_or_text;
  std::string name;
  // results
  bool finished = false;  // %gv-run returned #t
  std::string kind;       // else: geovis, exit, read, syntax, unbound, stack, other, internal
  std::string message;
  int line = 0;
  int column = 0;
  std::string name_found;  // unbound variable name
  int exit_code = 0;
};

std::string scm_string_or(SCM s, const std::string& fallback) {
  if (!scm_is_string(s)) return fallback;
  char* c = scm_to_utf8_string(s);
  std::string r(c);
  free(c);
  return r;
}

// The body evaluated in Guile mode. It only calls into Scheme through %gv-run (which catches
// everything) and an outer scm_c_catch for safety; C++ state lives in `req`, which outlives it.
SCM eval_body(void* data) {
  auto* req = static_cast<EvalRequest*>(data);
  EvalContext& ctx = *g_ctx;
  // Fresh module for this scene.
  SCM module = scm_call_1(g_make_module_proc, scm_from_bool(!ctx.opts->trusted));
  scm_variable_set_x(scm_c_module_lookup(g_prelude_module, "%gv-scene-module"), module);
  scm_variable_set_x(scm_c_module_lookup(g_prelude_module, "%gv-current-form"), SCM_BOOL_F);
  scm_variable_set_x(scm_c_module_lookup(g_prelude_module, "%gv-overrides"), SCM_EOL);

  // Overrides (read as Scheme data inside %gv-run, so a malformed VALUE is reported, not fatal).
  SCM defs = SCM_EOL;
  for (auto it = ctx.opts->defines.rbegin(); it != ctx.opts->defines.rend(); ++it)
    defs = scm_cons(scm_cons(scm_from_utf8_stringn(it->first.data(), it->first.size()),
                             scm_from_utf8_stringn(it->second.data(), it->second.size())),
                    defs);
  SCM thunk;
  SCM target = scm_from_utf8_stringn(req->path_or_text.data(), req->path_or_text.size());
  SCM name = scm_from_utf8_stringn(req->name.data(), req->name.size());
  // (lambda () (set! %gv-overrides (%gv-read-overrides defs)) (eval-file/-string ...))
  SCM setup = scm_list_3(scm_from_utf8_symbol("set!"), scm_from_utf8_symbol("%gv-overrides"),
                         scm_list_2(g_read_overrides_proc, scm_list_2(scm_from_utf8_symbol("quote"), defs)));
  SCM call = req->from_file ? scm_list_2(g_eval_file_proc, target) : scm_list_3(g_eval_string_proc, target, name);
  thunk = scm_eval(scm_list_4(scm_from_utf8_symbol("lambda"), SCM_EOL, setup, call), g_prelude_module);

  {
    std::lock_guard<std::mutex> lock(g_watch_mutex);
    g_eval_thread = scm_current_thread();
    g_evaluating = true;
  }
  g_watch_cv.notify_all();
  set_heap_limit(ctx.opts->memory_limit_bytes);  // cleared by run() whatever happens here
  SCM result = scm_call_3(g_run_proc, thunk, scm_from_long(kStackLimitWords), scm_from_bool(ctx.opts->print_output));
  clear_heap_limit();
  {
    std::lock_guard<std::mutex> lock(g_watch_mutex);
    g_evaluating = false;
  }
  if (scm_is_eq(result, SCM_BOOL_T)) {
    req->finished = true;
    return SCM_BOOL_T;
  }
  // (kind message line column name)
  if (scm_ilength(result) != 5) {
    req->kind = "internal";
    req->message = "unexpected result from the scene evaluator";
    return SCM_BOOL_F;
  }
  SCM kind = scm_list_ref(result, scm_from_int(0));
  SCM msg = scm_list_ref(result, scm_from_int(1));
  SCM line = scm_list_ref(result, scm_from_int(2));
  SCM col = scm_list_ref(result, scm_from_int(3));
  SCM nm = scm_list_ref(result, scm_from_int(4));
  req->kind = scm_is_symbol(kind) ? scm_string_or(scm_symbol_to_string(kind), "other") : "other";
  if (req->kind == "exit") {
    req->exit_code = scm_is_integer(msg) && scm_is_signed_integer(msg, -1000000, 1000000) ? scm_to_int(msg)
                                                                                          : (scm_is_false(msg) ? 1 : 0);
  } else {
    req->message = scm_string_or(msg, "");
  }
  req->line = scm_is_signed_integer(line, 0, 1 << 30) ? scm_to_int(line) : 0;
  req->column = scm_is_signed_integer(col, 0, 1 << 30) ? scm_to_int(col) : 0;
  req->name_found = scm_string_or(nm, "");
  return SCM_BOOL_F;
}

SCM eval_handler(void* data, SCM key, SCM args) {
  auto* req = static_cast<EvalRequest*>(data);
  req->kind = "internal";
  SCM s = scm_simple_format(SCM_BOOL_F, scm_from_utf8_string("~s ~s"), scm_list_2(key, args));
  req->message = scm_string_or(s, "unknown Guile error");
  return SCM_BOOL_F;
}

void* eval_in_guile(void* data) {
  auto* req = static_cast<EvalRequest*>(data);
  if (!g_prelude_ready) {
    PreludeInit init;
    SCM r = scm_c_catch(SCM_BOOL_T, init_prelude_body, nullptr, init_prelude_handler, &init, nullptr, nullptr);
    if (!scm_is_true(r)) {
      req->kind = "internal";
      req->message = "could not load the GeoViS prelude: " + init.error;
      return nullptr;
    }
    g_prelude_ready = true;
  }
  scm_c_catch(SCM_BOOL_T, eval_body, req, eval_handler, req, nullptr, nullptr);
  return nullptr;
}

// "2 GiB", "64 MiB", "1000 bytes".
std::string format_bytes(size_t bytes) {
  static const char* const units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024 && u < 4) {
    v /= 1024;
    ++u;
  }
  std::ostringstream os;
  os << v << " " << units[u];
  return os.str();
}

std::string parent_dir(const std::string& path) {
  std::filesystem::path p(path);
  std::string d = p.parent_path().string();
  return d.empty() ? std::string(".") : d;
}

// "; the ( at file:L:C is never closed" (or the string starting there): a small Scheme lexer
// (comments ; #| |# , strings with escapes, characters #\x) run over the text that ended early.
std::string unclosed_hint(const std::string& text, const std::string& file) {
  struct Pos {
    int line, col;
  };
  std::vector<Pos> open;
  int line = 1, col = 1;
  size_t i = 0;
  const size_t n = text.size();
  auto advance = [&](size_t k) {
    for (size_t j = 0; j < k && i < n; ++j, ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
  };
  while (i < n) {
    const char c = text[i];
    if (c == ';') {
      while (i < n && text[i] != '\n') advance(1);
    } else if (c == '#' && i + 1 < n && text[i + 1] == '|') {
      int depth = 0;
      do {
        if (text.compare(i, 2, "#|") == 0) {
          ++depth;
          advance(2);
        } else if (text.compare(i, 2, "|#") == 0) {
          --depth;
          advance(2);
        } else {
          advance(1);
        }
      } while (i < n && depth > 0);
    } else if (c == '#' && i + 1 < n && text[i + 1] == '\\') {
      advance(3);  // #\x, including #\( #\) #\"
    } else if (c == '"') {
      const Pos start{line, col};
      advance(1);
      while (i < n && text[i] != '"') advance(text[i] == '\\' ? 2 : 1);
      if (i >= n)
        return "; the string starting at " + file + ":" + std::to_string(start.line) + ":" + std::to_string(start.col) +
               " is never closed";
      advance(1);
    } else if (c == '(' || c == '[') {
      open.push_back(Pos{line, col});
      advance(1);
    } else if (c == ')' || c == ']') {
      if (!open.empty()) open.pop_back();
      advance(1);
    } else {
      advance(1);
    }
  }
  if (open.empty()) return "";
  return "; the ( at " + file + ":" + std::to_string(open.front().line) + ":" + std::to_string(open.front().col) +
         " is never closed";
}

// Guile and its collector (libgc) take the first thread that enters Guile for the process's main
// thread and never unregister it. If that thread ends (the first evaluation ran on a short-lived
// thread: a test's std::thread, a server's worker), the next collection sends it the stop signal,
// which an ended thread never answers, and the process aborts ("Signals delivery fails
// constantly"; bdwgc issue 542). So Guile is first entered by a thread of its own that lasts as
// long as the process (idle, it answers the collector's signals); every thread that evaluates a
// scene is then registered with the collector, and unregistered when it ends, by Guile.
void enter_guile_first_on_a_lasting_thread() {
  static std::once_flag once;
  std::call_once(once, [] {
    std::promise<void> entered;
    std::future<void> done = entered.get_future();
    std::thread([entered = std::move(entered)]() mutable {
      scm_with_guile([](void*) -> void* { return nullptr; }, nullptr);
      entered.set_value();
      for (;;) std::this_thread::sleep_for(std::chrono::hours(24));
    }).detach();
    done.wait();
  });
}

SceneDescription run(EvalRequest& req, const std::string& file, const SchemeOptions& opts) {
  std::lock_guard<std::mutex> lock(g_eval_mutex);
  enter_guile_first_on_a_lasting_thread();
  EvalContext ctx;
  ctx.opts = &opts;
  ctx.desc.file = file;
  ctx.desc.dir = parent_dir(file);
  ctx.files.push_back(FileFrame{file, ctx.desc.dir, 0});
  g_ctx = &ctx;
  struct Reset {
    std::thread watch;
    ~Reset() {
      g_ctx = nullptr;
      if (watch.joinable()) {
        {
          std::lock_guard<std::mutex> lock(g_watch_mutex);
          g_watch_done = true;
        }
        g_watch_cv.notify_all();
        watch.join();
      }
    }
  } reset;
  {
    std::lock_guard<std::mutex> lock(g_watch_mutex);
    g_watch_done = false;
    g_evaluating = false;
  }
  if (opts.time_limit_seconds > 0) reset.watch = std::thread(watchdog, opts.time_limit_seconds);

  scm_with_guile(eval_in_guile, &req);
  clear_heap_limit();

  if (!req.finished) {
    if (req.kind == "geovis" && ctx.pending) std::rethrow_exception(ctx.pending);
    const SourceLoc where = current_form_loc();
    if (req.kind == "exit") {
      throw SceneExit(format_diagnostic(where, "exit", "",
                                        "the scene called (exit " + std::to_string(req.exit_code) +
                                            "); evaluation stopped, nothing will be rendered"),
                      req.exit_code);
    }
    if (req.kind == "read") {
      // Guile's reader message already starts with file:line:column; at the end of the input
      // it points at the end of the file, so say where the unclosed string or form starts.
      std::string msg = req.message;
      if (msg.find("end of input") != std::string::npos) {
        const FileFrame& f = ctx.files.back();
        std::string text;
        if (ctx.files.size() == 1 && !req.from_file) {
          text = req.path_or_text;
        } else {
          std::ifstream in(f.file, std::ios::binary);
          text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
        msg += unclosed_hint(text, f.file);
      }
      throw Error(msg);
    }
    SourceLoc loc = where;
    if (req.line > 0) loc.line = req.line;
    if (req.kind == "syntax") {
      std::string pos = loc.str();
      if (req.line > 0 && req.column > 0) pos += ":" + std::to_string(req.column);
      throw Error((pos.empty() ? "" : pos + ": ") + "syntax error: " + req.message);
    }
    if (req.kind == "unbound") {
      const std::string& name = req.name_found;
      const std::vector<std::string>& language = scene_language_names();
      // A misspelled GeoViS command ("init-metrik") or a name in a command family ("init-foo").
      static const char* const kCommandPrefixes[] = {"init-", "solid-", "plane-", "comp-", "local-", "mesh-", "csg-",
                                                     "add-",  "set-",   "get-",   "gvs-",  "calc-",  "m4d-"};
      bool command_like = false;
      for (const char* prefix : kCommandPrefixes) command_like = command_like || name.rfind(prefix, 0) == 0;
      command_like =
          command_like || (name.find('-') != std::string::npos && !closest_name(name, scene_command_names()).empty());
      if (command_like) {
        const std::string hint = did_you_mean(name, language);
        throw SceneError(loc, "", "",
                         "unknown command \"" + name + "\"" +
                             (hint.empty() ? " (GeoViS commands: " + join(scene_command_names()) + ")" : hint));
      }
      std::vector<std::string> candidates = ctx.defines;
      candidates.insert(candidates.end(), language.begin(), language.end());
      throw SceneError(loc, "", "", "unbound variable \"" + name + "\"" + did_you_mean(name, candidates));
    }
    if (req.kind == "stack") throw SceneError(loc, "", "", req.message);
    if (req.kind == "time") {
      std::ostringstream os;
      os << "the scene ran longer than the time limit of " << opts.time_limit_seconds
         << " s (an endless loop?); stopped here (--scene-time-limit changes the limit)";
      throw SceneError(loc, "", "", os.str());
    }
    if (req.kind == "memory") {
      std::ostringstream os;
      os << "the scene needs more memory than the limit of " << format_bytes(opts.memory_limit_bytes)
         << " (an unbounded allocation?); stopped here (--scene-memory-limit changes the limit)";
      throw SceneError(loc, "", "", os.str());
    }
    if (req.kind == "forbidden")
      throw SceneError(loc, "", "", "\"" + req.name_found + "\" is not available in scenes (" + kSandboxHint + ")");
    if (req.kind == "internal") throw Error(file + ": " + req.message);
    if (req.kind == "geovis") throw SceneError(loc, "", "", "internal error: lost the error of a command");
    throw SceneError(loc, "", "", req.message);
  }

  // --define overrides that the scene never defined.
  for (const auto& [name, value] : opts.defines) {
    const std::string lname = to_lower(name);
    if (ctx.used_overrides.count(lname)) continue;
    std::string msg = "--define " + name + "=" + value + ": the scene has no top-level (define " + lname +
                      " ...); the value is not used" + did_you_mean(lname, ctx.defines);
    if (!ctx.defines.empty()) msg += " (the scene defines: " + join(ctx.defines) + ")";
    if (opts.diag) opts.diag->warn(SourceLoc{file, 0}, "", "", msg);
  }
  return std::move(ctx.desc);
}

}  // namespace

EvalContext& context() { return *g_ctx; }

SourceLoc current_form_loc() {
  if (!g_ctx || g_ctx->files.empty()) return {};
  const FileFrame& f = g_ctx->files.back();
  return SourceLoc{f.file, f.form_line};
}

}  // namespace scheme_detail

SceneDescription evaluate_scene_file(const std::string& path, const SchemeOptions& opts) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(path + ": cannot read the scene file: " +
                (std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  scheme_detail::EvalRequest req;
  req.from_file = true;
  req.path_or_text = path;
  req.name = path;
  return scheme_detail::run(req, path, opts);
}

SceneDescription evaluate_scene_string(const std::string& text, const std::string& name, const SchemeOptions& opts) {
  scheme_detail::EvalRequest req;
  req.from_file = false;
  req.path_or_text = text;
  req.name = name;
  return scheme_detail::run(req, name, opts);
}

}  // namespace geovis
