// The scene's actions, run after the scene is read (docs/geovis-catalogue.md §1): calc-ray and
// calc-proj-ray write one light ray, gvs-print-motion a motion's points, gvs-print a definition.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "core/rotation.h"
#include "io/atomic_file.h"
#include "scene/builder.h"
#include "scene/builder_impl.h"
#include "scene/device_assembly.h"

namespace geovis {

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
    const bool below =
        std::mismatch(root.begin(), root.end(), target.begin(), target.end()).first == root.end() && target != root;
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
      const DefPtr& motion_def = Impl::resolve(*a.defs, ps, "id", Kind::Motion, a.seq);
      with_metric(motion_def->ps.has("metric")
                      ? &Impl::resolve(*a.defs, motion_def->ps, "metric", Kind::Metric, motion_def->seq)
                      : Impl::last_of(*a.defs, Kind::Metric, motion_def->seq));
      const MotionPtr mo = b.motion_of(motion_def);
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
      const DefPtr& raygen_def = Impl::resolve(*a.defs, ps, "raygen", Kind::RayGen, a.seq);
      with_metric(Impl::last_of(*a.defs, Kind::Metric, a.seq));
      SolverConfig cfg = b.raygen_config(raygen_def);
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
        const DefPtr& tetrad_def = Impl::resolve(*a.defs, ps, "locted", Kind::Tetrad, a.seq);
        const LocalTetrad t = b.tetrad_of(tetrad_def);
        e = t.e;
        const auto pos = ps.get_vector_any("pos", {4, 5}, std::vector<double>{t.pos[0], t.pos[1], t.pos[2], t.pos[3]});
        start = Vec4{{pos[0], pos[1], pos[2], pos[3]}};
        // dir = (ξ, χ) in degrees: local direction (sinχ cosξ, sinχ sinξ, cosχ), past-directed
        // (GeoViS calc-ray).
        const auto dir = ps.get_vector("dir", 2, std::vector<double>{0, 0});
        const double ksi = dir[0] * kDegToRad, chi = dir[1] * kDegToRad;
        const Vec4 loc{{-1.0, std::sin(chi) * std::cos(ksi), std::sin(chi) * std::sin(ksi), std::cos(chi)}};
        k = local_to_coord(e, loc);
      }
      if (!m.is_valid(start))
        ps.fail(proj_ray ? "projector" : "pos", "the start point " + fmt_vec(start.c, 4) +
                                                    " is outside the validity domain of the " + m.name() + " metric");
      const bool cartesian = proj_ray && ps.get_bool("cartesian", false);
      double J[3][3];
      if (cartesian && !m.pseudo_cartesian_jacobian(start, J))
        ps.fail("cartesian",
                std::string("Cartesian output needs Cartesian, spherical or cylindrical coordinates; the ") + m.name() +
                    " metric uses " + coord_type_name(m.info().coord_type) + " coordinates");
      // Points and vectors in the metric's pseudo-Cartesian coordinates (time unchanged).
      auto to_cartesian_vector = [&J](const Vec4& v) {
        Vec4 out{{v[0], 0, 0, 0}};
        for (int i = 0; i < 3; ++i) out[i + 1] = J[i][0] * v[1] + J[i][1] * v[2] + J[i][2] * v[3];
        return out;
      };
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
          Vec3 p;
          m.to_pseudo_cartesian(x, p);
          px = Vec4{{x[0], p.x, p.y, p.z}};
          m.pseudo_cartesian_jacobian(x, J);
          pk = to_cartesian_vector(kv);
          for (auto& bv : base) bv = to_cartesian_vector(bv);
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
