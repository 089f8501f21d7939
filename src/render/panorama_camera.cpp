// Panorama mapping, paper eq. (5) as implemented in GeoViS GvsPanoramaCam::GetRayDir:
//   λ = (sx − 1/2) fov_h,   φ = arcsin(1/2 − sy) · fov_v   (sic: GeoViS multiplies the arcsine
//   by the vertical field of view, so the vertical extent is ±arcsin(1/2)·fov_v),
//   d = cos φ cos λ f̂ + cos φ sin λ ĥ + sin φ v̂,
// sx = px/W, sy = py/H, frame as the pinhole camera (ĥ = dir × vup, v̂ = ĥ × dir).
#include "render/panorama_camera.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "render/camera_type.h"

namespace geovis {

PanoramaCamera::PanoramaCamera(const Vec3& dir, const Vec3& vup, double fov_h_deg, double fov_v_deg, int width,
                               int height)
    : Camera(width, height),
      dir_(dir),
      vup_(vup),
      fov_h_rad_(fov_h_deg * std::numbers::pi / 180.0),
      fov_v_rad_(fov_v_deg * std::numbers::pi / 180.0) {
  Camera::set_resolution(width, height);
  if (!(fov_h_deg > 0 && fov_h_deg <= 360) || !(fov_v_deg > 0 && fov_v_deg <= 360))
    throw ParameterError("PanoramaCam", "fov",
                         "expected two angles in (0, 360] degrees, found #(" + std::to_string(fov_h_deg) + " " +
                             std::to_string(fov_v_deg) + ")");
  frame_ = CameraFrame::from(dir_, vup_, type_name());
}

bool PanoramaCamera::direction(double px, double py, Vec3& d) const {
  const double sx = px / width_, sy = py / height_;
  const double lambda = (sx - 0.5) * fov_h_rad_;
  const double phi = std::asin(0.5 - sy) * fov_v_rad_;
  const double cp = std::cos(phi);
  d = normalize((cp * std::cos(lambda)) * frame_.fwd + (cp * std::sin(lambda)) * frame_.horiz +
                std::sin(phi) * frame_.vert);
  return true;
}

void PanoramaCamera::set_param(std::string_view name, const Value& value) {
  const std::string n = to_lower(name);
  if (n != "dir" && n != "vup") unknown_param(name);
  const auto v = value_as_vector(value, 3, type_name(), n);
  const Vec3 nv{v[0], v[1], v[2]};
  const CameraFrame f =
      n == "dir" ? CameraFrame::from(nv, vup_, type_name()) : CameraFrame::from(dir_, nv, type_name());
  (n == "dir" ? dir_ : vup_) = nv;
  frame_ = f;
}

namespace {
// GeoViS PanoramaCam (docs/geovis-catalogue.md §2).
const TypeRegistrar<CameraType> panorama_camera_registrar{
    {{"PanoramaCam",
      {},
      "panorama camera: cylindrical mapping of longitude and latitude around dir",
      [] {
        auto keys = camera_view_keys(ParamRange{0, 360, true, false});
        keys.insert(keys.begin(), camera_resolution_key(720, 576));
        return keys;
      }()},
     [](const ParamReader& keys, int width, int height) -> std::shared_ptr<Camera> {
       const auto fov = keys.vector("fov", 2), dir = keys.vector("dir", 3), vup = keys.vector("vup", 3);
       return std::make_shared<PanoramaCamera>(Vec3{dir[0], dir[1], dir[2]}, Vec3{vup[0], vup[1], vup[2]}, fov[0],
                                               fov[1], width, height);
     }}};
}  // namespace

}  // namespace geovis
