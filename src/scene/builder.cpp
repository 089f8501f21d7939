// Scene builder: GeoViS command calls -> render jobs (see builder.h for the overall scheme).
//
// References between definitions follow GeoViS's parser (catalogue §1, §10):
//  * an id given under a key must name a definition of the right kind, else the error names the
//    closest id of that kind;
//  * a key left out means the last definition of that kind made before the referencing command
//    (GeoViS's default when only one exists; we extend it to "the last-defined one");
//  * the symbols GeoViS commands return (gtTexture, gtShader, gtLocTed, ...) mean "the most
//    recently created one of that kind";
//  * the last scene object created before init-device is the default scene graph.
#include "scene/builder.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

#include "io/atomic_file.h"
#include "io/image.h"
#include "render/build_context.h"
#include "render/camera.h"
#include "render/camera_factory.h"
#include "render/data_files.h"
#include "render/plugins.h"
#include "spacetime/metric_registry.h"
#include "spacetime/motion_factory.h"
#include "spacetime/tetrad.h"

namespace geovis {

namespace {

// ---- kinds of definitions ---------------------------------------------------------------------

enum class Kind { Metric, Solver, Camera, RayGen, Tetrad, Projector, Light, LightMgr, Texture, Shader, Object, Motion };

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::Metric: return "metric";
    case Kind::Solver: return "solver";
    case Kind::Camera: return "camera";
    case Kind::RayGen: return "raygen";
    case Kind::Tetrad: return "local tetrad";
    case Kind::Projector: return "projector";
    case Kind::Light: return "light";
    case Kind::LightMgr: return "light manager";
    case Kind::Texture: return "texture";
    case Kind::Shader: return "shader";
    case Kind::Object: return "scene object";
    case Kind::Motion: return "motion";
  }
  return "object";
}

const std::map<std::string, Kind>& definition_commands() {
  static const std::map<std::string, Kind> m = {
      {"init-metric", Kind::Metric},         {"init-solver", Kind::Solver},
      {"init-camera", Kind::Camera},         {"init-raygen", Kind::RayGen},
      {"local-tetrad", Kind::Tetrad},        {"init-projector", Kind::Projector},
      {"init-light", Kind::Light},           {"init-light-mgr", Kind::LightMgr},
      {"init-texture", Kind::Texture},       {"init-shader", Kind::Shader},
      {"init-motion", Kind::Motion},         {"solid-box", Kind::Object},
      {"solid-cylinder", Kind::Object},      {"solid-ellipsoid", Kind::Object},
      {"solid-background", Kind::Object},    {"solid-ring", Kind::Object},
      {"plane-triangle", Kind::Object},      {"plane-ring", Kind::Object},
      {"plane-parallelogram", Kind::Object},
      {"mesh-obj", Kind::Object},            {"csg-object", Kind::Object},
      {"comp-object", Kind::Object},         {"comp-octree-object", Kind::Object},
      {"local-comp-object", Kind::Object},
  };
  return m;
}

/// Objects that contain other objects (built after their parts; they consume no objID).
bool is_container(const std::string& command) {
  return command == "comp-object" || command == "comp-octree-object" || command == "local-comp-object" ||
         command == "csg-object";
}

/// Commands the builder acts on besides definitions, and commands that only matter to the Scheme
/// evaluator (already handled there; accepted here so a description may contain them).
const std::vector<std::string>& other_commands() {
  static const std::vector<std::string> v = {
      "add-object", "set-parameter", "get-parameter", "init-device", "set-changeobj", "gvs-print-motion",
      "calc-ray", "calc-proj-ray", "gvs-print", "m4d-metriclist", "m4d-solverlist", "translate-obj",
      "rotate-obj", "scale-obj", "vec3", "vec4", "getenv", "exit"};
  return v;
}

/// Keys of the commands no plugin factory checks (catalogue §1). Unknown keys are warnings
/// (errors under --strict) naming the closest valid key; wrong shapes are errors.
const std::vector<ParamSpec>* builder_specs(const std::string& command) {
  using T = ParamType;
  static const std::map<std::string, std::vector<ParamSpec>> specs = {
      {"init-solver",
       {{"type", T::String, "integrator name (GeoViS nickname or full name)", true},
        {"id", T::String, "id"},
        {"metric", T::String, "metric id (the device's metric is used)"},
        {"geodtype", T::String, "lightlike, timelike or spacelike"},
        {"geoddir", T::String, "forward or backward"},
        {"step_ctrl", T::Bool, "adaptive step size control (default #t)"},
        {"step_size", T::Number, "initial or fixed step size (default 0.01)"},
        {"max_step", T::Number, "maximal step size"},
        {"eps_abs", T::Number, "absolute tolerance (default 1e-4)"},
        {"eps_rel", T::Number, "relative tolerance (default 0)"},
        {"separable", T::Bool,
         "geovis extension: KerrBL and Schwarzschild geodesics through Carter's separated equations in Mino "
         "time (default #t); #f: the coordinate geodesic equation, as GeoViS"},
        {"boundboxll", T::Vec4, "lower corner of the bounding box"},
        {"boundboxur", T::Vec4, "upper corner of the bounding box"}}},
      {"init-raygen",
       {{"type", T::String, "RayGenSimple"},
        {"id", T::String, "id"},
        {"solver", T::String, "solver id"},
        {"maxnumpoints", T::Int, "maximal number of ray points (default 3000)"},
        {"boundboxll", T::Vec4, "lower corner of the bounding box"},
        {"boundboxur", T::Vec4, "upper corner of the bounding box"}}},
      {"local-tetrad",
       {{"id", T::String, "id"},
        {"pos", T::Any, "position #(t x1 x2 x3)"},
        {"vel", T::Vec4, "coordinate four-velocity"},
        {"localvel", T::Vec3, "3-velocity relative to the natural tetrad"},
        {"e0", T::Vec4, "base vector e0"},
        {"e1", T::Vec4, "base vector e1"},
        {"e2", T::Vec4, "base vector e2"},
        {"e3", T::Vec4, "base vector e3"},
        {"incoords", T::Bool, "#t: e0..e3 in coordinates; #f: relative to the natural tetrad"},
        {"metric", T::String, "metric id"},
        {"localframe", T::Any, "natural tetrad kind (gpTetrad* constant)"}}},
      {"init-projector",
       {{"id", T::String, "id"},
        {"raygen", T::String, "ray generator id"},
        {"localtetrad", T::String, "observer's local tetrad id"},
        {"motion", T::String, "observer's motion id"},
        {"actualpos", T::Int, "point of the motion the observer is at"},
        {"color", T::Vec3, "background colour"},
        {"errcolor", T::Vec3, "colour of rays stopped by an integration error"},
        {"cstrcolor", T::Vec3, "colour of rays stopped by the constraint check"},
        {"breakcolor", T::Vec3, "colour of rays stopped by the metric's break condition"},
        {"pos", T::Any, "observer position (instead of localtetrad)"},
        {"e0", T::Vec4, "base vector e0"},
        {"e1", T::Vec4, "base vector e1"},
        {"e2", T::Vec4, "base vector e2"},
        {"e3", T::Vec4, "base vector e3"},
        {"incoords", T::Bool, "#t: e0..e3 in coordinates"},
        {"localframe", T::Any, "natural tetrad kind"}}},
      {"init-device",
       {{"type", T::String, "standard or standard_manual"},
        {"id", T::String, "id"},
        {"camera", T::String, "camera id"},
        {"projector", T::String, "projector id"},
        {"metric", T::String, "metric id"},
        {"lightmgr", T::String, "light manager id"},
        {"obj", T::String, "scene object id"},
        {"setparam", T::List, "(\"objID\" \"param\" value)", false, true}}},
      {"set-changeobj",
       {{"device", T::String, "device id", true}, {"setparam", T::List, "(\"objID\" \"param\" value)", false, true}}},
      {"add-object", {{"add-to", T::String, "compound id", true}, {"obj", T::String, "object id", false, true}}},
      {"calc-ray",
       {{"filename", T::String, "output file", true},
        {"raygen", T::String, "ray generator id"},
        {"locted", T::String, "local tetrad id"},
        {"pos", T::Any, "start position"},
        {"dir", T::Vec2, "direction (ksi, chi) in degrees"}}},
      {"calc-proj-ray",
       {{"filename", T::String, "output file", true},
        {"raygen", T::String, "ray generator id"},
        {"projector", T::String, "projector id"},
        {"dir", T::Vec3, "local direction"},
        {"cartesian", T::Bool, "write Cartesian coordinates"}}},
      {"gvs-print-motion", {{"id", T::String, "motion id", true}, {"file", T::String, "output file", true}}},
      {"gvs-print", {{"id", T::String, "id", true}}},
  };
  // The evaluator gives every call an id (a generated "unknownN" when the scene gave none).
  static const std::map<std::string, std::vector<ParamSpec>> with_id = [] {
    auto m = specs;
    for (auto& [cmd, v] : m)
      if (std::none_of(v.begin(), v.end(), [](const ParamSpec& p) { return p.key == "id"; }))
        v.push_back({"id", ParamType::String, "id"});
    return m;
  }();
  auto it = with_id.find(command);
  return it == with_id.end() ? nullptr : &it->second;
}

