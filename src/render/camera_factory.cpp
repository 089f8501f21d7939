// init-camera: the camera types register themselves beside their classes (render/camera_type.h);
// this file adds the keys every camera has and the filters (render/filter_type.h).
#include "render/camera_factory.h"

#include "core/error.h"
#include "render/camera_type.h"
#include "render/filter_type.h"

namespace geovis {

const std::vector<std::string>& camera_type_names() {
  static const std::vector<std::string> names = CameraRegistry::instance().names();
  return names;
}

const std::vector<std::string>& filter_names() {
  static const std::vector<std::string> names = FilterRegistry::instance().names();
  return names;
}

const char* filter_name(Filter f) {
  for (const FilterType* t : FilterRegistry::instance().entries())
    if (t->filter == f) return t->name.c_str();
  return "?";
}

Filter parse_filter(const std::string& name) { return FilterRegistry::instance().get(name, "camera filter").filter; }

namespace {

std::vector<ParamSpec> keys_of(const CameraType& type) {
  std::vector<ParamSpec> keys = camera_common_keys();
  keys.insert(keys.end(), type.keys.begin(), type.keys.end());
  return keys;
}

}  // namespace

std::vector<ParamSpec> camera_param_specs(const std::string& type) {
  return keys_of(CameraRegistry::instance().get(type, "camera type"));
}

std::shared_ptr<Camera> make_camera(const ParamSet& ps, BuildContext& ctx) {
  const CameraType& type = CameraRegistry::instance().get(ps, "type", ps.get_string("type"), "camera type");
  const std::vector<ParamSpec> specs = keys_of(type);
  Diagnostics fallback;
  ps.validate(specs, ctx.diag ? *ctx.diag : fallback);
  const ParamReader keys(ps, specs);

  const auto res = keys.vector("res", 2);
  for (double r : res)
    if (r != double(long(r)))
      ps.fail("res",
              "expected two positive integers, found #(" + std::to_string(res[0]) + " " + std::to_string(res[1]) + ")");
  std::shared_ptr<Camera> cam;
  try {
    cam = type.make(keys, int(res[0]), int(res[1]));
  } catch (const ParameterError& e) {
    // The camera names the key; the scene gives the location.
    throw SceneError(ps.loc(), ps.command(), e.key(), e.message());
  }
  cam->filter = FilterRegistry::instance().get(ps, "filter", keys.string("filter"), "camera filter").filter;
  cam->param = keys.number("param");
  return cam;
}

void override_camera_resolution(Camera& cam, int width, int height) { cam.set_resolution(width, height); }

}  // namespace geovis
