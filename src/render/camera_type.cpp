#include "render/camera_type.h"

#include "render/filter_type.h"

namespace geovis {

ParamSpec camera_resolution_key(double width, double height) {
  return {"res",
          ParamType::IntVec2,
          "resolution #(width height) in pixels",
          false,
          false,
          std::vector<double>{width, height},
          ParamRange{1, 1e6}};
}

std::vector<ParamSpec> camera_view_keys(ParamRange fov_range) {
  using T = ParamType;
  return {
      {"dir", T::Vec3, "viewing direction in the observer's local frame", false, false, std::vector<double>{-1, 0, 0}},
      {"vup", T::Vec3, "up vector in the local frame", false, false, std::vector<double>{0, 0, 1}},
      {"fov", T::Vec2, "field of view #(horizontal vertical) in degrees", false, false, std::vector<double>{60, 48},
       fov_range}};
}

std::vector<ParamSpec> camera_common_keys() {
  using T = ParamType;
  return {{"type", T::String, "camera type: " + join(CameraRegistry::instance().names()), true},
          {"id", T::String, "camera id"},
          {"filter", T::String, "what is stored besides the image: " + join(FilterRegistry::instance().names()), false,
           false, std::string("FilterRGB")},
          {"param", T::Number, "free camera parameter (stored, unused)", false, false, 0.0}};
}

}  // namespace geovis
