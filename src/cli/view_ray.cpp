#include "cli/view_ray.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/scene_options.h"
#include "core/error.h"
#include "core/number_text.h"
#include "render/camera.h"
#include "render/compound.h"
#include "render/data_exr.h"
#include "render/ray_path.h"
#include "scene/default_scene.h"
#include "scene/scheme.h"
#include "spacetime/horizon.h"

namespace geovis::cli {

namespace fs = std::filesystem;

struct PixelRayTracer::Loaded {
  std::unique_ptr<Diagnostics> diag;  ///< the builder reports warnings here while it builds frames
  std::unique_ptr<SceneBuilder> builder;
  std::string scene_label;
  /// SceneBuilder::build caches what it built (motions): one request builds at a time.
  mutable std::mutex build_mutex;
};

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read the scene \"" + path + "\"");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

nlohmann::json vec4(const Vec4& v) { return {v[0], v[1], v[2], v[3]}; }
nlohmann::json vec3(const Vec3& v) { return {v.x, v.y, v.z}; }

/// Bounds of the primitives (compounds are opened), pseudo-Cartesian; unbounded ones are left out.
void collect_outlines(const SceneObject& o, nlohmann::json& out) {
  if (const auto* c = dynamic_cast<const CompoundObject*>(&o)) {
    for (const auto& child : c->children())
      if (child) collect_outlines(*child, out);
    return;
  }
  const Bounds3 b = o.bounds();
  if (b.empty() || !std::isfinite(b.lo.x) || !std::isfinite(b.lo.y) || !std::isfinite(b.lo.z) ||
      !std::isfinite(b.hi.x) || !std::isfinite(b.hi.y) || !std::isfinite(b.hi.z))
    return;
  out.push_back({{"id", o.id}, {"chart", o.chart}, {"lo", vec3(b.lo)}, {"hi", vec3(b.hi)}});
}

}  // namespace

std::vector<std::string> split_defines(const std::string& defines) {
  std::vector<std::string> out;
  std::stringstream ss(defines);
  std::string word;
  while (ss >> word) {
    if (word.find('=') == std::string::npos && !out.empty())
      out.back() += " " + word;
    else
      out.push_back(word);
  }
  return out;
}

PixelRayTracer::PixelRayTracer(std::string scene_override) : scene_override_(std::move(scene_override)) {}