bool is_action(const std::string& c) {
  return c == "gvs-print-motion" || c == "calc-ray" || c == "calc-proj-ray" || c == "gvs-print";
}

/// Keys whose value is the id of another definition.
struct RefKey {
  const char* key;
  Kind kind;
};
const std::vector<RefKey>& ref_keys(Kind k) {
  static const std::vector<RefKey> none;
  static const std::vector<RefKey> object = {{"shader", Kind::Shader},   {"motion", Kind::Motion},
                                             {"localtetrad", Kind::Tetrad}, {"obj", Kind::Object},
                                             {"obj1", Kind::Object},     {"obj2", Kind::Object}};
  static const std::vector<RefKey> shader = {{"objcolor", Kind::Texture}, {"normalmap", Kind::Texture}};
  static const std::vector<RefKey> texture = {{"texture", Kind::Texture}};
  static const std::vector<RefKey> lightmgr = {{"light", Kind::Light}};
  switch (k) {
    case Kind::Object: return object;
    case Kind::Shader: return shader;
    case Kind::Texture: return texture;
    case Kind::LightMgr: return lightmgr;
    default: return none;
  }
}

// ---- stored definitions ------------------------------------------------------------------------

struct Def {
  Kind kind = Kind::Object;
  std::string id;
  int seq = 0;  ///< index of the creating call
  ParamSet ps;  ///< as called, patched by set-parameter / add-object / this frame's setparams
  /// Metric and camera changes are applied through Metric::set_param / Camera::set_param after
  /// construction (the key is the parameter name); other kinds are patched in `ps`.
  std::vector<Param> changes;
};
using DefPtr = std::shared_ptr<const Def>;
using DefMap = std::map<std::string, DefPtr>;

struct DeviceDef {
  int seq = 0;
  ParamSet ps;                     ///< the init-device call
  std::vector<Param> setparams;    ///< its setparam entries plus set-changeobj additions
  std::shared_ptr<const DefMap> defs;
};

struct ActionDef {
  int seq = 0;
  CommandCall call;
  std::shared_ptr<const DefMap> defs;
};

// ---- value serialisation for cache keys --------------------------------------------------------

void put_number(std::string& out, double d) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, d);
  out.append(buf, r.ptr);
}

void put_value(std::string& out, const Value& v) {
  struct V {
    std::string& o;
    void operator()(std::monostate) const { o += "()"; }
    void operator()(bool b) const { o += b ? "#t" : "#f"; }
    void operator()(double d) const { put_number(o, d); }
    void operator()(const std::string& s) const {
      o += '"';
      o += s;
      o += '"';
    }
    void operator()(const std::vector<double>& d) const {
      o += "#(";
      for (double x : d) {
        put_number(o, x);
        o += ' ';
      }
      o += ')';
    }
    void operator()(const Transform& t) const {
      o += "M" + std::to_string(t.dim) + "(";
      for (double x : t.m) {
        put_number(o, x);
        o += ' ';
      }
      o += ')';
    }
    void operator()(const ValueList& l) const {
      o += '(';
      for (const auto& x : l) {
        put_value(o, x);
        o += ' ';
      }
      o += ')';
    }
  };
  std::visit(V{out}, v.v);
}

std::string serialize(const ParamSet& ps, const std::vector<Param>& changes = {}) {
  std::string out = ps.command() + "{";
  for (const auto& p : ps.entries()) {
    out += p.key;
    out += '=';
    put_value(out, p.value);
    out += ';';
  }
  for (const auto& p : changes) {
    out += '!' + p.key + '=';
    put_value(out, p.value);
    out += ';';
  }
  out += '}';
  return out;
}

// ---- setparam targets (catalogue §10) ----------------------------------------------------------

/// ParamSet key a setparam parameter name changes (GeoViS uses a few names that differ from the
/// creating command's keys).
std::string setparam_key(const std::string& command, const std::string& name) {
  const std::string n = to_lower(name);
  if (command == "init-camera" && n == "eyesep") return "sep";
  if (command == "init-texture" && n == "startpoint") return "start";
  if (command == "init-texture" && n == "endpoint") return "end";
  if (command == "mesh-obj" && n == "objfilename") return "filename";
  return n;
}

/// Names a setparam may change for a definition (catalogue §10). Empty result + `any` = every
/// metric parameter (checked by Metric::set_param).
std::vector<std::string> settable_names(const Def& d, bool& any) {
  any = false;
  const std::string& c = d.ps.command();
  switch (d.kind) {
    case Kind::Metric: any = true; return {};
    case Kind::Camera: return {};  // Camera::set_param checks (it knows its type's names)
    case Kind::Tetrad: return {"pos", "time", "e0", "e1", "e2", "e3", "localvel", "calc"};
    case Kind::Projector: return {"actualpos"};
    case Kind::Texture: {
      const std::string type = d.ps.get_string("type", std::string());
      if (type == "UniTex") return {"color"};
      if (type == "ColorGradTex") return {"color1", "color2", "startpoint", "endpoint", "gradtype"};
      return {};
    }
    case Kind::Object: {
      if (c == "solid-ellipsoid") return {"axlen", "transform"};
      if (c == "mesh-obj") return {"objfilename"};
      if (c == "solid-box" || c == "solid-cylinder" || c == "solid-ring" || c == "csg-object" ||
          c == "plane-triangle" || c == "plane-parallelogram" || c == "plane-ring")
        return {"transform"};
      return {};
    }
    default: return {};
  }
}

/// Applies one parameter change (setparam of a device, or set-parameter) to a copy of `d`.
/// `where` is the ParamSet of the command making the change (for the error location).
DefPtr apply_change(const DefPtr& d, const std::string& name, const Value& value, const SourceLoc& loc,
                    const ParamSet& where, std::string_view key_for_errors) {
  auto nd = std::make_shared<Def>(*d);
  const std::string n = to_lower(name);
  if (d->kind == Kind::Metric) {
    // Check the name now (reported at the setparam); the value is checked when the metric is built.
    try {
      make_metric(d->ps.get_string("type"))->param(n);
    } catch (const SceneError&) {
      throw;
    } catch (const std::exception& e) {
      throw SceneError(loc.line ? loc : where.loc(), where.command(), key_for_errors,
                       "\"" + d->id + "\": " + e.what());
    }
  }
  if (d->kind == Kind::Metric || d->kind == Kind::Camera) {
    nd->changes.push_back(Param{n, value, loc});
    return nd;
  }
  bool any = false;
  const auto names = settable_names(*d, any);
  if (std::find(names.begin(), names.end(), n) == names.end()) {
    const SourceLoc& l = loc.line ? loc : where.loc();
    throw SceneError(l, where.command(), key_for_errors,
                     "\"" + d->id + "\" (" + d->ps.command() + ") has no parameter \"" + name +
                         "\" that can be changed" + did_you_mean(n, names) +
                         (names.empty() ? " (it has no changeable parameters)"
                                        : " (changeable: " + join(names) + ")"));
  }
  if (n == "calc") return nd;  // GeoViS: recompute the tetrad; ours is always computed on build
  if (d->kind == Kind::Tetrad && n == "time") {
    // "time" sets the time coordinate x^0 of the tetrad's position.
    const Value& v = value;
    if (!v.is_number()) {
      const SourceLoc& l = loc.line ? loc : where.loc();
      throw SceneError(l, where.command(), key_for_errors,
                       "time of \"" + d->id + "\": expected a number, found " + v.describe());
    }
    std::vector<double> pos = d->ps.get_vector("pos", 4, std::vector<double>{0, 0, 0, 0});
    pos[0] = std::get<double>(v.v);
    nd->ps.set("pos", Value(pos), loc);
    return nd;
  }
  nd->ps.set(setparam_key(d->ps.command(), n), value, loc);
  return nd;
}

