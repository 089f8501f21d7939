#include "render/data_exr.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/hash.h"
#include "core/number_text.h"
#include "render/camera.h"
#include "render/data_files.h"
#include "spacetime/metric.h"

namespace geovis {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::string vec(const double* v, int n) {
  // Appended piecewise: GCC 12 reports a false -Wrestrict on `"..." + std::string` chains.
  std::string s;
  for (int i = 0; i < n; ++i) {
    if (i) s.push_back(' ');
    s.append(exact_number_text(v[i]));
  }
  return s;
}

/// Full angle in degrees between the camera rays through image points (x0, y0) and (x1, y1);
/// NaN where the camera has no ray there.
double view_angle(const Camera& cam, double x0, double y0, double x1, double y1) {
  Vec3 a, b;
  if (!cam.direction(x0, y0, a) || !cam.direction(x1, y1, b)) return std::nan("");
  const double c = dot(normalize(a), normalize(b));
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

std::vector<std::pair<std::string, std::string>> header(const RenderJob& job, const DataFileInfo& info) {
  std::vector<std::pair<std::string, std::string>> h;
  auto add = [&h](const std::string& k, const std::string& v) { h.emplace_back("geovis:" + k, v); };
  add("format", "geovis data 1");
  add("version", info.version);
  add("scene.file", info.scene_file);
  add("scene.path", info.scene_path);
  add("scene.hash", info.scene_hash);
  add("scene.defines", info.defines);
  add("frame", std::to_string(info.frame));
  const Metric& m = *job.metric;
  add("metric", m.name());
  add("metric.coords",
      m.info().coords[0] + " " + m.info().coords[1] + " " + m.info().coords[2] + " " + m.info().coords[3]);
  add("metric.coordtype", coord_type_name(m.info().coord_type));
  for (size_t i = 0; i < m.info().params.size(); ++i)
    add("metric." + m.info().params[i].name, exact_number_text(m.param_values()[i]));
  add("observer.pos", vec(job.observer.pos.c, 4));
  add("observer.time", exact_number_text(job.observer.pos[0]));
  for (int a = 0; a < 4; ++a) add("observer.e" + std::to_string(a), vec(job.observer.e[a].c, 4));
  const Camera& cam = *job.camera;
  const int W = cam.width(), H = cam.height();
  add("camera", cam.type_name());
  add("camera.resolution", std::to_string(W) + " " + std::to_string(H));
  // Measured between the outer pixel edges through the image centre (every camera type).
  add("camera.fov", exact_number_text(view_angle(cam, 0, 0.5 * H, W, 0.5 * H)) + " " +
                        exact_number_text(view_angle(cam, 0.5 * W, 0, 0.5 * W, H)));
  add("camera.filter", std::to_string(int(job.filter)));
  add("supersample", std::to_string(job.supersample));
  const SolverConfig& s = job.solver;
  add("solver", solver_kind_name(s.kind));
  add("solver.eps_abs", exact_number_text(s.eps_abs));
  add("solver.eps_rel", exact_number_text(s.eps_rel));
  add("solver.step_ctrl", s.step_ctrl ? "1" : "0");
  add("solver.step_size", exact_number_text(s.step_size));
  add("solver.step_min", exact_number_text(s.step_min));
  add("solver.step_max", exact_number_text(s.step_max));
  add("solver.max_steps", std::to_string(s.max_steps));
  add("solver.lambda_max", exact_number_text(s.lambda_max));
  add("solver.constraint_tol", exact_number_text(s.constraint_tol));
  add("solver.box_ll", vec(s.box_ll.c, 4));
  add("solver.box_ur", vec(s.box_ur.c, 4));
  add("horizon_eps", exact_number_text(m.horizon_eps()));
  std::string stops;
  for (int i = 0; i < kRayStopCount; ++i) {
    if (i) stops.push_back(' ');
    stops.append(std::to_string(i)).append("=").append(ray_stop_name(RayStop(i)));
  }
  add("stop.codes", stops);
  return h;
}

Filter filter_of_extension(const std::string& ext) {
  if (ext == ".pdz") return Filter::RGBpdz;
  if (ext == ".jac") return Filter::RGBjac;
  if (ext == ".pt") return Filter::RGBpt;
  if (ext == ".dat") return Filter::RGBIntersec;
  return Filter::RGB;
}

/// A GeoViS data file as channels (names as in the EXR data file).
ChannelImage from_geovis_file(const std::string& path, Filter f) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error("cannot read \"" + path +
                "\": " + (std::filesystem::exists(path) ? "permission denied" : "no such file"));
  std::stringstream ss;
  ss << in.rdbuf();
  int W = 0, H = 0;
  std::vector<PixelData> data;
  try {
    data = decode_filter_data(f, ss.str(), W, H);
  } catch (const Error& e) {
    throw Error("\"" + path + "\" is not a GeoViS " + filter_data_extension(f) + " data file: " + e.what());
  }
  ChannelImage img;
  img.width = W;
  img.height = H;
  img.names = {"x0", "x1", "x2", "x3"};
  const bool has_dir = f != Filter::RGBpt, has_uv = f == Filter::RGBpt || f == Filter::RGBIntersec,
             has_jac = f == Filter::RGBjac || f == Filter::RGBIntersec;
  if (has_dir) img.names.insert(img.names.end(), {"k0", "k1", "k2", "k3", "z"});
  img.names.push_back("objid");
  if (has_uv) img.names.insert(img.names.end(), {"u", "v"});
  if (has_jac) img.names.insert(img.names.end(), {"jac.dplus", "jac.dminus", "jac.mu", "jac.angle", "jac.ellipticity"});
  img.metadata = {{"geovis:format", std::string("GeoViS ") + filter_data_extension(f)}};
  const size_t nc = img.names.size();
  img.pixels.assign(size_t(W) * H * nc, kNaN);
  for (size_t i = 0; i < data.size(); ++i) {
    const PixelData& p = data[i];
    // GeoViS stores a zero record where nothing was hit (objID 0 = no object).
    const bool hit = f == Filter::RGBIntersec ? (p.pos[0] != 0 || p.pos[1] != 0 || p.pos[2] != 0 || p.pos[3] != 0 ||
                                                 p.uv[0] != 0 || p.uv[1] != 0)
                                              : p.object_id != 0;
    if (!hit) continue;
    float* o = &img.pixels[i * nc];
    size_t n = 0;
    for (double v : p.pos) o[n++] = float(v);
    if (has_dir) {
      for (double v : p.dir) o[n++] = float(v);
      o[n++] = p.freqshift != 0 ? float(p.freqshift) : kNaN;
    }
    o[n++] = float(p.object_id);
    if (has_uv) {
      o[n++] = float(p.uv[0]);
      o[n++] = float(p.uv[1]);
    }
    if (has_jac)
      for (double v : p.jacobi) o[n++] = float(v);
  }
  return img;
}

}  // namespace