std::shared_ptr<const PixelRayTracer::Loaded> PixelRayTracer::load(const ChannelImage& data,
                                                                   const std::string& data_path) {
  const std::string hash = data.meta("geovis:scene.hash");
  if (hash.empty())
    throw Error("\"" + data_path +
                "\" names no scene (a GeoViS data file has no header): its rays cannot be traced "
                "again; use the OpenEXR data file of geovis render --data");
  const std::string file = data.meta("geovis:scene.file"), path = data.meta("geovis:scene.path");
  const std::string defines = data.meta("geovis:scene.defines"), res = data.meta("geovis:camera.resolution");
  const std::string key = hash + "\n" + defines + "\n" + res + "\n" + scene_override_;
  std::lock_guard<std::mutex> lock(mutex_);
  if (auto it = cache_.find(key); it != cache_.end()) return it->second;

  // The scene text: the built-in scene, or the file found where the header says.
  std::string scene_path, text;
  if (!scene_override_.empty()) {
    scene_path = scene_override_;
  } else if (!file.empty()) {
    std::vector<std::string> tried;
    if (!path.empty()) tried.push_back(path);
    tried.push_back((fs::path(data_path).parent_path() / file).string());
    tried.push_back(file);
    for (const auto& t : tried) {
      std::error_code ec;
      if (fs::is_regular_file(t, ec)) {
        scene_path = t;
        break;
      }
    }
    if (scene_path.empty()) {
      std::string list;
      for (const auto& t : tried) list += (list.empty() ? "\"" : ", \"") + t + "\"";
      throw Error("the scene \"" + file + "\" of \"" + data_path + "\" is not found (looked at " + list +
                  "); give it with --scene FILE");
    }
  }
  text = scene_path.empty() ? default_scene_text() : read_text(scene_path);
  const std::string label = scene_path.empty() ? "the built-in scene" : "\"" + scene_path + "\"";
  if (fnv1a_hex(text) != hash)
    throw Error("the scene " + label + " changed since \"" + data_path + "\" was rendered (its hash is " +
                fnv1a_hex(text) + ", the data file's " + hash +
                "): the ray would not be the pixel's; render the data file again or give the original with --scene");

  SceneArgs args;
  args.defines = split_defines(defines);
  auto loaded = std::make_shared<Loaded>();
  loaded->diag = std::make_unique<Diagnostics>();
  loaded->scene_label = label;
  const SchemeOptions sopts = scheme_options(args, loaded->diag.get(), true);
  SceneDescription scene = scene_path.empty() ? evaluate_scene_string(text, default_scene_name() + ".scm", sopts)
                                              : evaluate_scene_file(scene_path, sopts);
  BuildOptions bopts;
  const std::string dir = scene_path.empty() ? std::string() : fs::path(scene_path).parent_path().string();
  bopts.search_paths.push_back(dir.empty() ? "." : dir);
  bopts.search_paths.push_back(".");
  bopts.diag = loaded->diag.get();
  bopts.write_action_files = false;  // the viewer writes no file of the scene's actions
  int w = 0, h = 0;
  if (std::sscanf(res.c_str(), "%d %d", &w, &h) == 2 && w > 0 && h > 0) bopts.resolution = std::pair{w, h};
  loaded->builder = std::make_unique<SceneBuilder>(std::move(scene), bopts);
  cache_[key] = loaded;
  return loaded;
}