// ---- files named by the scene -------------------------------------------------------------------

/// GeoViS scenes name their texture images and meshes by paths of the author's machine
/// (`(string-append (getenv "HOME") "/local/Texturen/...")`, or "examples/eso0932a.tif" relative
/// to the folder GeoViS was started in). When `name` exists neither as given nor relative to a
/// search folder, the file of the same name in a search folder (scene folder, --texture-path,
/// working folder) is used instead; returns that path, or "" when there is none (the factory then
/// reports the file as missing, listing every place searched).
std::string find_by_file_name(const std::string& name, const std::vector<std::string>& dirs) {
  namespace fs = std::filesystem;
  try {
    (void)find_file(name, dirs);
    return "";  // found as given: nothing to substitute
  } catch (const Error&) {
  }
  const fs::path file = fs::path(name).filename();
  if (file.empty()) return "";
  std::error_code ec;
  for (const auto& dir : dirs) {
    const fs::path c = fs::path(dir) / file;
    if (fs::is_regular_file(c, ec)) return c.string();
  }
  return "";
}

/// `ps` with its image file (init-texture Image) or mesh file (mesh-obj) replaced by the file of
/// the same name in a search folder when the named one does not exist (find_by_file_name), with
/// a warning saying so. Otherwise `ps` unchanged.
ParamSet with_files_found(const ParamSet& ps, const std::vector<std::string>& dirs, Diagnostics* diag) {
  const std::string& cmd = ps.command();
  std::string key, name;
  if (cmd == "init-texture" && to_lower(ps.get_string("type", std::string())) == "image") {
    const Param* p = ps.find("file");
    if (!p || !p->value.is_string()) return ps;
    key = "file";
    name = std::get<std::string>(p->value.v);
  } else if (cmd == "mesh-obj") {
    const Param* p = ps.find("filename");
    if (!p || !p->value.is_string()) return ps;
    const Param* d = ps.find("pathname");
    const std::string dir = d && d->value.is_string() ? std::get<std::string>(d->value.v) : std::string();
    key = "filename";
    name = dir.empty() ? std::get<std::string>(p->value.v) : dir + "/" + std::get<std::string>(p->value.v);
  } else {
    return ps;
  }
  const std::string found = find_by_file_name(name, dirs);
  if (found.empty()) return ps;
  ParamSet out = ps;
  const SourceLoc loc = ps.find(key)->loc;
  out.set(key, Value(found), loc);
  if (cmd == "mesh-obj") out.set("pathname", Value(std::string()), loc);
  if (diag)
    diag->warn(loc, cmd, key,
               "\"" + name + "\" does not exist; using \"" + found + "\" (the file of that name in a search folder)");
  return out;
}

// ---- errors ------------------------------------------------------------------------------------

[[noreturn]] void rethrow_at(const ParamSet& ps, std::string_view key, const std::exception& e) {
  if (dynamic_cast<const SceneError*>(&e)) throw;
  ps.fail(key, e.what());
}

// ---- coordinate helpers for calc-proj-ray's cartesian output -----------------------------------

