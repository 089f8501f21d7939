// Pinhole mapping, paper eq. (3) as implemented in GeoViS GvsPinHoleCam::GetRayDir:
//   sx = px/W, sy = py/H (pixel centres (i+.5)/W, (j+.5)/H),
//   d ∝ f̂ + (2 sx − 1) tan(fov_h/2) ĥ + (1 − 2 sy) tan(fov_v/2) v̂,
// with ĥ = dir × vup, v̂ = ĥ × dir (normalised). GeoViS's aspect ratio factor is 1 (GvsCamera sets
// aspectRatio = 1 and nothing changes it), so the horizontal extent is given by fov_h itself.
#include "render/pinhole_camera.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "render/camera_type.h"

namespace geovis {

namespace {
void check_fov(double h, double v, const char* cam) {
  if (!(h > 0 && h < 180) || !(v > 0 && v < 180))
    throw ParameterError(
        cam, "fov",
        "expected two angles in (0, 180) degrees, found #(" + std::to_string(h) + " " + std::to_string(v) + ")");
}
Vec3 to_vec3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }
}  // namespace

PinholeCamera::PinholeCamera(const Vec3& dir, const Vec3& vup, double fov_h_deg, double fov_v_deg, int width,
                             int height)
    : Camera(width, height), dir_(dir), vup_(vup), fov_h_(fov_h_deg), fov_v_(fov_v_deg) {
  Camera::set_resolution(width, height);
  install();
}

void PinholeCamera::install() {
  check_fov(fov_h_, fov_v_, type_name());
  frame_ = CameraFrame::from(dir_, vup_, type_name());
  tan_half_h_ = std::tan(fov_h_ * std::numbers::pi / 360.0);
  tan_half_v_ = std::tan(fov_v_ * std::numbers::pi / 360.0);
}

bool PinholeCamera::direction(double px, double py, Vec3& d) const {
  const double sx = px / width_, sy = py / height_;
  d = normalize(frame_.fwd + ((2.0 * sx - 1.0) * tan_half_h_) * frame_.horiz +
                ((1.0 - 2.0 * sy) * tan_half_v_) * frame_.vert);
  return true;
}

void PinholeCamera::set_param(std::string_view name, const Value& value) {
  const std::string n = to_lower(name);
  if (n == "dir") {
    const Vec3 old = dir_;
    dir_ = to_vec3(value_as_vector(value, 3, type_name(), n));
    try {
      install();
    } catch (...) {
      dir_ = old;
      install();
      throw;
    }
  } else if (n == "vup") {
    const Vec3 old = vup_;
    vup_ = to_vec3(value_as_vector(value, 3, type_name(), n));
    try {
      install();
    } catch (...) {
      vup_ = old;
      install();
      throw;
    }
  } else if (n == "fov") {
    const auto f = value_as_vector(value, 2, type_name(), n);
    check_fov(f[0], f[1], type_name());
    fov_h_ = f[0];
    fov_v_ = f[1];
    install();
  } else {
    unknown_param(name);
  }
}

namespace {
// GeoViS PinHoleCam (docs/geovis-catalogue.md §2).
const TypeRegistrar<CameraType> pinhole_camera_registrar{
    {{"PinHoleCam",
      {},
      "pinhole camera: perspective image of the viewing direction dir",
      [] {
        auto keys = camera_view_keys(ParamRange{0, 180, true, true});
        keys.insert(keys.begin(), camera_resolution_key(720, 576));
        return keys;
      }()},
     [](const ParamReader& keys, int width, int height) -> std::shared_ptr<Camera> {
       const auto fov = keys.vector("fov", 2);
       return std::make_shared<PinholeCamera>(to_vec3(keys.vector("dir", 3)), to_vec3(keys.vector("vup", 3)), fov[0],
                                              fov[1], width, height);
     }}};
}  // namespace

}  // namespace geovis
