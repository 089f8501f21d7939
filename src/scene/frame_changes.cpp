#include "scene/frame_changes.h"

#include <algorithm>

#include "core/error.h"
#include "spacetime/metric_registry.h"

namespace geovis::scene_build {

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

/// Names a setparam may change for a definition (docs/geovis-catalogue.md §10, from the command
/// table). `any` = every parameter of the type (metrics and cameras check the name themselves).
std::vector<std::string> settable_names(const Def& d, bool& any) {
  const SceneCommand* c = command_entry(d.ps.command());
  any = c && c->change_rule == Changeable::TypeParameters;
  if (!c || any || !c->changeable) return {};
  return c->changeable(d.ps.get_string("type", std::string()));
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
      throw SceneError(loc.line ? loc : where.loc(), where.command(), key_for_errors, "\"" + d->id + "\": " + e.what());
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
                         (names.empty() ? " (it has no changeable parameters)" : " (changeable: " + join(names) + ")"));
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

}  // namespace geovis::scene_build