/// Cartesian position and the Jacobian ∂(x,y,z)/∂(x^1,x^2,x^3) for spherical (r,θ,φ) or
/// cylindrical (r,φ,z) coordinates; time is unchanged. Returns false for other coordinate types.
bool cartesian_jacobian(CoordType ct, const Vec4& x, Vec4& xc, double J[4][4]) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) J[i][j] = i == j ? 1.0 : 0.0;
  xc = x;
  if (ct == CoordType::Cartesian) return true;
  if (ct == CoordType::Spherical) {
    const double r = x[1], st = std::sin(x[2]), ct_ = std::cos(x[2]), sp = std::sin(x[3]), cp = std::cos(x[3]);
    xc = Vec4{{x[0], r * st * cp, r * st * sp, r * ct_}};
    const double Js[3][3] = {{st * cp, r * ct_ * cp, -r * st * sp}, {st * sp, r * ct_ * sp, r * st * cp}, {ct_, -r * st, 0}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J[i + 1][j + 1] = Js[i][j];
    return true;
  }
  if (ct == CoordType::Cylindrical) {
    const double r = x[1], sp = std::sin(x[2]), cp = std::cos(x[2]);
    xc = Vec4{{x[0], r * cp, r * sp, x[3]}};
    const double Jc[3][3] = {{cp, -r * sp, 0}, {sp, r * cp, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J[i + 1][j + 1] = Jc[i][j];
    return true;
  }
  return false;
}

Vec4 apply_jacobian(const double J[4][4], const Vec4& v) {
  Vec4 o{{0, 0, 0, 0}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) o[i] += J[i][j] * v[j];
  return o;
}

std::string fmt_vec(const double* v, int n) {
  std::ostringstream os;
  os << "(";
  for (int i = 0; i < n; ++i) os << (i ? ", " : "") << v[i];
  os << ")";
  return os.str();
}

}  // namespace

// =================================================================================================

struct SceneBuilder::Impl {
  SceneDescription scene;
  BuildOptions opts;

  DefMap defs;  ///< current definitions while the calls are processed
  std::shared_ptr<const DefMap> snapshot;  ///< shared copy of `defs`, reset when defs change
  std::vector<DeviceDef> devices;
  std::vector<ActionDef> actions;
  std::map<std::string, std::string> device_ids;  ///< init-device id -> index (as string)
  std::map<std::string, int> device_index;

  // ---- cache of built artefacts across devices ----
  struct CacheEntry {
    std::shared_ptr<const void> value;
    int objects_used = 0;  ///< objIDs the object consumed (objects only)
    long last_used = 0;
  };
  mutable std::mutex cache_mutex;
  mutable std::map<std::string, CacheEntry> cache;
  mutable long generation = 0;

  Impl(SceneDescription s, BuildOptions o) : scene(std::move(s)), opts(std::move(o)) {}

  std::shared_ptr<const DefMap> current_snapshot() {
    if (!snapshot) snapshot = std::make_shared<const DefMap>(defs);
    return snapshot;
  }
  void changed() { snapshot.reset(); }

  void warn(const SourceLoc& loc, std::string_view command, std::string_view key, std::string_view msg) const {
    if (opts.diag) opts.diag->warn(loc, command, key, msg);
  }

  // ---- processing the calls ----

  void process() {
    for (size_t i = 0; i < scene.calls.size(); ++i) process_call(static_cast<int>(i), scene.calls[i]);
  }

  std::string id_of(const ParamSet& ps, int seq) {
    if (const Param* p = ps.find("id")) {
      if (!p->value.is_string()) ps.fail("id", "expected a string, found " + p->value.describe());
      return std::get<std::string>(p->value.v);
    }
    return "unknown" + std::to_string(seq);  // GeoViS names objects without id "unknownN"
  }

  void check_new_id(const ParamSet& ps, const std::string& id) {
    auto it = defs.find(id);
    if (it != defs.end())
      ps.fail("id", "id \"" + id + "\" is already used by the " + it->second->ps.command() + " at " +
                        (it->second->ps.loc().str().empty() ? "an earlier call" : it->second->ps.loc().str()));
    if (device_index.count(id)) ps.fail("id", "id \"" + id + "\" is already used by a device");
  }

  void process_call(int seq, const CommandCall& call) {
    const ParamSet& ps = call.params;
    const std::string& cmd = call.command;
    Diagnostics sink;  // warnings are dropped when the caller gave no Diagnostics
    if (const auto* specs = builder_specs(cmd)) ps.validate(*specs, opts.diag ? *opts.diag : sink);
    if (cmd == "init-motion")
      ps.validate(motion_param_specs(ps.get_string("type", std::string())), opts.diag ? *opts.diag : sink);
    auto dk = definition_commands().find(cmd);
    if (dk != definition_commands().end()) {
      auto d = std::make_shared<Def>();
      d->kind = dk->second;
      d->seq = seq;
      d->ps = ps;
      if (d->ps.command().empty()) d->ps.set_command(cmd);
      d->id = id_of(ps, seq);
      check_new_id(ps, d->id);
      defs[d->id] = d;
      changed();
      return;
    }
    if (cmd == "add-object") {
      const std::string target = ps.get_string("add-to");
      const DefPtr t = lookup(defs, ps, "add-to", target, Kind::Object, seq);
      if (t->ps.command() != "comp-object" && t->ps.command() != "comp-octree-object")
        ps.fail("add-to", "\"" + target + "\" is a " + t->ps.command() +
                              "; objects can only be added to a comp-object or comp-octree-object");
      auto nd = std::make_shared<Def>(*t);
      const auto objs = ps.find_all("obj");
      if (objs.empty()) ps.fail("obj", "this key is required but missing (the object(s) to add)");
      for (const Param* p : objs) {
        if (!p->value.is_string()) ps.fail("obj", "expected a string, found " + p->value.describe());
        lookup(defs, ps, "obj", std::get<std::string>(p->value.v), Kind::Object, seq);
        nd->ps.add("obj", p->value, p->loc);
      }
      defs[t->id] = nd;
      changed();
      return;
    }
    if (cmd == "set-parameter") {
      const std::string id = ps.get_string("id");
      auto it = defs.find(id);
      if (it == defs.end()) fail_unknown_id(defs, ps, "id", id, std::nullopt);
      DefPtr d = it->second;
      bool any_change = false;
      for (const auto& p : ps.entries()) {
        if (p.key == "id") continue;
        d = apply_change(d, p.key, p.value, p.loc, ps, p.key);
        any_change = true;
      }
      if (!any_change) ps.fail("", "set-parameter needs a parameter to change besides id");
      defs[id] = d;
      changed();
      return;
    }
    if (cmd == "init-device") {
      DeviceDef dev;
      dev.seq = seq;
      dev.ps = ps;
      static const std::vector<std::string> type_names = {"standard", "standard_manual"};
      const std::string type = ps.get_string("type", std::string("standard"));
      if (std::find(type_names.begin(), type_names.end(), type) == type_names.end())
        ps.fail("type", "unknown device type \"" + type + "\"" + did_you_mean(type, type_names) +
                            " (valid: standard, standard_manual)");
      for (const Param* p : ps.find_all("setparam")) dev.setparams.push_back(*p);
      dev.defs = current_snapshot();
      if (const Param* p = ps.find("id")) {
        if (!p->value.is_string()) ps.fail("id", "expected a string, found " + p->value.describe());
        const std::string id = std::get<std::string>(p->value.v);
        check_new_id(ps, id);
        device_index[id] = static_cast<int>(devices.size());
      }
      // Check the setparam entries now so a bad one is reported at parse time, as GeoViS does.
      for (const auto& sp : dev.setparams) apply_setparam(*dev.defs, sp, dev.ps, nullptr);
      devices.push_back(std::move(dev));
      return;
    }
    if (cmd == "set-changeobj") {
      const std::string id = ps.get_string("device");
      auto it = device_index.find(id);
      if (it == device_index.end()) {
        std::vector<std::string> ids;
        for (const auto& [k, v] : device_index) ids.push_back(k);
        ps.fail("device", "unknown device id \"" + id + "\"" + did_you_mean(id, ids) +
                              (ids.empty() ? " (no init-device with an id precedes this command)"
                                           : " (defined: " + join(ids) + ")"));
      }
      DeviceDef& dev = devices[it->second];
      for (const Param* p : ps.find_all("setparam")) {
        apply_setparam(*dev.defs, *p, ps, nullptr);
        dev.setparams.push_back(*p);
      }
      return;
    }
    if (is_action(cmd)) {
      actions.push_back(ActionDef{seq, call, current_snapshot()});
      return;
    }
    if (std::find(other_commands().begin(), other_commands().end(), cmd) != other_commands().end()) return;
    std::vector<std::string> all = other_commands();
    for (const auto& [k, v] : definition_commands()) all.push_back(k);
    throw SceneError(ps.loc(), cmd, "", "unknown command" + did_you_mean(cmd, all));
  }

  /// Applies one setparam entry ("objID" "param" value) to `defs` (when non-null) or only checks it.
  void apply_setparam(const DefMap& snapshot_defs, const Param& sp, const ParamSet& where, DefMap* out) const {
    const SourceLoc& loc = sp.loc.line ? sp.loc : where.loc();
    auto bad = [&](const std::string& msg) { throw SceneError(loc, where.command(), "setparam", msg); };
    if (!sp.value.is_list()) bad("expected (\"objID\" \"param\" value), found " + sp.value.describe());
    const auto& l = std::get<ValueList>(sp.value.v);
    if (l.size() != 3 || !l[0].is_string() || !l[1].is_string())
      bad("expected (\"objID\" \"param\" value), found " + sp.value.describe());
    const std::string& id = std::get<std::string>(l[0].v);
    const std::string& name = std::get<std::string>(l[1].v);
    const DefMap& src = out ? *out : snapshot_defs;
    auto it = src.find(id);
    if (it == src.end()) {
      std::vector<std::string> ids;
      for (const auto& [k, v] : src) ids.push_back(k);
      bad("unknown object id \"" + id + "\"" + did_you_mean(id, ids) +
          (ids.empty() ? std::string(" (nothing is defined before this command)") : " (defined: " + join(ids) + ")"));
    }
    DefPtr nd = apply_change(it->second, name, l[2], loc, where, "setparam");
    if (out) (*out)[id] = nd;
  }

  // ---- references ----

  [[noreturn]] static void fail_unknown_id(const DefMap& m, const ParamSet& ps, std::string_view key,
                                           const std::string& id, std::optional<Kind> kind) {
    std::vector<std::string> ids;
    for (const auto& [k, v] : m)
      if (!kind || v->kind == *kind) ids.push_back(k);
    const std::string what = kind ? kind_name(*kind) : "object";
    ps.fail(key, "unknown " + what + " id \"" + id + "\"" + did_you_mean(id, ids) +
                     (ids.empty() ? " (no " + what + " is defined before this command)" : " (defined: " + join(ids) + ")"));
  }

  /// The last definition of `kind` created before call `before` (nullptr when none).
  static const DefPtr* last_of(const DefMap& m, Kind kind, int before) {
    const DefPtr* best = nullptr;
    for (const auto& [k, v] : m)
      if (v->kind == kind && v->seq < before && (!best || v->seq > (*best)->seq)) best = &v;
    return best;
  }

  static const DefPtr& lookup(const DefMap& m, const ParamSet& ps, std::string_view key, const std::string& id,
                              Kind kind, int before) {
    auto it = m.find(id);
    if (it == m.end()) {
      // gtTexture, gtShader, ...: the symbol a GeoViS command returns = the latest of that kind.
      if (id.size() > 2 && id.compare(0, 2, "gt") == 0)
        if (const DefPtr* d = last_of(m, kind, before)) return *d;
      fail_unknown_id(m, ps, key, id, kind);
    }
    if (it->second->kind != kind)
      ps.fail(key, "\"" + id + "\" is a " + kind_name(it->second->kind) + " (" + it->second->ps.command() +
                       "), expected a " + kind_name(kind));
    return it->second;
  }

  /// The definition named under `key`, or the last one of `kind` before call `before`.
  static const DefPtr& resolve(const DefMap& m, const ParamSet& ps, std::string_view key, Kind kind, int before) {
    if (const Param* p = ps.find(key)) {
      if (!p->value.is_string()) ps.fail(key, "expected a string (an id), found " + p->value.describe());
      return lookup(m, ps, key, std::get<std::string>(p->value.v), kind, before);
    }
    if (const DefPtr* d = last_of(m, kind, before)) return *d;
    ps.fail(key, std::string("no ") + kind_name(kind) + " is defined before this command");
  }

  // ---- cache ----

  template <class T, class Make>
  std::shared_ptr<T> cached(const std::string& key, Make&& make, int* objects_used = nullptr) const {
    {
      std::lock_guard<std::mutex> lock(cache_mutex);
      auto it = cache.find(key);
      if (it != cache.end()) {
        it->second.last_used = generation;
        if (objects_used) *objects_used = it->second.objects_used;
        return std::const_pointer_cast<T>(std::static_pointer_cast<const T>(it->second.value));
      }
    }
    std::shared_ptr<T> v = make();
    std::lock_guard<std::mutex> lock(cache_mutex);
    CacheEntry e;
    e.value = v;
    e.objects_used = objects_used ? *objects_used : 0;
    e.last_used = generation;
    cache[key] = std::move(e);
    return v;
  }

  /// Forgets what the last two device builds did not use (bounded memory over long sequences).
  void trim_cache() const {
    std::lock_guard<std::mutex> lock(cache_mutex);
    for (auto it = cache.begin(); it != cache.end();)
      it = it->second.last_used < generation - 1 ? cache.erase(it) : std::next(it);
    ++generation;
  }

  // ---- solver configuration (catalogue §1 init-solver / init-raygen) ----

  static SolverConfig solver_config(const ParamSet& ps) {
    SolverConfig c;
    try {
      c.kind = solver_kind_from_name(ps.get_string("type"));
    } catch (const std::exception& e) {
      rethrow_at(ps, "type", e);
    }
    if (ps.has("geodtype")) {
      try {
        c.type = parse_geodesic_type(ps.get_string("geodtype"));
      } catch (const std::exception& e) {
        rethrow_at(ps, "geodtype", e);
      }
    }
    const std::string dir = ps.get_string("geoddir", std::string("forward"));
    if (dir != "forward" && dir != "backward")
      ps.fail("geoddir", "expected \"forward\" or \"backward\", found \"" + dir + "\"");
    c.step_ctrl = ps.get_bool("step_ctrl", true);
    c.step_size = ps.get_number("step_size", 0.01);
    c.step_max = ps.get_number("max_step", c.step_max);
    c.eps_abs = ps.get_number("eps_abs", 1e-4);
    c.eps_rel = ps.get_number("eps_rel", 0.0);
    c.separable = ps.get_bool("separable", true);
    if (!(c.step_size > 0)) ps.fail("step_size", "expected a positive step size, found " + std::to_string(c.step_size));
    if (!(c.step_max > 0)) ps.fail("max_step", "expected a positive maximal step, found " + std::to_string(c.step_max));
    if (!(c.eps_abs >= 0) || !(c.eps_rel >= 0) || (c.eps_abs == 0 && c.eps_rel == 0 && c.step_ctrl))
      ps.fail("eps_abs", "expected non-negative tolerances, not both zero with step control");
    // GeoViS default bounding box: (±DBL_MAX, ±50, ±50, ±50) (catalogue §1).
    set_box(ps, c);
    return c;
  }

  static void set_box(const ParamSet& ps, SolverConfig& c) {
    const std::vector<double> ll = ps.get_vector("boundboxll", 4, std::vector<double>{-DBL_MAX, -50, -50, -50});
    const std::vector<double> ur = ps.get_vector("boundboxur", 4, std::vector<double>{DBL_MAX, 50, 50, 50});
    for (int i = 0; i < 4; ++i) {
      if (!(ll[i] < ur[i])) ps.fail("boundboxur", "every component must exceed the one of boundBoxLL");
      c.box_ll[i] = ll[i];
      c.box_ur[i] = ur[i];
    }
  }
};

// =================================================================================================
// Building one device.

namespace {

struct DeviceInfo {
  std::string metric_line, observer_line, camera_line, objects_line;
};

}  // namespace

class DeviceBuild {
 public:
  using Impl = SceneBuilder::Impl;
  DeviceBuild(const Impl& impl, const DeviceDef& dev) : impl_(impl), dev_(dev), defs_(*dev.defs) {
    for (const auto& sp : dev.setparams) impl.apply_setparam(*dev.defs, sp, dev.ps, &defs_);
    ctx_.diag = impl.opts.diag;
    ctx_.search_paths = impl.opts.search_paths;
  }

  std::vector<FrameJob> build(int device_no, DeviceInfo* info) {
    const ParamSet& dps = dev_.ps;
    // -- metric --
    const DefPtr& mdef = Impl::resolve(defs_, dps, "metric", Kind::Metric, dev_.seq);
    metric_ = metric_of(mdef, &metric_key_);
    ctx_.metric = metric_;

    // -- everything a device may reference, in GeoViS creation order --
    std::vector<DefPtr> ordered;
    for (const auto& [id, d] : defs_) ordered.push_back(d);
    std::sort(ordered.begin(), ordered.end(), [](const DefPtr& a, const DefPtr& b) { return a->seq < b->seq; });
    for (const auto& d : ordered)
      if (d->kind == Kind::Texture) ensure(d);
    for (const auto& d : ordered)
      if (d->kind == Kind::Shader || d->kind == Kind::Light) ensure(d);
    // Primitives first, in creation order: their objIDs count from 1 in that order (GeoViS
    // mObjCounter); containers (which may contain later objects through add-object) afterwards.
    for (const auto& d : ordered)
      if (d->kind == Kind::Object && !is_container(d->ps.command())) ensure(d);
    for (const auto& d : ordered)
      if (d->kind == Kind::Object && is_container(d->ps.command())) ensure(d);

    RenderJob job;
    job.metric = metric_;
    job.supersample = impl_.opts.supersample;

    // -- scene graph: `obj`, else the last object created before init-device --
    const DefPtr& root = Impl::resolve(defs_, dps, "obj", Kind::Object, dev_.seq);
    job.scene = ctx_.objects.at(root->id);

    // -- light manager --
    if (dps.has("lightmgr") || Impl::last_of(defs_, Kind::LightMgr, dev_.seq)) {
      const DefPtr& lm = Impl::resolve(defs_, dps, "lightmgr", Kind::LightMgr, dev_.seq);
      for (const auto& ref : ref_keys(Kind::LightMgr))
        for (const Param* p : lm->ps.find_all(ref.key)) {
          if (!p->value.is_string()) lm->ps.fail(ref.key, "expected a string (an id), found " + p->value.describe());
          Impl::lookup(defs_, lm->ps, ref.key, std::get<std::string>(p->value.v), ref.kind, lm->seq);
        }
      try {
        job.lights = make_light_manager(lm->ps, ctx_);
      } catch (const std::exception& e) {
        rethrow_at(lm->ps, "", e);
      }
    }

    // -- projector: observer, ray generator, colours --
    const DefPtr& proj = Impl::resolve(defs_, dps, "projector", Kind::Projector, dev_.seq);
    const ParamSet& pps = proj->ps;
    job.background = color3(pps, "color", Color{0, 0, 0});
    if (pps.has("errcolor")) job.error_color = color3(pps, "errcolor", Color{});
    if (pps.has("cstrcolor")) job.constraint_color = color3(pps, "cstrcolor", Color{});
    if (pps.has("breakcolor")) job.break_color = color3(pps, "breakcolor", Color{});
    std::string observer_kind;
    job.observer = observer_of(proj, observer_kind);
    if (!metric_->is_valid(job.observer.pos))
      pps.fail(pps.has("motion") ? "motion" : "localtetrad",
               "the observer position " + fmt_vec(job.observer.pos.c, 4) + " is outside the validity domain of the " +
                   metric_->name() + " metric (e.g. inside a horizon or on a coordinate singularity)");

    const DefPtr& rg = Impl::resolve(defs_, pps, "raygen", Kind::RayGen, proj->seq);
    job.solver = raygen_config(rg);

    // -- camera --
    const DefPtr& cdef = Impl::resolve(defs_, dps, "camera", Kind::Camera, dev_.seq);
    CameraPtr cam;
    try {
      cam = make_camera(cdef->ps, ctx_);
    } catch (const std::exception& e) {
      rethrow_at(cdef->ps, "type", e);
    }
    for (const auto& ch : cdef->changes) {
      try {
        cam->set_param(ch.key, ch.value);
      } catch (const std::exception& e) {
        throw SceneError(ch.loc.line ? ch.loc : dps.loc(), dps.command(), "setparam",
                         "camera \"" + cdef->id + "\": " + e.what());
      }
    }
    if (impl_.opts.resolution) {
      try {
        override_camera_resolution(*cam, impl_.opts.resolution->first, impl_.opts.resolution->second);
      } catch (const std::exception& e) {
        throw Error(std::string("--res: ") + e.what());
      }
    }
    job.filter = cam->filter;
    if (job.solver.kind == SolverKind::RungeKuttaNystrom86 &&
        (!metric_->has_separable_geodesics() || !job.solver.separable || job.filter == Filter::RGBjac)) {
      const DefPtr& sdef = Impl::resolve(defs_, rg->ps, "solver", Kind::Solver, rg->seq);
      sdef->ps.fail("type", std::string("RKN86 integrates only the separated geodesic equations of KerrBL and "
                                        "Schwarzschild (") +
                                (job.filter == Filter::RGBjac ? "not the Jacobi equation of the RGBjac filter"
                                 : !job.solver.separable       ? "here switched off by 'separable #f'"
                                                               : "this scene's metric is " + metric_->name()) +
                                "); use DOP853");
    }

    if (info) {
      std::ostringstream m;
      m << metric_->name();
      const auto& ps = metric_->info().params;
      for (size_t i = 0; i < ps.size(); ++i) m << (i ? ", " : " (") << ps[i].name << " = " << metric_->param_values()[i];
      if (!ps.empty()) m << ")";
      info->metric_line = m.str();
      info->observer_line = "position " + fmt_vec(job.observer.pos.c, 4) + ", " + observer_kind;
      std::ostringstream c;
      c << cam->type_name() << " " << cam->width() << "x" << cam->height();
      if (const Param* fov = cdef->ps.find("fov")) {
        c << ", fov ";
        put_value_readable(c, fov->value);
      }
      c << ", filter " << cdef->ps.get_string("filter", std::string("FilterRGB"));
      if (cam->is_stereo()) c << ", stereo";
      info->camera_line = c.str();
      std::map<std::string, int> counts;
      count_objects(root, counts);
      std::ostringstream o;
      int total = 0;
      for (const auto& [k, n] : counts) {
        o << (total ? ", " : "") << n << " " << k;
        total += n;
      }
      info->objects_line = o.str();
    }

    std::vector<FrameJob> out;
    std::vector<std::string> files;
    if (*filter_data_extension(job.filter)) files.push_back(filter_data_extension(job.filter));
    if (cam->is_stereo()) {
      // Two images per device; each eye is the observer displaced in its local frame
      // (GeoViS PinHoleStereoCam).
      for (Eye eye : {Eye::Left, Eye::Right}) {
        FrameJob fj;
        fj.device = device_no;
        fj.eye = eye == Eye::Left ? "left" : "right";
        fj.job = job;
        fj.job.observer = offset_observer(job.observer, cam->eye_offset(eye));
        fj.job.camera = cam;
        fj.data_files_wanted = files;
        out.push_back(std::move(fj));
      }
    } else {
      FrameJob fj;
      fj.device = device_no;
      fj.job = std::move(job);
      fj.job.camera = cam;
      fj.data_files_wanted = files;
      out.push_back(std::move(fj));
    }
    return out;
  }

  // ---- pieces usable by the actions ----

  std::shared_ptr<const Metric> metric_of(const DefPtr& d, std::string* key_out) {
    const std::string key = "metric:" + serialize(d->ps, d->changes);
    if (key_out) *key_out = key;
    return impl_.cached<const Metric>(key, [&] { return build_metric(*d); });
  }

  SolverConfig raygen_config(const DefPtr& rg) {
    const ParamSet& rps = rg->ps;
    const std::string type = rps.get_string("type", std::string("RayGenSimple"));
    if (type != "RayGenSimple")
      rps.fail("type", "unknown ray generator \"" + type + "\"" + did_you_mean(type, {"RayGenSimple"}) +
                           " (valid: RayGenSimple)");
    const DefPtr& sdef = Impl::resolve(defs_, rps, "solver", Kind::Solver, rg->seq);
    SolverConfig c = Impl::solver_config(sdef->ps);
    // A solver used by a ray generator integrates light rays backwards (catalogue §1): the
    // initial tangent is past-directed (paper eq. 7), set by the tracer; λ increases.
    c.type = GeodesicType::Lightlike;
    c.direction = 1.0;
    c.max_steps = rps.get_int("maxnumpoints", 3000);
    if (c.max_steps < 2) rps.fail("maxnumpoints", "expected at least 2 points, found " + std::to_string(c.max_steps));
    if (rps.has("boundboxll") || rps.has("boundboxur")) Impl::set_box(rps, c);
    return c;
  }

  LocalTetrad tetrad_of(const DefPtr& d) {
    const std::shared_ptr<const Metric> m = tetrad_metric(d);
    LocalTetrad t;
    try {
      t.e = tetrad_from_params(d->ps, *m, &t.pos);
    } catch (const std::exception& e) {
      rethrow_at(d->ps, "", e);
    }
    if (!m->is_valid(t.pos))
      d->ps.fail("pos", "the position " + fmt_vec(t.pos.c, 4) + " is outside the validity domain of the " + m->name() +
                            " metric (e.g. inside a horizon or on a coordinate singularity)");
    return t;
  }

  MotionPtr motion_of(const DefPtr& d) {
    std::shared_ptr<const Metric> m = metric_;
    std::string mkey = metric_key_;
    if (d->ps.has("metric")) m = metric_of(Impl::resolve(defs_, d->ps, "metric", Kind::Metric, d->seq), &mkey);
    SolverConfig cfg;
    std::string skey;
    if (d->ps.has("solver") || Impl::last_of(defs_, Kind::Solver, d->seq)) {
      const DefPtr& s = Impl::resolve(defs_, d->ps, "solver", Kind::Solver, d->seq);
      cfg = Impl::solver_config(s->ps);
      skey = serialize(s->ps);
    }
    // A motion is the worldline of a massive body: its geodesic is timelike.
    cfg.type = GeodesicType::Timelike;
    const std::string key = "motion:" + serialize(d->ps) + "|" + mkey + "|" + skey;
    return impl_.cached<Motion>(key, [&]() -> std::shared_ptr<Motion> {
      try {
        MotionPtr mp = make_motion(d->ps, m, cfg);
        if (!mp || mp->samples().empty()) d->ps.fail("", "the motion has no points");
        return mp;
      } catch (const std::exception& e) {
        rethrow_at(d->ps, "", e);
      }
    });
  }

  const DefMap& defs() const { return defs_; }
  BuildContext& ctx() { return ctx_; }
  const std::shared_ptr<const Metric>& metric() const { return metric_; }
  void set_metric(const DefPtr& d) {
    metric_ = metric_of(d, &metric_key_);
    ctx_.metric = metric_;
  }

  Observer observer_of(const DefPtr& proj, std::string& kind) {
    const ParamSet& pps = proj->ps;
    Observer obs;
    if (pps.has("motion")) {
      const DefPtr& md = Impl::resolve(defs_, pps, "motion", Kind::Motion, proj->seq);
      const MotionPtr mo = motion_of(md);
      const auto& samples = mo->samples();
      const int n = pps.get_int("actualpos", 0);
      if (n < 0 || n >= static_cast<int>(samples.size()))
        pps.fail("actualpos", "point " + std::to_string(n) + " does not exist: motion \"" + md->id + "\" has " +
                                  std::to_string(samples.size()) + " points (0 to " +
                                  std::to_string(samples.size() - 1) + ")");
      obs.pos = samples[n].x;
      obs.e = samples[n].e;
      kind = "moving with motion \"" + md->id + "\" (point " + std::to_string(n) + " of " +
             std::to_string(samples.size()) + ", proper time " + std::to_string(samples[n].tau) + ")";
      return obs;
    }
    if (!pps.has("localtetrad") && pps.has("pos")) {
      // The tetrad given inline (pos has 4 or 5 components; GeoViS reads the first four).
      ParamSet tps = pps;
      tps.set("pos", Value(std::vector<double>([&] {
                auto v = pps.get_vector_any("pos", {4, 5});
                v.resize(4);
                return v;
              }())),
              pps.find("pos")->loc);
      auto d = std::make_shared<Def>(*proj);
      d->ps = tps;
      const LocalTetrad t = tetrad_of(d);
      obs.pos = t.pos;
      obs.e = t.e;
      kind = "static tetrad given in the projector";
      return obs;
    }
    const DefPtr& td = Impl::resolve(defs_, pps, "localtetrad", Kind::Tetrad, proj->seq);
    const LocalTetrad t = tetrad_of(td);
    obs.pos = t.pos;
    obs.e = t.e;
    kind = "static local tetrad \"" + td->id + "\"" +
           (td->ps.get_bool("incoords", false) ? " (coordinate components)"
                                               : std::string(" (relative to the ") +
                                                     tetrad_kind_name(static_cast<TetradKind>(
                                                         td->ps.get_int("localframe", 0))) +
                                                     " natural tetrad)");
    if (td->ps.has("localvel")) kind += ", boosted by localvel " + fmt_vec(td->ps.get_vector("localvel", 3).data(), 3);
    return obs;
  }

 private:
  std::shared_ptr<const Metric> tetrad_metric(const DefPtr& d) {
    if (d->ps.has("metric") && d->kind == Kind::Tetrad)
      return metric_of(Impl::resolve(defs_, d->ps, "metric", Kind::Metric, d->seq), nullptr);
    return metric_;
  }

  static std::shared_ptr<const Metric> build_metric(const Def& d) {
    const ParamSet& ps = d.ps;
    const std::string type = ps.get_string("type");
    std::unique_ptr<Metric> m;
    try {
      m = make_metric(type);
    } catch (const std::exception& e) {
      rethrow_at(ps, "type", e);
    }
    // Every key but type and id is a metric parameter (catalogue §1).
    for (const auto& p : ps.entries()) {
      if (p.key == "type" || p.key == "id") continue;
      const double v = ps.get_number(p.key);
      try {
        m->set_param(p.key, v);
      } catch (const std::exception& e) {
        rethrow_at(ps, p.key, e);
      }
    }
    for (const auto& ch : d.changes) {
      try {
        m->set_param(ch.key, value_as_number(ch.value, ch.key));
      } catch (const std::exception& e) {
        throw SceneError(ch.loc, "setparam", ch.key, "metric \"" + d.id + "\": " + e.what());  // value out of range
      }
    }
    return std::shared_ptr<const Metric>(std::move(m));
  }

  static Color color3(const ParamSet& ps, std::string_view key, Color def) {
    const auto v = ps.get_vector(key, 3, std::vector<double>{def.r, def.g, def.b});
    return Color{v[0], v[1], v[2]};
  }

  static void put_value_readable(std::ostream& os, const Value& v) {
    if (v.is_vector()) {
      const auto& d = std::get<std::vector<double>>(v.v);
      for (size_t i = 0; i < d.size(); ++i) os << (i ? " x " : "") << d[i];
    } else if (v.is_number()) {
      os << std::get<double>(v.v);
    } else {
      os << v.describe();
    }
  }

  void count_objects(const DefPtr& d, std::map<std::string, int>& counts) {
    ++counts[d->ps.command()];
    for (const char* key : {"obj", "obj1", "obj2"})
      for (const Param* p : d->ps.find_all(key))
        if (p->value.is_string()) {
          auto it = defs_.find(std::get<std::string>(p->value.v));
          if (it != defs_.end() && it->second->kind == Kind::Object) count_objects(it->second, counts);
        }
  }

  /// Builds definition `d` (and what it references) into the build context, once per device,
  /// reusing the cache when its contents and dependencies are unchanged. Returns its cache key.
  const std::string& ensure(const DefPtr& d) {
    auto done = keys_.find(d->id);
    if (done != keys_.end()) return done->second;
    if (!in_progress_.insert(d->id).second)
      d->ps.fail("", "\"" + d->id + "\" refers to itself (through the objects, shaders or textures it uses)");
    std::string key = std::string(kind_name(d->kind)) + ":" + serialize(d->ps, d->changes);
    for (const auto& ref : ref_keys(d->kind))
      for (const Param* p : d->ps.find_all(ref.key)) {
        if (!p->value.is_string()) d->ps.fail(ref.key, "expected a string (an id), found " + p->value.describe());
        const DefPtr& dep = Impl::lookup(defs_, d->ps, ref.key, std::get<std::string>(p->value.v), ref.kind, d->seq);
        if (ref.kind == Kind::Motion) {
          ctx_.motions[dep->id] = motion_of(dep);
          // gtMotion-style references resolve to an id the factory does not know: alias it.
          ctx_.motions[std::get<std::string>(p->value.v)] = ctx_.motions[dep->id];
          key += "|" + std::string(ref.key) + "=" + motion_key(dep);
        } else if (ref.kind == Kind::Tetrad) {
          const LocalTetrad t = tetrad_of(dep);
          ctx_.tetrads[dep->id] = t;
          ctx_.tetrads[std::get<std::string>(p->value.v)] = t;
          key += "|" + std::string(ref.key) + "=" + serialize(dep->ps, dep->changes) + metric_key_;
        } else {
          key += "|" + std::string(ref.key) + "=" + ensure(dep);
          alias(ref.kind, std::get<std::string>(p->value.v), dep->id);
        }
      }
    try {
      switch (d->kind) {
        case Kind::Texture:
          ctx_.textures[d->id] = impl_.cached<Texture>(
              key, [&] { return make_texture(with_files_found(d->ps, ctx_.search_paths, ctx_.diag), ctx_); });
          break;
        case Kind::Shader:
          ctx_.shaders[d->id] = impl_.cached<Shader>(key, [&] { return make_shader(d->ps, ctx_); });
          break;
        case Kind::Light:
          ctx_.lights[d->id] = make_point_light(d->ps, ctx_);
          break;
        case Kind::Object: {
          // Objects live in the metric's pseudo-Cartesian coordinates; primitives consume objIDs
          // from the counter, so both are part of the key.
          key += "|" + metric_key_ + "|#" + std::to_string(ctx_.object_count());
          const int start = ctx_.object_count();
          int used = 0;
          bool built = false;
          auto obj = impl_.cached<SceneObject>(
              key,
              [&] {
                built = true;
                SceneObjectPtr o = make_object(with_files_found(d->ps, ctx_.search_paths, ctx_.diag), ctx_);
                if (o && o->id.empty()) o->id = d->id;
                used = ctx_.object_count() - start;
                return o;
              },
              &used);
          if (!built) ctx_.set_object_count(start + used);
          ctx_.objects[d->id] = obj;
          break;
        }
        default: break;
      }
    } catch (const std::exception& e) {
      rethrow_at(d->ps, "", e);
    }
    in_progress_.erase(d->id);
    return keys_[d->id] = key;
  }

  std::string motion_key(const DefPtr& d) const { return serialize(d->ps) + metric_key_; }

  void alias(Kind kind, const std::string& name, const std::string& id) {
    if (name == id) return;
    switch (kind) {
      case Kind::Texture: ctx_.textures[name] = ctx_.textures[id]; break;
      case Kind::Shader: ctx_.shaders[name] = ctx_.shaders[id]; break;
      case Kind::Object: ctx_.objects[name] = ctx_.objects[id]; break;
      case Kind::Light: ctx_.lights[name] = ctx_.lights[id]; break;
      default: break;
    }
  }

  const Impl& impl_;
  const DeviceDef& dev_;
  DefMap defs_;
  BuildContext ctx_;
  std::shared_ptr<const Metric> metric_;
  std::string metric_key_;
  std::map<std::string, std::string> keys_;
  std::set<std::string> in_progress_;
};

// =================================================================================================

SceneBuilder::SceneBuilder(SceneDescription scene, BuildOptions opts)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(opts))) {
  if (impl_->opts.supersample < 1)
    throw Error("--supersample: expected a positive number of samples, found " + std::to_string(impl_->opts.supersample));
  impl_->process();
}
SceneBuilder::~SceneBuilder() = default;
SceneBuilder::SceneBuilder(SceneBuilder&&) noexcept = default;
SceneBuilder& SceneBuilder::operator=(SceneBuilder&&) noexcept = default;