nlohmann::json PixelRayTracer::trace(const ChannelImage& data, const std::string& data_path, int x, int y) {
  if (x < 0 || y < 0 || x >= data.width || y >= data.height)
    throw Error("pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                std::to_string(data.width) + "x" + std::to_string(data.height) + " image");
  const std::shared_ptr<const Loaded> loaded = load(data, data_path);
  const std::string frame_text = data.meta("geovis:frame");
  const int frame = frame_text.empty() ? 0 : std::stoi(frame_text);
  if (frame < 0 || frame >= loaded->builder->device_count())
    throw Error("frame " + std::to_string(frame) + " of \"" + data_path + "\" is not in the scene (it has " +
                std::to_string(loaded->builder->device_count()) + " frames)");
  std::vector<FrameJob> jobs;
  {
    std::lock_guard<std::mutex> lock(loaded->build_mutex);
    jobs = loaded->builder->build(frame);
  }
  const RenderJob& job = jobs.front().job;  // a stereo pair: the left eye
  if (job.camera->width() != data.width || job.camera->height() != data.height)
    throw Error("the scene's camera has " + std::to_string(job.camera->width()) + "x" +
                std::to_string(job.camera->height()) + " pixels, the data file " + std::to_string(data.width) + "x" +
                std::to_string(data.height));

  const RayPath path = trace_ray_path(job, x + 0.5, y + 0.5);
  const Metric& m = *job.metric;
  nlohmann::json j;
  j["frame"] = frame;
  j["pixel"] = {x, y};
  j["scene"] = loaded->scene_label;
  j["metric"] = m.name();
  j["coords"] = m.info().coords;
  nlohmann::json params = nlohmann::json::object();
  for (size_t i = 0; i < m.info().params.size(); ++i) params[m.info().params[i].name] = m.param_values()[i];
  j["params"] = params;
  j["traced"] = path.traced;
  Vec3 obs_p;
  m.to_pseudo_cartesian(job.observer.pos, obs_p);
  j["observer"] = {{"x", vec4(job.observer.pos)}, {"p", vec3(obs_p)}};
  if (const auto s = central_surface(m))
    j["surface"] = {{"kind", s->kind}, {"radius", s->radius}, {"formula", s->formula}};
  else
    j["surface"] = nullptr;
  nlohmann::json outlines = nlohmann::json::array();
  if (job.scene) collect_outlines(*job.scene, outlines);
  j["objects"] = outlines;
  if (!path.traced) return j;

  nlohmann::json pts = nlohmann::json::array();
  for (const RayPoint& p : path.points)
    pts.push_back({{"lambda", p.lambda}, {"x", vec4(p.x)}, {"k", vec4(p.k)}, {"p", vec3(p.p)}, {"chart", p.chart}});
  j["points"] = pts;
  const TraceResult& r = path.result;
  j["stop"] = r.hit ? "hit" : stop_reason_name(r.reason);
  j["hit"] = r.hit;
  if (r.hit) j["object_id"] = r.hit_info.object_id;
  j["lambda"] = r.lambda;
  j["local_dir"] = vec3(path.local_dir);

  // The same ray with `geovis geodesic` (which starts in the natural tetrad, backwards in time).
  const SolverConfig& s = job.solver;
  std::string cmd = "geovis geodesic --metric " + m.name();
  for (size_t i = 0; i < m.info().params.size(); ++i)
    cmd += " --param " + m.info().params[i].name + "=" + exact_number_text(m.param_values()[i]);
  cmd += " --pos " + exact_number_text(job.observer.pos[0]) + "," + exact_number_text(job.observer.pos[1]) + "," +
         exact_number_text(job.observer.pos[2]) + "," + exact_number_text(job.observer.pos[3]);
  cmd += " --dir " + exact_number_text(path.natural_dir.x) + "," + exact_number_text(path.natural_dir.y) + "," +
         exact_number_text(path.natural_dir.z);
  cmd += std::string(" --solver ") + solver_kind_name(s.kind) + " --eps-abs " + exact_number_text(s.eps_abs) +
         " --eps-rel " + exact_number_text(s.eps_rel) + " --max-steps " + std::to_string(s.max_steps) +
         " --equations " + (s.separable ? "separable" : "coordinate");
  if (std::isfinite(s.lambda_max)) cmd += " --lambda-max " + exact_number_text(s.lambda_max);
  cmd +=
      std::isfinite(path.escape_radius) ? " --escape-radius " + exact_number_text(path.escape_radius) : " --no-escape";
  // What `geovis geodesic` cannot express: the same steps only up to where these act.
  std::vector<std::string> differs;
  const SolverConfig d;
  if (!(std::fabs(path.natural_scale - 1) < 1e-12))
    differs.push_back("the observer moves in the natural frame: its affine parameter is " +
                      exact_number_text(path.natural_scale) + " times this one");
  // Carter's separated equations ignore a max_step the scene did not give (SolverConfig::step_max_separable).
  const bool step_max_acts = !(s.separable && m.has_separable_geodesics()) || s.step_max_separable;
  if (s.step_ctrl != d.step_ctrl || s.step_size != d.step_size || s.step_min != d.step_min ||
      (step_max_acts && s.step_max != d.step_max))
    differs.push_back("step settings (step_ctrl/step_size/step_min/step_max)");
  if (s.constraint_tol != d.constraint_tol || s.reproject != d.reproject) differs.push_back("constraint settings");
  j["geodesic"] = {{"command", cmd},
                   {"dir", vec3(path.natural_dir)},
                   {"scale", path.natural_scale},
                   {"differences", differs},
                   {"note",
                    "the tracer also stops at a hit and at the scene's bounding box; geovis geodesic runs on "
                    "(its points start the same)"}};

  // What the data file stored for this pixel, for comparison with the traced ray.
  nlohmann::json stored = nlohmann::json::object();
  const size_t nc = data.names.size(), base = (size_t(y) * data.width + x) * nc;
  for (size_t c = 0; c < nc; ++c) {
    const float v = data.pixels[base + c];
    stored[data.names[c]] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  }
  j["stored"] = stored;
  return j;
}

}  // namespace geovis::cli
