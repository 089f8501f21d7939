// The description of a camera type (core/type_registry.h): each camera's .cpp file registers one
// CameraType with its keys and defaults (GeoViS's, Parser/parse_camera.cpp: dir #(-1 0 0),
// vup #(0 0 1), fov #(60 48) degrees, res #(720 576)) and its factory. make_camera
// (camera_factory.h) adds the keys every camera has and builds it.
#pragma once

#include <memory>
#include <vector>

#include "core/param_reader.h"
#include "core/type_registry.h"
#include "render/camera.h"

namespace geovis {

struct CameraType : TypeDescription {
  /// The camera at resolution width x height from its keys (absent keys read as their defaults).
  /// Constructors report bad values as ParameterError naming the key.
  std::shared_ptr<Camera> (*make)(const ParamReader& keys, int width, int height) = nullptr;
};
using CameraRegistry = TypeRegistry<CameraType>;

/// `res` with the given default resolution (GeoViS: #(720 576); 2PICam #(100 100)).
ParamSpec camera_resolution_key(double width, double height);
/// dir, vup, fov: the view of the pinhole-like cameras (PinHoleCam, PinHoleStereoCam, PanoramaCam);
/// `fov_range` is the camera's (a pinhole's (0, 180), a panorama's (0, 360]).
std::vector<ParamSpec> camera_view_keys(ParamRange fov_range);
/// type, id, filter, param: the keys every camera has.
std::vector<ParamSpec> camera_common_keys();

}  // namespace geovis