int SceneBuilder::device_count() const { return static_cast<int>(impl_->devices.size()); }
int SceneBuilder::action_count() const { return static_cast<int>(impl_->actions.size()); }

std::vector<FrameJob> SceneBuilder::build(int device) const {
  if (device < 0 || device >= device_count())
    throw Error("device " + std::to_string(device) + " does not exist: the scene has " +
                std::to_string(device_count()) + " device(s)" +
                (device_count() ? " (0 to " + std::to_string(device_count() - 1) + ")" : std::string()));
  DeviceBuild b(*impl_, impl_->devices[device]);
  auto jobs = b.build(device, nullptr);
  impl_->trim_cache();
  return jobs;
}

std::string SceneBuilder::summary() const {
  std::ostringstream os;
  const std::string name = impl_->scene.file.empty() ? std::string("(scene)") : impl_->scene.file;
  os << "scene:    " << name << "\n";
  if (impl_->devices.empty()) {
    os << "frames:   0 (the scene has no init-device)\n";
    return os.str();
  }
  DeviceInfo info;
  DeviceBuild b(*impl_, impl_->devices[0]);
  const auto jobs = b.build(0, &info);
  os << "metric:   " << info.metric_line << "\n";
  os << "observer: " << info.observer_line << "\n";
  os << "camera:   " << info.camera_line << "\n";
  os << "objects:  " << info.objects_line << "\n";
  os << "frames:   " << device_count() << (jobs.size() == 2 ? " (stereo: 2 images per frame)" : "") << "\n";
  if (!impl_->actions.empty()) os << "actions:  " << impl_->actions.size() << "\n";
  return os.str();
}

