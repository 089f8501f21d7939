#include "render/camera.h"

#include <cmath>

#include "core/error.h"

namespace geovis {

void Camera::set_resolution(int width, int height) {
  if (width <= 0 || height <= 0)
    throw Error(std::string("camera ") + type_name() + ": resolution must be positive, found " + std::to_string(width) +
                "x" + std::to_string(height));
  width_ = width;
  height_ = height;
}

void Camera::unknown_param(std::string_view name) const {
  const auto names = param_names();
  throw Error(std::string("camera ") + type_name() + ": unknown parameter \"" + std::string(name) + "\"" +
              did_you_mean(name, names) +
              (names.empty() ? " (it has no settable parameters)" : " (settable: " + join(names) + ")"));
}

CameraFrame CameraFrame::from(const Vec3& dir, const Vec3& vup, std::string_view camera) {
  const double nd = norm(dir), nu = norm(vup);
  if (!(nd > 0) || !std::isfinite(nd))
    throw ParameterError(camera, "dir", "expected a non-zero direction, found a zero vector");
  if (!(nu > 0) || !std::isfinite(nu))
    throw ParameterError(camera, "vup", "expected a non-zero up vector, found a zero vector");
  CameraFrame f;
  f.fwd = dir / nd;
  const Vec3 h = cross(dir, vup);
  const double nh = norm(h);
  if (!(nh > 1e-12 * nd * nu))
    throw ParameterError(camera, "vup", "expected a vector not parallel to dir, found a parallel one");
  f.horiz = h / nh;
  f.vert = normalize(cross(f.horiz, f.fwd));
  return f;
}

Observer offset_observer(const Observer& obs, const Vec3& d) {
  Observer o = obs;
  for (int mu = 0; mu < 4; ++mu) o.pos[mu] += d.x * obs.e[1][mu] + d.y * obs.e[2][mu] + d.z * obs.e[3][mu];
  return o;
}

std::vector<double> value_as_vector(const Value& v, size_t n, std::string_view owner, std::string_view key) {
  if (n == 1 && v.is_number()) return {std::get<double>(v.v)};
  if (v.is_vector()) {
    const auto& d = std::get<std::vector<double>>(v.v);
    if (d.size() == n) return d;
  }
  throw ParameterError(owner, key,
                       "expected " + (n == 1 ? std::string("a number") : "a " + std::to_string(n) + "-vector") +
                           ", found " + v.describe());
}

double value_as_number(const Value& v, std::string_view owner, std::string_view key) {
  return value_as_vector(v, 1, owner, key)[0];
}

}  // namespace geovis