const char* ray_stop_name(RayStop s) {
  switch (s) {
    case RayStop::Hit: return "hit";
    case RayStop::Escaped: return "escaped";
    case RayStop::Horizon: return "horizon";
    case RayStop::Box: return "box";
    case RayStop::MaxSteps: return "max-steps";
    case RayStop::Constraint: return "constraint";
    case RayStop::Error: return "error";
    case RayStop::NoRay: return "no-ray";
  }
  return "error";
}

RayStop ray_stop(const PixelData& d) {
  if (!d.traced) return RayStop::NoRay;
  if (d.hit) return RayStop::Hit;
  switch (d.stop) {
    case StopReason::Escaped: return RayStop::Escaped;  // left every object's bound for good
    case StopReason::Invalid: return RayStop::Horizon;  // the metric's break condition
    case StopReason::BoundingBox: return RayStop::Box;
    case StopReason::MaxSteps:
    case StopReason::LambdaMax: return RayStop::MaxSteps;
    case StopReason::Constraint: return RayStop::Constraint;
    case StopReason::None:
    case StopReason::Callback:
    case StopReason::StepUnderflow:
    case StopReason::NotFinite: break;
  }
  return RayStop::Error;
}

std::string fnv1a_hex(const std::string& text) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(fnv1a64(text.data(), text.size())));
  return buf;
}