// ---- actions ----------------------------------------------------------------------------------

namespace {

namespace fs = std::filesystem;

// Where an action writes the file named by `key`: relative to the output folder; for a sandboxed
// scene only below it (docs/security.md).
std::string action_output_path(const ParamSet& ps, const std::string& key, const BuildOptions& opts) {
  const std::string name = ps.get_string(key);
  fs::path p(name);
  if (p.is_relative() && !opts.output_dir.empty()) p = fs::path(opts.output_dir) / p;
  if (opts.confine_output) {
    std::error_code ec;
    const fs::path root = fs::weakly_canonical(opts.output_dir.empty() ? fs::path(".") : fs::path(opts.output_dir), ec);
    const fs::path target = fs::weakly_canonical(fs::absolute(p, ec), ec);
    const bool below = std::mismatch(root.begin(), root.end(), target.begin(), target.end()).first == root.end() &&
                       target != root;
    if (ec || !below)
      ps.fail(key, "\"" + name + "\" is outside the output folder " + root.string() +
                       ": a scene may write its files only below it (they run sandboxed; --trust-scene lifts this)");
  }
  return p.string();
}

}  // namespace

void SceneBuilder::run_actions(std::ostream& out) const {
  for (const ActionDef& a : impl_->actions) {
    const ParamSet& ps = a.call.params;
    const std::string& cmd = a.call.command;
    // The definitions as they were at the action, with the metric last defined before it.
    DeviceDef pseudo;
    pseudo.seq = a.seq;
    pseudo.ps = ps;
    pseudo.defs = a.defs;
    DeviceBuild b(*impl_, pseudo);
    auto with_metric = [&](const DefPtr* m) {
      if (!m) ps.fail("", "no metric is defined before this command");
      b.set_metric(*m);
    };
    if (cmd == "gvs-print") {
      const std::string id = ps.get_string("id");
      auto it = a.defs->find(id);
      if (it == a.defs->end()) Impl::fail_unknown_id(*a.defs, ps, "id", id, std::nullopt);
      const Def& d = *it->second;
      out << d.ps.command() << " \"" << d.id << "\"";
      if (!d.ps.loc().str().empty()) out << " (" << d.ps.loc().str() << ")";
      out << "\n";
      for (const auto& p : d.ps.entries()) out << "  " << p.key << ": " << p.value.describe() << "\n";
      for (const auto& p : d.changes) out << "  " << p.key << " (changed): " << p.value.describe() << "\n";
      continue;
    }
    if (cmd == "gvs-print-motion") {
      const DefPtr& md = Impl::resolve(*a.defs, ps, "id", Kind::Motion, a.seq);
      with_metric(md->ps.has("metric") ? &Impl::resolve(*a.defs, md->ps, "metric", Kind::Metric, md->seq)
                                       : Impl::last_of(*a.defs, Kind::Metric, md->seq));
      const MotionPtr mo = b.motion_of(md);
      std::ostringstream data;
      mo->write(data);
      const std::string file = action_output_path(ps, "file", impl_->opts);
      if (!impl_->opts.write_action_files) continue;
      try {
        write_file_atomic(file, data.str());
      } catch (const Error& e) {
        ps.fail("file", e.what());
      }
      continue;
    }
    if (cmd == "calc-ray" || cmd == "calc-proj-ray") {
      const bool proj_ray = cmd == "calc-proj-ray";
      const std::string file = action_output_path(ps, "filename", impl_->opts);
      const DefPtr& rg = Impl::resolve(*a.defs, ps, "raygen", Kind::RayGen, a.seq);
      with_metric(Impl::last_of(*a.defs, Kind::Metric, a.seq));
      SolverConfig cfg = b.raygen_config(rg);
      const Metric& m = *b.metric();
      Tetrad e{};
      Vec4 start{};
      Vec4 k{};
      if (proj_ray) {
        const DefPtr& proj = Impl::resolve(*a.defs, ps, "projector", Kind::Projector, a.seq);
        std::string kind;
        const Observer o = b.observer_of(proj, kind);
        e = o.e;
        start = o.pos;
        const auto d = ps.get_vector("dir", 3, std::vector<double>{-1, 0, 0});
        // GeoViS: k = -e0 + d^i e_i with d as given (not normalised).
        for (int mu = 0; mu < 4; ++mu) k[mu] = -e[0][mu] + d[0] * e[1][mu] + d[1] * e[2][mu] + d[2] * e[3][mu];
      } else {
        const DefPtr& td = Impl::resolve(*a.defs, ps, "locted", Kind::Tetrad, a.seq);
        const LocalTetrad t = b.tetrad_of(td);
        e = t.e;
        const auto pos = ps.get_vector_any("pos", {4, 5}, std::vector<double>{t.pos[0], t.pos[1], t.pos[2], t.pos[3]});
        start = Vec4{{pos[0], pos[1], pos[2], pos[3]}};
        // dir = (ξ, χ) in degrees: local direction (sinχ cosξ, sinχ sinξ, cosχ), past-directed
        // (GeoViS calc-ray).
        const auto dir = ps.get_vector("dir", 2, std::vector<double>{0, 0});
        const double ksi = dir[0] * M_PI / 180.0, chi = dir[1] * M_PI / 180.0;
        const Vec4 loc{{-1.0, std::sin(chi) * std::cos(ksi), std::sin(chi) * std::sin(ksi), std::cos(chi)}};
        k = local_to_coord(e, loc);
      }
      if (!m.is_valid(start))
        ps.fail(proj_ray ? "projector" : "pos", "the start point " + fmt_vec(start.c, 4) +
                                                   " is outside the validity domain of the " + m.name() + " metric");
      const bool cartesian = proj_ray && ps.get_bool("cartesian", false);
      double J[4][4];
      Vec4 xc;
      if (cartesian && !cartesian_jacobian(m.info().coord_type, start, xc, J))
        ps.fail("cartesian", std::string("Cartesian output needs Cartesian, spherical or cylindrical coordinates; the ") +
                                 m.name() + " metric uses " + coord_type_name(m.info().coord_type) + " coordinates");
      std::ostringstream txt;
      txt.precision(10);
      const GeodesicSystem sys = proj_ray ? GeodesicSystem::Transport : GeodesicSystem::Geodesic;
      double y[kMaxSystemDim] = {};
      for (int i = 0; i < 4; ++i) {
        y[i] = start[i];
        y[4 + i] = k[i];
      }
      if (proj_ray)
        for (int a2 = 0; a2 < 4; ++a2)
          for (int mu = 0; mu < 4; ++mu) y[8 + 4 * a2 + mu] = e[a2][mu];
      auto write_point = [&](const double* s) {
        const Vec4 x{{s[0], s[1], s[2], s[3]}};
        const Vec4 kv{{s[4], s[5], s[6], s[7]}};
        if (!proj_ray) {
          txt << x[0] << " " << x[1] << " " << x[2] << " " << x[3] << "\n";
          return;
        }
        // GeoViS calc-proj-ray columns: pos(4) 0 dir(4) e0..e3 (16) sqrt|g(k,k)|.
        Mat4 g;
        m.metric_tensor(x, g);
        const double nrm = std::sqrt(std::fabs(dot(g, kv, kv)));
        Vec4 px = x, pk = kv;
        Vec4 base[4];
        for (int a2 = 0; a2 < 4; ++a2) base[a2] = Vec4{{s[8 + 4 * a2], s[9 + 4 * a2], s[10 + 4 * a2], s[11 + 4 * a2]}};
        if (cartesian) {
          cartesian_jacobian(m.info().coord_type, x, px, J);
          pk = apply_jacobian(J, kv);
          for (auto& bv : base) bv = apply_jacobian(J, bv);
        }
        txt << px[0] << " " << px[1] << " " << px[2] << " " << px[3] << " 0";
        for (int i = 0; i < 4; ++i) txt << " " << pk[i];
        for (const auto& bv : base)
          for (int i = 0; i < 4; ++i) txt << " " << bv[i];
        txt << " " << nrm << "\n";
      };
      write_point(y);
      auto cb = [&](const StepView& st) {
        write_point(st.y1);
        return StepAction::Continue;
      };
      m.integrate(cfg, sys, y, 0.0, StepCallback(cb));
      if (!impl_->opts.write_action_files) continue;
      try {
        write_file_atomic(file, txt.str());
      } catch (const Error& e) {
        ps.fail("filename", e.what());
      }
      continue;
    }
  }
}

}  // namespace geovis
