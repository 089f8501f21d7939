// The GeoViS commands of the scene language (catalogue §1) as Guile primitives.
//
// Recording commands (init-metric, solid-box, init-device, ...) turn their '(key value ...)
// arguments into a ParamSet (keys lower case, repeated keys kept in order, Scheme values converted
// to core/params.h Values) and append a CommandCall; they return the object's id string, so
// `(objcolor ,(init-texture ...)) refers to the texture just made. Immediate commands (vec3, vec4,
// translate-obj, rotate-obj, scale-obj, get-parameter, m4d-metriclist, m4d-solverlist, getenv,
// exit) return a value.
//
// Every primitive runs its C++ work inside try/catch; a C++ exception is stored in the context
// and re-raised in Scheme as 'geovis-error (only after all C++ objects of the frame are gone),
// so no C++ exception crosses Guile frames and no Guile non-local exit skips a C++ destructor.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/rotation.h"
#include "scene/command_table.h"
#include "scene/scheme_internal.h"
#include "spacetime/geodesic.h"
#include "spacetime/metric_registry.h"

namespace geovis {

const std::vector<std::string>& scene_command_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const SceneCommand& c : scene_commands())
      if (c.role != CommandRole::Immediate) n.emplace_back(c.name);
    return n;
  }();
  return names;
}

const std::vector<std::string>& scene_extension_command_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const SceneCommand& c : scene_commands())
      if (c.geovis_extension) n.emplace_back(c.name);
    return n;
  }();
  return names;
}

const std::vector<std::string>& scene_language_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = scene_command_list();
    for (const auto& [scene_name, prelude_name] : scene_constant_bindings())
      if (scene_name != "do" && scene_name != "quit" && scene_name.rfind("primitive-", 0) != 0) n.push_back(scene_name);
    return n;
  }();
  return names;
}

bool scene_may_read_env(const std::string& name) {
  return name == "HOME" || name == "USER" || name == "LOGNAME" || name.rfind("GEOVIS_", 0) == 0;
}

namespace scheme_detail {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxValueDepth = 32;  // nesting of lists inside a value
constexpr size_t kMaxLoadDepth = 64;

// ----------------------------------------------------------------------------------------------
// Small Guile helpers (none of them can raise a Scheme exception for the inputs they check).

std::string to_std(SCM s) {
  size_t len = 0;
  char* c = scm_to_utf8_stringn(s, &len);
  std::string r(c, len);
  free(c);
  return r;
}

std::string symbol_name(SCM sym) { return to_std(scm_symbol_to_string(sym)); }

SCM prelude_proc(const char* name) { return scm_variable_ref(scm_c_private_lookup("geovis prelude", name)); }

bool is_matrix(SCM v) {
  static SCM pred = prelude_proc("%gv-matrix?");
  return scm_is_true(scm_call_1(pred, v));
}

Transform matrix_to_transform(SCM v) {
  static SCM dim_proc = prelude_proc("%gv-matrix-dim");
  static SCM elems_proc = prelude_proc("%gv-matrix-elements");
  Transform t;
  t.dim = scm_to_int(scm_call_1(dim_proc, v));
  SCM e = scm_call_1(elems_proc, v);
  for (size_t i = 0; i < 16; ++i) t.m[i] = scm_to_double(scm_c_vector_ref(e, i));
  return t;
}

SCM transform_to_matrix(const Transform& t) {
  static SCM make_proc = prelude_proc("%gv-make-matrix");
  SCM e = scm_c_make_vector(16, SCM_BOOL_F);
  for (size_t i = 0; i < 16; ++i) scm_c_vector_set_x(e, i, scm_from_double(t.m[i]));
  return scm_call_2(make_proc, scm_from_int(t.dim), e);
}

std::string truncated(std::string s, size_t n = 80) {
  if (s.size() > n) s = s.substr(0, n) + "...";
  return s;
}

}  // namespace

std::string describe_scm(SCM v) {
  if (scm_is_bool(v)) return scm_is_true(v) ? "the boolean #t" : "the boolean #f";
  if (scm_is_real(v)) return "the number " + to_std(scm_number_to_string(v, scm_from_int(10)));
  if (scm_is_number(v)) return "the complex number " + to_std(scm_number_to_string(v, scm_from_int(10)));
  if (scm_is_string(v)) return "the string \"" + truncated(to_std(v), 60) + "\"";
  if (scm_is_symbol(v)) return "the symbol " + truncated(symbol_name(v), 60);
  if (scm_is_null(v)) return "the empty list ()";
  if (scm_is_eq(v, SCM_UNSPECIFIED)) return "no value (#<unspecified>)";
  if (scm_is_true(scm_procedure_p(v))) return "a procedure";
  if (is_matrix(v)) return "a transform matrix";
  const std::string text = truncated(to_std(scm_object_to_string(v, SCM_UNDEFINED)));
  if (scm_is_pair(v)) return "the list " + text;
  if (scm_is_vector(v)) return "the vector " + text;
  return text;
}

