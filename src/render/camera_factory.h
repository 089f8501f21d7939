// Builds cameras from `init-camera` parameter sets (docs/geovis-catalogue.md §1/§2). The camera
// types and their keys come from the CameraRegistry (render/camera_type.h; each camera's .cpp
// registers itself), the filters from the FilterRegistry (render/filter_type.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/params.h"
#include "render/build_context.h"
#include "render/camera.h"

namespace geovis {

/// The registered camera types (GeoViS: PinHoleCam, PinHoleStereoCam, PanoramaCam, 4PICam, 2PICam), sorted.
const std::vector<std::string>& camera_type_names();

/// Keys `init-camera` accepts for the given camera type (type, id, res, filter, param and the
/// type's own keys). Unknown type -> Error with the closest valid name.
std::vector<ParamSpec> camera_param_specs(const std::string& type);

/// The registered filter names (FilterRGB, FilterRGBpdz, FilterRGBjac, FilterRGBpt, FilterIntersec;
/// the alias FilterRGBIntersec is accepted too), sorted.
const std::vector<std::string>& filter_names();
const char* filter_name(Filter f);
/// Unknown name -> Error with the closest valid one.
Filter parse_filter(const std::string& name);

/// Creates the camera of an `init-camera` call. Unknown keys are warnings (errors under --strict)
/// naming the closest valid key; an unknown type, a bad value or a missing `type` is a SceneError
/// "file:line: init-camera: key: ...".
std::shared_ptr<Camera> make_camera(const ParamSet& ps, BuildContext& ctx);

/// The --res override: a new resolution with the same field of view (2PICam stays square).
void override_camera_resolution(Camera& cam, int width, int height);

}  // namespace geovis