std::vector<std::string> data_channel_names(bool jacobi) {
  std::vector<std::string> n = {"R",  "G",  "B", "x0",    "x1",   "x2",     "x3", "k0", "k1",
                                "k2", "k3", "z", "objid", "stop", "lambda", "u",  "v"};
  if (jacobi)
    n.insert(n.end(), {"jac.dplus", "jac.dminus", "jac.mu", "jac.angle", "jac.ellipticity", "jac.J11", "jac.J12",
                       "jac.J21", "jac.J22"});
  return n;
}

ChannelImage make_data_image(const RenderJob& job, const Image& rgb, const std::vector<PixelData>& data,
                             const DataFileInfo& info) {
  if (!job.metric || !job.camera) throw Error("data file: the job has no metric or camera");
  const size_t n = size_t(rgb.width) * rgb.height;
  if (rgb.channels != 3 || data.size() != n)
    throw Error("data file: expected " + std::to_string(n) + " pixel records, found " + std::to_string(data.size()));
  const bool jac = job.filter == Filter::RGBjac;
  ChannelImage img;
  img.width = rgb.width;
  img.height = rgb.height;
  img.names = data_channel_names(jac);
  img.metadata = header(job, info);
  const size_t nc = img.names.size();
  img.pixels.assign(n * nc, kNaN);
  for (size_t i = 0; i < n; ++i) {
    const PixelData& p = data[i];
    float* o = &img.pixels[i * nc];
    for (int c = 0; c < 3; ++c) o[c] = rgb.pixels[i * 3 + c];
    o[13] = float(int(ray_stop(p)));
    o[14] = p.traced ? float(p.lambda) : kNaN;
    if (!p.hit) continue;  // hit channels stay NaN
    for (int k = 0; k < 4; ++k) {
      o[3 + k] = float(p.pos[k]);
      o[7 + k] = float(p.dir[k]);
    }
    o[11] = p.freqshift != 0 ? float(p.freqshift) : kNaN;  // 0 = no emitter velocity known there
    o[12] = float(p.object_id);
    o[15] = float(p.uv[0]);
    o[16] = float(p.uv[1]);
    if (jac) {
      for (int k = 0; k < 5; ++k) o[17 + k] = float(p.jacobi[k]);
      for (int k = 0; k < 4; ++k) o[22 + k] = float(p.jacobi_matrix[k]);
    }
  }
  return img;
}

std::string data_exr_path(const std::string& image_path) {
  std::filesystem::path p(image_path);
  const bool is_exr = to_lower(p.extension().string()) == ".exr";
  p.replace_extension(is_exr ? ".data.exr" : ".exr");
  return p.string();
}

std::string write_data_exr(const std::string& image_path, const RenderJob& job, const Image& rgb,
                           const std::vector<PixelData>& data, const DataFileInfo& info) {
  const std::string path = data_exr_path(image_path);
  write_channel_image(path, make_data_image(job, rgb, data, info));
  return path;
}

ChannelImage read_data_file(const std::string& path) {
  const std::string ext = to_lower(std::filesystem::path(path).extension().string());
  const Filter f = filter_of_extension(ext);
  if (f != Filter::RGB) return from_geovis_file(path, f);
  if (ext != ".exr")
    throw Error("\"" + path +
                "\" is not a data file: expected an OpenEXR data file (.exr, written by geovis render "
                "--data or a data filter) or a GeoViS .pdz, .jac, .pt or .dat file");
  ChannelImage img = read_channel_image(path);
  if (img.meta("geovis:format").rfind("geovis data", 0) != 0 || img.channel("x1") < 0)
    throw Error("\"" + path +
                "\" is an OpenEXR image but not a geovis data file (no geovis:format header or no "
                "hit channels); render with --data or a data filter to make one");
  return img;
}

}  // namespace geovis
