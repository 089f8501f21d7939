#include "render/stereo_camera.h"

#include <cmath>

#include "core/error.h"
#include "render/camera_type.h"

namespace geovis {

PinholeStereoCamera::PinholeStereoCamera(const Vec3& dir, const Vec3& vup, double fov_h_deg, double fov_v_deg,
                                         int width, int height, double eye_separation)
    : PinholeCamera(dir, vup, fov_h_deg, fov_v_deg, width, height), sep_(eye_separation) {
  if (!(sep_ >= 0) || !std::isfinite(sep_))
    throw ParameterError("PinHoleStereoCam", "sep", "expected a non-negative number, found " + std::to_string(sep_));
}

void PinholeStereoCamera::set_param(std::string_view name, const Value& value) {
  if (to_lower(name) == "eyesep") {
    const double s = value_as_number(value, "PinHoleStereoCam", "eyesep");
    if (!(s >= 0) || !std::isfinite(s))
      throw ParameterError("PinHoleStereoCam", "eyesep", "expected a non-negative number, found " + value.describe());
    sep_ = s;
    return;
  }
  PinholeCamera::set_param(name, value);
}

Vec3 PinholeStereoCamera::eye_offset(Eye eye) const {
  // GeoViS places the eyes at ∓sep/2 times its horizontal half-vector |dir| tan(fov_h/2) ĥ; we use
  // the unit horizontal axis so that `sep` is the actual eye separation.
  switch (eye) {
    case Eye::Left: return (-0.5 * sep_) * frame_.horiz;
    case Eye::Right: return (0.5 * sep_) * frame_.horiz;
    default: return {0, 0, 0};
  }
}

namespace {
// GeoViS PinHoleStereoCam (docs/geovis-catalogue.md §2): two images, eyes at -+sep/2.
const TypeRegistrar<CameraType> stereo_camera_registrar{
    {{"PinHoleStereoCam",
      {},
      "two pinhole cameras (left and right eye), one image each",
      [] {
        auto keys = camera_view_keys(ParamRange{0, 180, true, true});
        keys.insert(keys.begin(), camera_resolution_key(720, 576));
        keys.push_back({"sep", ParamType::Number, "eye separation (per-frame change: eyesep)", false, false, 0.1,
                        ParamRange::non_negative()});
        return keys;
      }()},
     [](const ParamReader& keys, int width, int height) -> std::shared_ptr<Camera> {
       const auto fov = keys.vector("fov", 2), dir = keys.vector("dir", 3), vup = keys.vector("vup", 3);
       return std::make_shared<PinholeStereoCamera>(Vec3{dir[0], dir[1], dir[2]}, Vec3{vup[0], vup[1], vup[2]}, fov[0],
                                                    fov[1], width, height, keys.number("sep"));
     }}};
}  // namespace

}  // namespace geovis
