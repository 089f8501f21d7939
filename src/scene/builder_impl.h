// SceneBuilder::Impl: reads a scene's calls in order into definitions, devices and actions,
// resolves references between them (rules in builder.cpp's header comment) and caches what is
// built from them. Internal to src/scene/.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/param_reader.h"
#include "scene/builder.h"
#include "scene/command_table.h"
#include "scene/cache_keys.h"
#include "scene/definitions.h"
#include "scene/frame_changes.h"
#include "scene/scheme.h"
#include "spacetime/geodesic.h"
#include "spacetime/motion_factory.h"

namespace geovis {

using namespace scene_build;

struct SceneBuilder::Impl {
  SceneDescription scene;
  BuildOptions opts;

  DefMap defs;                             ///< current definitions while the calls are processed
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
    const SceneCommand* entry = command_entry(cmd);
    if (!entry) throw SceneError(ps.loc(), cmd, "", "unknown command" + did_you_mean(cmd, scene_command_names()));
    if (entry->role == CommandRole::Immediate) return;  // evaluated by the scene language, nothing to build
    if (const auto keys = builder_checked_keys(*entry, ps)) ps.validate(*keys, opts.diag ? *opts.diag : sink);
    if (is_definition(entry)) {
      auto d = std::make_shared<Def>();
      d->kind = entry->kind;
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
      const std::vector<std::string> type_names = entry->types();
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
    if (entry->role == CommandRole::Action) actions.push_back(ActionDef{seq, call, current_snapshot()});
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
    const std::string what = kind ? definition_kind_name(*kind) : "object";
    ps.fail(key,
            "unknown " + what + " id \"" + id + "\"" + did_you_mean(id, ids) +
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
      ps.fail(key, "\"" + id + "\" is a " + definition_kind_name(it->second->kind) + " (" + it->second->ps.command() +
                       "), expected a " + definition_kind_name(kind));
    return it->second;
  }

  /// The definition named under `key`, or the last one of `kind` before call `before`.
  static const DefPtr& resolve(const DefMap& m, const ParamSet& ps, std::string_view key, Kind kind, int before) {
    if (const Param* p = ps.find(key)) {
      if (!p->value.is_string()) ps.fail(key, "expected a string (an id), found " + p->value.describe());
      return lookup(m, ps, key, std::get<std::string>(p->value.v), kind, before);
    }
    if (const DefPtr* d = last_of(m, kind, before)) return *d;
    ps.fail(key, std::string("no ") + definition_kind_name(kind) + " is defined before this command");
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

  /// init-solver's keys with their defaults (scene/command_table.cpp): read through them so the
  /// documented defaults are the ones used.
  static SolverConfig solver_config(const ParamSet& ps) {
    const std::vector<ParamSpec> specs = find_scene_command("init-solver")->keys(std::string());
    const ParamReader keys(ps, specs);
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
    const std::string dir = keys.string("geoddir");
    if (dir != "forward" && dir != "backward")
      ps.fail("geoddir", "expected \"forward\" or \"backward\", found \"" + dir + "\"");
    c.step_ctrl = keys.boolean("step_ctrl");
    c.step_size = keys.number("step_size");
    c.step_max = keys.number("max_step");
    c.step_max_separable = ps.has("max_step");
    c.eps_abs = keys.number("eps_abs");
    c.eps_rel = keys.number("eps_rel");
    c.separable = keys.boolean("separable");
    if (c.eps_abs == 0 && c.eps_rel == 0 && c.step_ctrl)
      ps.fail("eps_abs", "expected non-negative tolerances, not both zero with step control");
    set_box(keys, c);
    return c;
  }

  /// boundboxll/boundboxur of init-solver or init-raygen.
  static void set_box(const ParamReader& keys, SolverConfig& c) {
    const std::vector<double> ll = keys.vector("boundboxll", 4);
    const std::vector<double> ur = keys.vector("boundboxur", 4);
    for (int i = 0; i < 4; ++i) {
      if (!(ll[i] < ur[i])) keys.fail("boundboxur", "every component must exceed the one of boundBoxLL");
      c.box_ll[i] = ll[i];
      c.box_ur[i] = ur[i];
    }
  }
};

}  // namespace geovis