void raise_pending_in_scheme() {
  scm_throw(scm_from_utf8_symbol("geovis-error"), SCM_EOL);
  std::abort();  // scm_throw does not return
}

namespace {

// ----------------------------------------------------------------------------------------------
// Where a command was called: the macro passes #(file line line-of-arg1 ...) (0 = unknown).
struct CallSite {
  SourceLoc loc;
  std::vector<int> arg_lines;
  SourceLoc arg_loc(size_t i) const {
    if (i < arg_lines.size() && arg_lines[i] > 0) return SourceLoc{loc.file, arg_lines[i]};
    return loc;
  }
};

CallSite call_site(SCM locs) {
  CallSite site;
  site.loc = current_form_loc();
  if (!scm_is_vector(locs) || scm_c_vector_length(locs) < 2) return site;
  SCM file = scm_c_vector_ref(locs, 0);
  if (scm_is_string(file)) site.loc.file = to_std(file);
  SCM line = scm_c_vector_ref(locs, 1);
  if (scm_is_signed_integer(line, 1, 1 << 30)) site.loc.line = scm_to_int(line);
  for (size_t i = 2; i < scm_c_vector_length(locs); ++i) {
    SCM l = scm_c_vector_ref(locs, i);
    site.arg_lines.push_back(scm_is_signed_integer(l, 1, 1 << 30) ? scm_to_int(l) : 0);
  }
  return site;
}

// Argument list of a call as a vector of SCM (on the stack frame of the caller: the list itself
// stays referenced by the Scheme caller, so the elements are alive).
std::vector<SCM> list_items(SCM list) {
  std::vector<SCM> out;
  for (SCM p = list; scm_is_pair(p); p = scm_cdr(p)) out.push_back(scm_car(p));
  return out;
}

// ----------------------------------------------------------------------------------------------
// Scheme value -> Value.
struct ValueContext {
  const SourceLoc& loc;
  const std::string& command;
  const std::string& key;
};

Value to_value(SCM v, const ValueContext& c, int depth = 0) {
  if (depth > kMaxValueDepth)
    throw SceneError(c.loc, c.command, c.key, "value is nested too deeply (more than 32 levels of lists)");
  if (scm_is_bool(v)) return Value(scm_is_true(v));
  if (scm_is_real(v)) return Value(scm_to_double(v));
  if (scm_is_string(v)) return Value(to_std(v));
  if (scm_is_symbol(v)) return Value(to_lower(symbol_name(v)));
  if (scm_is_vector(v)) {
    const size_t n = scm_c_vector_length(v);
    std::vector<double> out(n);
    for (size_t i = 0; i < n; ++i) {
      SCM e = scm_c_vector_ref(v, i);
      if (!scm_is_real(e))
        throw SceneError(c.loc, c.command, c.key,
                         "expected a vector of numbers, found " + describe_scm(e) + " at position " +
                             std::to_string(i + 1) + " of " + describe_scm(v));
      out[i] = scm_to_double(e);
    }
    return Value(std::move(out));
  }
  if (scm_is_null(v)) return Value(ValueList{});
  if (scm_is_pair(v)) {
    SCM head = scm_car(v);
    if (scm_is_eq(head, scm_from_utf8_symbol("unquote")) || scm_is_eq(head, scm_from_utf8_symbol("unquote-splicing")))
      throw SceneError(c.loc, c.command, c.key,
                       "found the unevaluated expression " + truncated(to_std(scm_object_to_string(v, SCM_UNDEFINED))) +
                           ": a ,expr is only evaluated inside a backquoted list; write `(" + c.key +
                           " ,...) instead of '(" + c.key + " ,...)");
    if (scm_ilength(v) < 0)
      throw SceneError(c.loc, c.command, c.key,
                       "expected a proper list, found the dotted or circular list " +
                           truncated(to_std(scm_object_to_string(v, SCM_UNDEFINED))));
    ValueList out;
    for (SCM p = v; scm_is_pair(p); p = scm_cdr(p)) out.push_back(to_value(scm_car(p), c, depth + 1));
    return Value(std::move(out));
  }
  if (is_matrix(v)) return Value(matrix_to_transform(v));
  throw SceneError(c.loc, c.command, c.key,
                   "expected a number, string, boolean, vector #(...), matrix or list, found " + describe_scm(v));
}

SCM from_value(const Value& v) {
  struct V {
    SCM operator()(std::monostate) const { return SCM_UNSPECIFIED; }
    SCM operator()(bool b) const { return scm_from_bool(b); }
    SCM operator()(double d) const { return scm_from_double(d); }
    SCM operator()(const std::string& s) const { return scm_from_utf8_stringn(s.data(), s.size()); }
    SCM operator()(const std::vector<double>& x) const {
      SCM vec = scm_c_make_vector(x.size(), SCM_BOOL_F);
      for (size_t i = 0; i < x.size(); ++i) scm_c_vector_set_x(vec, i, scm_from_double(x[i]));
      return vec;
    }
    SCM operator()(const Transform& t) const { return transform_to_matrix(t); }
    SCM operator()(const ValueList& l) const {
      SCM out = SCM_EOL;
      for (auto it = l.rbegin(); it != l.rend(); ++it) out = scm_cons(from_value(*it), out);
      return out;
    }
  };
  return std::visit(V{}, v.v);
}

// ----------------------------------------------------------------------------------------------
// Recording commands.

bool is_target_command(const std::string& cmd) {
  // Their `id` names an existing object instead of defining one.
  return cmd == "set-parameter" || cmd == "gvs-print" || cmd == "gvs-print-motion";
}

std::vector<std::string> known_ids(const EvalContext& ctx) {
  std::vector<std::string> ids;
  ids.reserve(ctx.ids.size());
  for (const auto& [id, index] : ctx.ids) ids.push_back(id);
  return ids;
}

// Parses the '(key value ...) arguments of a command into `ps`.
void parse_arguments(const std::string& cmd, const CallSite& site, SCM args, ParamSet& ps) {
  const std::vector<SCM> items = list_items(args);
  for (size_t i = 0; i < items.size(); ++i) {
    SCM a = items[i];
    const SourceLoc loc = site.arg_loc(i);
    const std::string nth = "argument " + std::to_string(i + 1);
    if (!scm_is_pair(a))
      throw SceneError(loc, cmd, "",
                       nth + ": expected a (key value) list such as '(id \"name\"), found " + describe_scm(a));
    SCM key = scm_car(a);
    if (!scm_is_symbol(key))
      throw SceneError(loc, cmd, "",
                       nth + ": expected a (key value) list starting with a symbol key, found " + describe_scm(a));
    const std::string k = to_lower(symbol_name(key));
    const long n = scm_ilength(scm_cdr(a));
    if (n < 0) throw SceneError(loc, cmd, k, "expected a (key value) list, found the dotted pair " + describe_scm(a));
    if (n == 0) throw SceneError(loc, cmd, k, "the key has no value: expected (" + k + " value)");
    const ValueContext vc{loc, cmd, k};
    for (SCM p = scm_cdr(a); scm_is_pair(p); p = scm_cdr(p)) {
      Value v = to_value(scm_car(p), vc);
      if (k == "setparam") {
        // ("objID" "param" value), catalogue §1 conventions.
        const auto* l = std::get_if<ValueList>(&v.v);
        if (!l || l->size() != 3 || !(*l)[0].is_string() || !(*l)[1].is_string())
          throw SceneError(loc, cmd, k, "expected (\"objID\" \"param\" value), found " + describe_scm(scm_car(p)));
      }
      ps.add(k, std::move(v), loc);
    }
  }
}

SCM record_command(const std::string& cmd, const CallSite& site, SCM args) {
  EvalContext& ctx = context();
  if (ctx.desc.calls.size() >= ctx.opts->max_calls)
    throw SceneError(
        site.loc, cmd, "",
        "the scene made more than " + std::to_string(ctx.opts->max_calls) + " command calls (runaway loop?)");
  ParamSet ps(cmd, site.loc);
  parse_arguments(cmd, site, args, ps);

  const auto ids = ps.find_all("id");
  if (ids.size() > 1) throw SceneError(ids[1]->loc, cmd, "id", "the id is given more than once");
  const Param* idp = ids.empty() ? nullptr : ids[0];
  if (idp && !idp->value.is_string())
    throw SceneError(idp->loc, cmd, "id", "expected a string, found " + idp->value.describe());

  if (is_target_command(cmd)) {
    if (!idp)
      throw SceneError(
          site.loc, cmd, "id",
          "this key is required: the id of the object to " + std::string(cmd == "set-parameter" ? "change" : "print"));
    const std::string& id = std::get<std::string>(idp->value.v);
    if (!ctx.ids.count(id))
      throw SceneError(idp->loc, cmd, "id",
                       "no object with id \"" + id + "\" has been defined before" + did_you_mean(id, known_ids(ctx)));
    ctx.desc.calls.push_back(CommandCall{cmd, std::move(ps)});
    return scm_from_utf8_stringn(id.data(), id.size());
  }

  std::string id;
  if (idp) {
    id = std::get<std::string>(idp->value.v);
    auto it = ctx.ids.find(id);
    if (it != ctx.ids.end()) {
      const CommandCall& prev = ctx.desc.calls[it->second];
      throw SceneError(
          idp->loc, cmd, "id",
          "the id \"" + id + "\" is already used by the " + prev.command + " at " + prev.params.loc().str());
    }
  } else {
    // GeoViS names objects without an id "unknownN" (catalogue §1 conventions).
    do {
      id = "unknown" + std::to_string(ctx.generated_ids++);
    } while (ctx.ids.count(id));
    ps.add("id", Value(id), site.loc);
  }
  ctx.ids.emplace(id, ctx.desc.calls.size());
  ctx.desc.calls.push_back(CommandCall{cmd, std::move(ps)});
  return scm_from_utf8_stringn(id.data(), id.size());
}

// ----------------------------------------------------------------------------------------------
// Immediate commands.

double number_arg(SCM v, const std::string& cmd, const SourceLoc& loc, const std::string& what) {
  if (!scm_is_real(v)) throw SceneError(loc, cmd, "", "expected " + what + ", found " + describe_scm(v));
  return scm_to_double(v);
}

std::vector<double> vector_arg(SCM v, const std::string& cmd, const SourceLoc& loc, std::initializer_list<size_t> sizes,
                               const std::string& what) {
  if (!scm_is_vector(v)) throw SceneError(loc, cmd, "", "expected " + what + ", found " + describe_scm(v));
  const size_t n = scm_c_vector_length(v);
  bool ok = false;
  for (size_t s : sizes) ok = ok || n == s;
  if (!ok) throw SceneError(loc, cmd, "", "expected " + what + ", found " + describe_scm(v));
  std::vector<double> out(n);
  for (size_t i = 0; i < n; ++i) {
    SCM e = scm_c_vector_ref(v, i);
    if (!scm_is_real(e))
      throw SceneError(
          loc, cmd, "",
          "expected " + what + ", found " + describe_scm(v) + " (entry " + std::to_string(i + 1) + " is not a number)");
    out[i] = scm_to_double(e);
  }
  return out;
}

SCM make_vector(const std::vector<double>& x) { return from_value(Value(x)); }

// Optional trailing matrix composed as (new * trailing): the trailing transform is applied first,
// as GeoViS's parse_transformObject.cpp does.
SCM finish_transform(Transform t, const std::vector<SCM>& a, size_t next, const std::string& cmd,
                     const SourceLoc& loc) {
  if (a.size() > next + 1)
    throw SceneError(loc, cmd, "",
                     "too many arguments: expected at most one trailing matrix, found " +
                         std::to_string(a.size() - next) + " more arguments");
  if (a.size() == next + 1) {
    if (!is_matrix(a[next]))
      throw SceneError(
          loc, cmd, "",
          "expected a trailing matrix (from translate-obj, rotate-obj or scale-obj), found " + describe_scm(a[next]));
    const Transform inner = matrix_to_transform(a[next]);
    if (inner.dim != t.dim)
      throw SceneError(loc, cmd, "",
                       "cannot compose a " + std::to_string(t.dim) + "D transform with the trailing " +
                           std::to_string(inner.dim) + "D matrix");
    t = t * inner;
  }
  return transform_to_matrix(t);
}

// 2D matrices act on (u, v, 0, 1): linear part in rows/columns 0-1, translation in column 3.
Transform translation(const std::vector<double>& d) {
  Transform t = Transform::identity(static_cast<int>(d.size()));
  for (size_t i = 0; i < d.size(); ++i) t(static_cast<int>(i), 3) = d[i];
  return t;
}

Transform scaling(const std::vector<double>& s) {
  Transform t = Transform::identity(static_cast<int>(s.size()));
  for (size_t i = 0; i < s.size(); ++i) t(static_cast<int>(i), static_cast<int>(i)) = s[i];
  return t;
}

// Rotation by `angle` (radians) about the unit axis n as a 3D Transform (core/rotation.h).
Transform rotation3(std::array<double, 3> n, double angle) {
  const Matrix3 r = rotation_about_axis(n, angle);
  Transform t = Transform::identity(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t(i, j) = r[i][j];
  return t;
}

// 2D rotation by `angle` about the point (cx, cy): T(c) R(angle) T(-c) (Motion4D RotateMat2D).
Transform rotation2(double cx, double cy, double angle) {
  Transform r = Transform::identity(2);
  r(0, 0) = std::cos(angle);
  r(0, 1) = -std::sin(angle);
  r(1, 0) = std::sin(angle);
  r(1, 1) = std::cos(angle);
  return translation({cx, cy}) * r * translation({-cx, -cy});
}

SCM translate_obj(const std::vector<SCM>& a, const SourceLoc& loc) {
  const std::string cmd = "translate-obj";
  if (a.empty()) throw SceneError(loc, cmd, "", "expected a vector #(dx dy) or #(dx dy dz), found no argument");
  const auto d = vector_arg(a[0], cmd, loc, {2, 3}, "a vector #(dx dy) or #(dx dy dz)");
  return finish_transform(translation(d), a, 1, cmd, loc);
}

SCM scale_obj(const std::vector<SCM>& a, const SourceLoc& loc) {
  const std::string cmd = "scale-obj";
  if (a.empty()) throw SceneError(loc, cmd, "", "expected a vector #(sx sy) or #(sx sy sz), found no argument");
  const auto s = vector_arg(a[0], cmd, loc, {2, 3}, "a vector #(sx sy) or #(sx sy sz)");
  return finish_transform(scaling(s), a, 1, cmd, loc);
}

SCM rotate_obj(const std::vector<SCM>& a, const SourceLoc& loc) {
  const std::string cmd = "rotate-obj";
  const std::string forms =
      "(rotate-obj \"x\"|\"y\"|\"z\" degrees [matrix]), (rotate-obj #(ax ay az) degrees [matrix]), "
      "(rotate-obj #(cx cy) degrees [matrix]) or (rotate-obj degrees [matrix])";
  if (a.empty()) throw SceneError(loc, cmd, "", "expected " + forms + ", found no argument");
  if (scm_is_real(a[0])) {  // 2D rotation about the origin
    return finish_transform(rotation2(0, 0, scm_to_double(a[0]) * kDegToRad), a, 1, cmd, loc);
  }
  if (a.size() < 2) throw SceneError(loc, cmd, "", "expected " + forms + ", the angle is missing");
  const double angle = number_arg(a[1], cmd, loc, "the rotation angle in degrees") * kDegToRad;
  if (scm_is_string(a[0]) || scm_is_symbol(a[0])) {
    const std::string axis = to_lower(scm_is_string(a[0]) ? to_std(a[0]) : symbol_name(a[0]));
    std::array<double, 3> n{0, 0, 0};
    if (axis == "x")
      n = {1, 0, 0};
    else if (axis == "y")
      n = {0, 1, 0};
    else if (axis == "z")
      n = {0, 0, 1};
    else
      throw SceneError(loc, cmd, "", "expected the axis \"x\", \"y\" or \"z\", found " + describe_scm(a[0]));
    return finish_transform(rotation3(n, angle), a, 2, cmd, loc);
  }
  if (scm_is_vector(a[0])) {
    const auto v = vector_arg(a[0], cmd, loc, {2, 3}, "an axis #(ax ay az) or a centre #(cx cy)");
    if (v.size() == 2) return finish_transform(rotation2(v[0], v[1], angle), a, 2, cmd, loc);
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(len > 0) || !std::isfinite(len))
      throw SceneError(loc, cmd, "", "the rotation axis must be a finite non-zero vector, found " + describe_scm(a[0]));
    return finish_transform(rotation3({v[0] / len, v[1] / len, v[2] / len}, angle), a, 2, cmd, loc);
  }
  throw SceneError(loc, cmd, "", "expected " + forms + ", found " + describe_scm(a[0]));
}

SCM vec_n(const std::string& cmd, size_t n, const std::vector<SCM>& a, const SourceLoc& loc) {
  if (a.size() != n)
    throw SceneError(loc, cmd, "",
                     "expected " + std::to_string(n) + " numbers, found " + std::to_string(a.size()) + " arguments");
  std::vector<double> x(n);
  for (size_t i = 0; i < n; ++i) x[i] = number_arg(a[i], cmd, loc, "a number as argument " + std::to_string(i + 1));
  return make_vector(x);
}

// (get-parameter '(id "obj")) -> ((key . value) ...) of the object as recorded so far (later
// set-parameter calls applied); (get-parameter '(id "obj") '(param "key")) -> that value.
SCM get_parameter(const CallSite& site, SCM args) {
  const std::string cmd = "get-parameter";
  EvalContext& ctx = context();
  ParamSet q(cmd, site.loc);
  parse_arguments(cmd, site, args, q);
  const Param* idp = q.find("id");
  if (!idp || !idp->value.is_string())
    throw SceneError(site.loc, cmd, "id", "this key is required: the id (a string) of the object to query");
  const std::string& id = std::get<std::string>(idp->value.v);
  auto it = ctx.ids.find(id);
  if (it == ctx.ids.end())
    throw SceneError(idp->loc, cmd, "id",
                     "no object with id \"" + id + "\" has been defined before" + did_you_mean(id, known_ids(ctx)));
  ParamSet current = ctx.desc.calls[it->second].params;
  for (size_t i = it->second + 1; i < ctx.desc.calls.size(); ++i) {
    const CommandCall& c = ctx.desc.calls[i];
    if (c.command != "set-parameter" || c.params.get_string("id", "") != id) continue;
    for (const Param& p : c.params.entries())
      if (p.key != "id") current.set(p.key, p.value, p.loc);
  }
  if (const Param* pp = q.find("param")) {
    if (!pp->value.is_string())
      throw SceneError(pp->loc, cmd, "param", "expected a string (the key to read), found " + pp->value.describe());
    const std::string key = to_lower(std::get<std::string>(pp->value.v));
    const Param* p = current.find(key);
    if (!p) {
      std::vector<std::string> keys;
      for (const Param& e : current.entries()) keys.push_back(e.key);
      throw SceneError(pp->loc, cmd, "param",
                       "the object \"" + id + "\" has no parameter \"" + key + "\"" + did_you_mean(key, keys) +
                           " (it has: " + join(keys) + ")");
    }
    return from_value(p->value);
  }
  SCM out = SCM_EOL;
  const auto& entries = current.entries();
  for (auto e = entries.rbegin(); e != entries.rend(); ++e)
    out = scm_cons(scm_cons(scm_from_utf8_symbol(e->key.c_str()), from_value(e->value)), out);
  return out;
}

SCM print_list(const std::string& text) {
  SCM port = scm_current_output_port();
  scm_display(scm_from_utf8_stringn(text.data(), text.size()), port);
  return SCM_UNSPECIFIED;
}

SCM m4d_metriclist() {
  std::string text = "Metrics (init-metric '(type ...)):\n";
  for (const auto& n : metric_names()) text += "  " + n + "\n";
  return print_list(text);
}

SCM m4d_solverlist() {
  std::string text = "Solvers (init-solver '(type ...)):\n";
  for (const auto& s : solver_names()) text += "  " + s.name + "  -  " + s.description + "\n";
  return print_list(text);
}

SCM getenv_cmd(const std::vector<SCM>& a, const SourceLoc& loc) {
  const std::string cmd = "getenv";
  if (a.size() != 1 || !scm_is_string(a[0]))
    throw SceneError(loc, cmd, "",
                     "expected one string (the variable name), found " +
                         (a.empty() ? std::string("no argument") : describe_scm(a[0])));
  const std::string name = to_std(a[0]);
  if (!context().opts->trusted && !scene_may_read_env(name))
    throw SceneError(loc, cmd, "",
                     "the environment variable \"" + name +
                         "\" is not available in scenes (they may read HOME, USER, LOGNAME and GEOVIS_*; " +
                         kSandboxHint + ")");
  const char* v = std::getenv(name.c_str());
  if (!v) {
    // GeoViS would pass a null pointer on; we continue with "" and say so.
    if (context().opts->diag)
      context().opts->diag->warn(loc, cmd, "", "environment variable " + name + " is not set; using \"\"");
    return scm_from_utf8_string("");
  }
  return scm_from_locale_string(v);
}

// Set by the exit command; gv_call raises 'geovis-exit after leaving the C++ frame.
thread_local bool t_exit_requested = false;
thread_local int t_exit_code = 0;

SCM exit_cmd(const std::vector<SCM>& a, const SourceLoc& loc) {
  int code = 0;
  if (!a.empty()) {
    if (scm_is_bool(a[0]))
      code = scm_is_true(a[0]) ? 0 : 1;
    else if (scm_is_signed_integer(a[0], -255, 255))
      code = scm_to_int(a[0]);
    else
      throw SceneError(loc, "exit", "", "expected an exit code (integer or boolean), found " + describe_scm(a[0]));
  }
  t_exit_requested = true;
  t_exit_code = code;
  return SCM_UNSPECIFIED;
}

SCM dispatch(SCM name, SCM locs, SCM args) {
  const std::string cmd = scm_is_string(name) ? to_std(name) : std::string("?");
  const CallSite site = call_site(locs);
  if (scm_ilength(args) < 0) throw SceneError(site.loc, cmd, "", "arguments must form a proper list");
  const std::vector<SCM> a = list_items(args);
  if (cmd == "vec3") return vec_n(cmd, 3, a, site.loc);
  if (cmd == "vec4") return vec_n(cmd, 4, a, site.loc);
  if (cmd == "translate-obj") return translate_obj(a, site.loc);
  if (cmd == "rotate-obj") return rotate_obj(a, site.loc);
  if (cmd == "scale-obj") return scale_obj(a, site.loc);
  if (cmd == "get-parameter") return get_parameter(site, args);
  if (cmd == "m4d-metriclist") return m4d_metriclist();
  if (cmd == "m4d-solverlist") return m4d_solverlist();
  if (cmd == "getenv") return getenv_cmd(a, site.loc);
  if (cmd == "exit") return exit_cmd(a, site.loc);
  return record_command(cmd, site, args);
}

struct DispatchCall {
  SCM name, locs, args;
  SCM result = SCM_UNSPECIFIED;
  bool failed = false;
};

void* dispatch_catching(void* data) {
  auto* call = static_cast<DispatchCall*>(data);
  try {
    call->result = dispatch(call->name, call->locs, call->args);
  } catch (...) {
    context().pending = std::current_exception();
    call->failed = true;
  }
  return nullptr;
}

// Runs the C++ work of a primitive so that no C++ exception crosses Guile frames: an exception is
// stored and re-raised in Scheme as 'geovis-error once `body`'s frames are gone (this frame holds
// nothing with a destructor).
template <class Body>
SCM guarded(Body&& body) {
  SCM result = SCM_UNSPECIFIED;
  bool failed = false;
  try {
    result = body();
  } catch (...) {
    context().pending = std::current_exception();
    failed = true;
  }
  if (failed) raise_pending_in_scheme();
  return result;
}

// (%gv-call name locs args). The command runs with asyncs blocked, so that the time limit
// (an async, scheme.cpp) never unwinds through its C++ frames.
SCM gv_call(SCM name, SCM locs, SCM args) {
  t_exit_requested = false;
  DispatchCall call{name, locs, args};
  scm_c_call_with_blocked_asyncs(dispatch_catching, &call);
  const SCM result = call.result;
  if (call.failed) raise_pending_in_scheme();
  if (t_exit_requested) scm_throw(scm_from_utf8_symbol("geovis-exit"), scm_list_1(scm_from_int(t_exit_code)));
  return result;
}

// (%gv-set-form-line! line): the top-level form being evaluated in the innermost file.
SCM gv_set_form_line(SCM line) {
  if (scm_is_signed_integer(line, 0, 1 << 30) && !context().files.empty())
    context().files.back().form_line = scm_to_int(line);
  return SCM_UNSPECIFIED;
}

// Is the existing path `p` inside the folder `root`? Both with symbolic links and ".." resolved.
bool is_below(const fs::path& p, const fs::path& root) {
  std::error_code ec;
  const fs::path cp = fs::canonical(p, ec);
  if (ec) return false;
  const fs::path cr = fs::canonical(root, ec);
  if (ec) return false;
  return std::mismatch(cr.begin(), cr.end(), cp.begin(), cp.end()).first == cr.end();
}

std::string file_kind(const fs::path& p) {
  std::error_code ec;
  switch (fs::status(p, ec).type()) {
    case fs::file_type::directory: return "a directory";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::fifo: return "a named pipe";
    case fs::file_type::socket: return "a socket";
    default: return "a special file";
  }
}

// The file `(load name)` reads: relative to the loading file's folder, else in the --scene-path
// folders. Sandboxed, it must be a .scm file below the scene's folder or a --scene-path folder
// (docs/security.md).
fs::path find_load_file(const EvalContext& ctx, const std::string& name, const SourceLoc& loc) {
  const std::string what = "cannot load \"" + name + "\": ";
  std::error_code ec;
  fs::path p(name);
  std::vector<std::string> looked;
  if (p.is_relative()) {
    p = fs::path(ctx.files.back().dir) / name;
    looked.push_back(p.string());
    for (const auto& dir : ctx.opts->load_paths) {
      if (fs::exists(p, ec)) break;
      p = fs::path(dir) / name;
      looked.push_back(p.string());
    }
  } else {
    looked.push_back(p.string());
  }
  if (!fs::exists(p, ec)) throw SceneError(loc, "load", "", what + "no such file (looked for " + join(looked) + ")");
  if (!ctx.opts->trusted) {
    std::vector<std::string> roots{ctx.desc.dir};
    roots.insert(roots.end(), ctx.opts->load_paths.begin(), ctx.opts->load_paths.end());
    bool allowed = to_lower(p.extension().string()) == ".scm";
    bool below = false;
    for (const auto& r : roots) below = below || is_below(p, r);
    if (!allowed || !below)
      throw SceneError(loc, "load", "",
                       what + "not allowed: a scene may load only .scm files below its own folder (" + ctx.desc.dir +
                           ") and the --scene-path folders, and " + p.string() + " is " +
                           (allowed ? "outside them" : "not a .scm file") + " (" + kSandboxHint + ")");
  }
  if (!fs::is_regular_file(p, ec))
    throw SceneError(loc, "load", "", what + p.string() + " is " + file_kind(p) + ", not a regular file");
  return p;
}

// (%gv-enter-file file) -> resolved path; relative paths are relative to the loading file.
SCM gv_enter_file(SCM file) {
  return guarded([&]() -> SCM {
    EvalContext& ctx = context();
    const SourceLoc loc = current_form_loc();
    if (!scm_is_string(file))
      throw SceneError(loc, "load", "", "expected a file name string, found " + describe_scm(file));
    if (ctx.files.size() > kMaxLoadDepth)
      throw SceneError(loc, "load", "", "files load each other more than 64 levels deep (a file loading itself?)");
    const std::string name = to_std(file);
    const fs::path p = find_load_file(ctx, name, loc);
    const std::string resolved = p.lexically_normal().string();
    std::string dir = p.parent_path().string();
    if (dir.empty()) dir = ".";
    ctx.files.push_back(FileFrame{resolved, dir, 0});
    return scm_from_utf8_stringn(resolved.data(), resolved.size());
  });
}

SCM gv_leave_file() {
  if (context().files.size() > 1) context().files.pop_back();
  return SCM_UNSPECIFIED;
}

SCM gv_note_define(SCM name) {
  if (!scm_is_string(name)) return SCM_UNSPECIFIED;
  return guarded([&] {
    auto& defs = context().defines;
    std::string n = to_std(name);
    if (std::find(defs.begin(), defs.end(), n) == defs.end()) defs.push_back(std::move(n));
    return SCM_UNSPECIFIED;
  });
}

SCM gv_note_override_used(SCM name) {
  if (!scm_is_string(name)) return SCM_UNSPECIFIED;
  return guarded([&] {
    context().used_overrides.insert(to_lower(to_std(name)));
    return SCM_UNSPECIFIED;
  });
}

// (%gv-define-error name text message): a --define VALUE that is not one Scheme datum.
SCM gv_define_error(SCM name, SCM text, SCM message) {
  return guarded([&]() -> SCM {
    throw Error("--define " + (scm_is_string(name) ? to_std(name) : std::string("?")) + "=" +
                (scm_is_string(text) ? to_std(text) : std::string("?")) + ": " +
                (scm_is_string(message) ? to_std(message) : std::string("invalid value")));
  });
}

}  // namespace

void define_command_primitives() {
  scm_c_define_gsubr("%gv-call", 3, 0, 0, reinterpret_cast<scm_t_subr>(gv_call));
  scm_c_define_gsubr("%gv-set-form-line!", 1, 0, 0, reinterpret_cast<scm_t_subr>(gv_set_form_line));
  scm_c_define_gsubr("%gv-enter-file", 1, 0, 0, reinterpret_cast<scm_t_subr>(gv_enter_file));
  scm_c_define_gsubr("%gv-leave-file", 0, 0, 0, reinterpret_cast<scm_t_subr>(gv_leave_file));
  scm_c_define_gsubr("%gv-note-define", 1, 0, 0, reinterpret_cast<scm_t_subr>(gv_note_define));
  scm_c_define_gsubr("%gv-note-override-used", 1, 0, 0, reinterpret_cast<scm_t_subr>(gv_note_override_used));
  scm_c_define_gsubr("%gv-define-error", 3, 0, 0, reinterpret_cast<scm_t_subr>(gv_define_error));
}

}  // namespace scheme_detail
}  // namespace geovis
