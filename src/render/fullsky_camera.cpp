// Full-sky mapping, paper eq. (4) as implemented in GeoViS Gvs4PICam::GetRayDir:
//   θ = sy π,  φ = (1 − 2 sx) π + angle,  d = (sin θ cos φ, sin θ sin φ, cos θ)
// (the paper writes φ = (sx − 1/2) 2π; the code, which GeoViS scenes were made with, runs φ the
// other way so that the image is not mirrored).
#include "render/fullsky_camera.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "render/camera_type.h"

namespace geovis {

FullSkyCamera::FullSkyCamera(double angle_deg, int width, int height) : Camera(width, height), angle_deg_(angle_deg) {
  Camera::set_resolution(width, height);
  if (!std::isfinite(angle_deg)) throw ParameterError("4PICam", "angle", "expected a finite number of degrees");
}

bool FullSkyCamera::direction(double px, double py, Vec3& d) const {
  constexpr double pi = std::numbers::pi;
  const double sx = px / width_, sy = py / height_;
  const double theta = sy * pi;
  const double phi = (1.0 - 2.0 * sx) * pi + angle_deg_ * pi / 180.0;
  d = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  return true;
}

void FullSkyCamera::set_param(std::string_view name, const Value& value) {
  if (to_lower(name) != "angle") unknown_param(name);
  const double a = value_as_number(value, "4PICam", "angle");
  if (!std::isfinite(a)) throw ParameterError("4PICam", "angle", "expected a finite number, found " + value.describe());
  angle_deg_ = a;
}

namespace {
// GeoViS 4PICam (docs/geovis-catalogue.md §2).
const TypeRegistrar<CameraType> fullsky_camera_registrar{
    {{"4PICam",
      {},
      "full-sky camera: equirectangular image of all directions",
      {camera_resolution_key(720, 576),
       {"angle", ParamType::Number, "rotation about the local z axis in degrees", false, false, 0.0}}},
     [](const ParamReader& keys, int width, int height) -> std::shared_ptr<Camera> {
       return std::make_shared<FullSkyCamera>(keys.number("angle"), width, height);
     }}};
}  // namespace

}  // namespace geovis
