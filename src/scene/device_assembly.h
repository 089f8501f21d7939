// Building one device: a device's definitions (with this frame's changes) -> metric, observer,
// camera, scene objects, lights -> render jobs, reusing what the builder cached. Internal to
// src/scene/.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "render/build_context.h"
#include "render/camera.h"
#include "render/camera_factory.h"
#include "render/data_files.h"
#include "render/plugins.h"
#include "scene/builder_impl.h"
#include "scene/scene_files.h"
#include "spacetime/metric_registry.h"
#include "spacetime/tetrad.h"

namespace geovis {

/// What `geovis check` prints about a device.
struct DeviceInfo {
  std::string metric_line, observer_line, camera_line, objects_line;
};

class DeviceBuild {
 public:
  using Impl = SceneBuilder::Impl;
  DeviceBuild(const Impl& impl, const DeviceDef& dev) : impl_(impl), dev_(dev), defs_(*dev.defs) {
    for (const auto& sp : dev.setparams) impl.apply_setparam(*dev.defs, sp, dev.ps, &defs_);
    ctx_.diag = impl.opts.diag;
    ctx_.search_paths = impl.opts.search_paths;
  }

  std::vector<FrameJob> build(int device_no, DeviceInfo* info) {
    const ParamSet& device_ps = dev_.ps;
    // -- metric --
    const DefPtr& metric_def = Impl::resolve(defs_, device_ps, "metric", Kind::Metric, dev_.seq);
    metric_ = metric_of(metric_def, &metric_key_);
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
    const DefPtr& root = Impl::resolve(defs_, device_ps, "obj", Kind::Object, dev_.seq);
    job.scene = ctx_.objects.at(root->id);

    // -- light manager --
    if (device_ps.has("lightmgr") || Impl::last_of(defs_, Kind::LightMgr, dev_.seq)) {
      const DefPtr& light_mgr_def = Impl::resolve(defs_, device_ps, "lightmgr", Kind::LightMgr, dev_.seq);
      for (const auto& ref : ref_keys(Kind::LightMgr))
        for (const Param* p : light_mgr_def->ps.find_all(ref.key)) {
          if (!p->value.is_string())
            light_mgr_def->ps.fail(ref.key, "expected a string (an id), found " + p->value.describe());
          Impl::lookup(defs_, light_mgr_def->ps, ref.key, std::get<std::string>(p->value.v), ref.kind,
                       light_mgr_def->seq);
        }
      try {
        job.lights = make_light_manager(light_mgr_def->ps, ctx_);
      } catch (const std::exception& e) {
        rethrow_at(light_mgr_def->ps, "", e);
      }
    }

    // -- projector: observer, ray generator, colours --
    const DefPtr& proj = Impl::resolve(defs_, device_ps, "projector", Kind::Projector, dev_.seq);
    const ParamSet& projector_ps = proj->ps;
    const std::vector<ParamSpec> projector_specs = find_scene_command("init-projector")->keys(std::string());
    const ParamReader projector_keys(projector_ps, projector_specs);
    job.background = color3(projector_keys, "color");
    if (projector_ps.has("errcolor")) job.error_color = color3(projector_keys, "errcolor");
    if (projector_ps.has("cstrcolor")) job.constraint_color = color3(projector_keys, "cstrcolor");
    if (projector_ps.has("breakcolor")) job.break_color = color3(projector_keys, "breakcolor");
    std::string observer_kind;
    job.observer = observer_of(proj, observer_kind);
    if (!metric_->is_valid(job.observer.pos))
      projector_ps.fail(projector_ps.has("motion") ? "motion" : "localtetrad",
                        "the observer position " + fmt_vec(job.observer.pos.c, 4) +
                            " is outside the validity domain of the " + metric_->name() +
                            " metric (e.g. inside a horizon or on a coordinate singularity)");

    const DefPtr& raygen_def = Impl::resolve(defs_, projector_ps, "raygen", Kind::RayGen, proj->seq);
    job.solver = raygen_config(raygen_def);

    // -- camera --
    const DefPtr& camera_def = Impl::resolve(defs_, device_ps, "camera", Kind::Camera, dev_.seq);
    CameraPtr cam;
    try {
      cam = make_camera(camera_def->ps, ctx_);
    } catch (const std::exception& e) {
      rethrow_at(camera_def->ps, "type", e);
    }
    for (const auto& ch : camera_def->changes) {
      try {
        cam->set_param(ch.key, ch.value);
      } catch (const std::exception& e) {
        throw SceneError(ch.loc.line ? ch.loc : device_ps.loc(), device_ps.command(), "setparam",
                         "camera \"" + camera_def->id + "\": " + e.what());
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
      const DefPtr& solver_def = Impl::resolve(defs_, raygen_def->ps, "solver", Kind::Solver, raygen_def->seq);
      solver_def->ps.fail("type", std::string("RKN86 integrates only the separated geodesic equations of KerrBL and "
                                              "Schwarzschild (") +
                                      (job.filter == Filter::RGBjac ? "not the Jacobi equation of the RGBjac filter"
                                       : !job.solver.separable      ? "here switched off by 'separable #f'"
                                                                    : "this scene's metric is " + metric_->name()) +
                                      "); use DOP853");
    }

    if (info) {
      std::ostringstream m;
      m << metric_->name();
      const auto& ps = metric_->info().params;
      for (size_t i = 0; i < ps.size(); ++i)
        m << (i ? ", " : " (") << ps[i].name << " = " << metric_->param_values()[i];
      if (!ps.empty()) m << ")";
      info->metric_line = m.str();
      info->observer_line = "position " + fmt_vec(job.observer.pos.c, 4) + ", " + observer_kind;
      std::ostringstream c;
      c << cam->type_name() << " " << cam->width() << "x" << cam->height();
      if (const Param* fov = camera_def->ps.find("fov")) {
        c << ", fov ";
        put_value_readable(c, fov->value);
      }
      c << ", filter " << camera_def->ps.get_string("filter", std::string("FilterRGB"));
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

  SolverConfig raygen_config(const DefPtr& raygen_def) {
    const ParamSet& raygen_ps = raygen_def->ps;
    const std::string type = raygen_ps.get_string("type", std::string("RayGenSimple"));
    if (type != "RayGenSimple")
      raygen_ps.fail("type", "unknown ray generator \"" + type + "\"" + did_you_mean(type, {"RayGenSimple"}) +
                                 " (valid: RayGenSimple)");
    const DefPtr& solver_def = Impl::resolve(defs_, raygen_ps, "solver", Kind::Solver, raygen_def->seq);
    SolverConfig c = Impl::solver_config(solver_def->ps);
    // A solver used by a ray generator integrates light rays backwards (catalogue §1): the
    // initial tangent is past-directed (paper eq. 7), set by the tracer; λ increases.
    c.type = GeodesicType::Lightlike;
    c.direction = 1.0;
    const std::vector<ParamSpec> specs = find_scene_command("init-raygen")->keys(std::string());
    const ParamReader keys(raygen_ps, specs);
    c.max_steps = keys.integer("maxnumpoints");
    if (raygen_ps.has("boundboxll") || raygen_ps.has("boundboxur")) Impl::set_box(keys, c);
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
    const ParamSet& projector_ps = proj->ps;
    Observer obs;
    if (projector_ps.has("motion")) {
      const DefPtr& motion_def = Impl::resolve(defs_, projector_ps, "motion", Kind::Motion, proj->seq);
      const MotionPtr mo = motion_of(motion_def);
      const auto& samples = mo->samples();
      const std::vector<ParamSpec> projector_specs = find_scene_command("init-projector")->keys(std::string());
      const int n = ParamReader(projector_ps, projector_specs).integer("actualpos");
      if (n < 0 || n >= static_cast<int>(samples.size()))
        projector_ps.fail("actualpos", "point " + std::to_string(n) + " does not exist: motion \"" + motion_def->id +
                                           "\" has " + std::to_string(samples.size()) + " points (0 to " +
                                           std::to_string(samples.size() - 1) + ")");
      obs.pos = samples[n].x;
      obs.e = samples[n].e;
      kind = "moving with motion \"" + motion_def->id + "\" (point " + std::to_string(n) + " of " +
             std::to_string(samples.size()) + ", proper time " + std::to_string(samples[n].tau) + ")";
      return obs;
    }
    if (!projector_ps.has("localtetrad") && projector_ps.has("pos")) {
      // The tetrad given inline (pos has 4 or 5 components; GeoViS reads the first four).
      ParamSet tetrad_ps = projector_ps;
      tetrad_ps.set("pos", Value(std::vector<double>([&] {
                      auto v = projector_ps.get_vector_any("pos", {4, 5});
                      v.resize(4);
                      return v;
                    }())),
                    projector_ps.find("pos")->loc);
      auto d = std::make_shared<Def>(*proj);
      d->ps = tetrad_ps;
      const LocalTetrad t = tetrad_of(d);
      obs.pos = t.pos;
      obs.e = t.e;
      kind = "static tetrad given in the projector";
      return obs;
    }
    const DefPtr& tetrad_def = Impl::resolve(defs_, projector_ps, "localtetrad", Kind::Tetrad, proj->seq);
    const LocalTetrad t = tetrad_of(tetrad_def);
    obs.pos = t.pos;
    obs.e = t.e;
    kind = "static local tetrad \"" + tetrad_def->id + "\"" +
           (tetrad_def->ps.get_bool("incoords", false)
                ? " (coordinate components)"
                : std::string(" (relative to the ") +
                      tetrad_kind_name(static_cast<TetradKind>(tetrad_def->ps.get_int("localframe", 0))) +
                      " natural tetrad)");
    if (tetrad_def->ps.has("localvel"))
      kind += ", boosted by localvel " + fmt_vec(tetrad_def->ps.get_vector("localvel", 3).data(), 3);
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
        m->set_param(ch.key, value_as_number(ch.value, d.id, ch.key));
      } catch (const ParameterError& e) {
        throw SceneError(ch.loc, "setparam", ch.key, "metric \"" + d.id + "\": " + e.message());
      } catch (const std::exception& e) {
        throw SceneError(ch.loc, "setparam", ch.key, "metric \"" + d.id + "\": " + e.what());  // value out of range
      }
    }
    return std::shared_ptr<const Metric>(std::move(m));
  }

  static Color color3(const ParamReader& keys, std::string_view key) {
    const auto v = keys.vector(key, 3);
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
    std::string key = std::string(definition_kind_name(d->kind)) + ":" + serialize(d->ps, d->changes);
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
        case Kind::Light: ctx_.lights[d->id] = make_point_light(d->ps, ctx_); break;
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

}  // namespace geovis
