// init-camera defaults are GeoViS's (Parser/parse_camera.cpp): dir #(-1 0 0), vup #(0 0 1),
// fov #(60 48) degrees, res #(720 576); 2PICam res #(100 100); sep 0.1; angle/heading/pitch 0.
#include "render/camera_factory.h"

#include "core/error.h"
#include "render/dome_camera.h"
#include "render/fullsky_camera.h"
#include "render/panorama_camera.h"
#include "render/pinhole_camera.h"
#include "render/stereo_camera.h"

namespace geovis {

const std::vector<std::string>& camera_type_names() {
  static const std::vector<std::string> names = {"PinHoleCam", "PinHoleStereoCam", "PanoramaCam", "4PICam", "2PICam"};
  return names;
}

const std::vector<std::string>& filter_names() {
  static const std::vector<std::string> names = {"FilterRGB", "FilterRGBpdz", "FilterRGBjac", "FilterRGBpt",
                                                 "FilterIntersec"};
  return names;
}

const char* filter_name(Filter f) {
  switch (f) {
    case Filter::RGB: return "FilterRGB";
    case Filter::RGBpdz: return "FilterRGBpdz";
    case Filter::RGBjac: return "FilterRGBjac";
    case Filter::RGBpt: return "FilterRGBpt";
    case Filter::RGBIntersec: return "FilterIntersec";
  }
  return "?";
}

Filter parse_filter(const std::string& name) {
  const auto& names = filter_names();
  for (size_t i = 0; i < names.size(); ++i)
    if (name == names[i]) return Filter(int(i));
  if (name == "FilterRGBIntersec") return Filter::RGBIntersec;
  for (size_t i = 0; i < names.size(); ++i)
    if (to_lower(name) == to_lower(names[i])) return Filter(int(i));
  throw Error("unknown camera filter \"" + name + "\"" + did_you_mean(name, names) + " (valid: " + join(names) + ")");
}

namespace {

std::string check_type(const std::string& type) {
  for (const auto& n : camera_type_names())
    if (n == type) return n;
  for (const auto& n : camera_type_names())
    if (to_lower(n) == to_lower(type)) return n;
  return {};
}

}  // namespace

std::vector<ParamSpec> camera_param_specs(const std::string& type_in) {
  const std::string type = check_type(type_in);
  if (type.empty())
    throw Error("unknown camera type \"" + type_in + "\"" + did_you_mean(type_in, camera_type_names()) +
                " (valid: " + join(camera_type_names()) + ")");
  std::vector<ParamSpec> s = {
      {"type", ParamType::String, "camera type: " + join(camera_type_names()), true},
      {"id", ParamType::String, "camera id"},
      {"res", ParamType::IntVec2, "resolution #(width height) in pixels"},
      {"filter", ParamType::String, "what is stored besides the image: " + join(filter_names())},
      {"param", ParamType::Number, "free camera parameter (stored, unused)"},
  };
  if (type == "PinHoleCam" || type == "PinHoleStereoCam" || type == "PanoramaCam") {
    s.push_back({"dir", ParamType::Vec3, "viewing direction in the observer's local frame (default #(-1 0 0))"});
    s.push_back({"vup", ParamType::Vec3, "up vector in the local frame (default #(0 0 1))"});
    s.push_back({"fov", ParamType::Vec2, "field of view #(horizontal vertical) in degrees (default #(60 48))"});
  }
  if (type == "PinHoleStereoCam") s.push_back({"sep", ParamType::Number, "eye separation (default 0.1)"});
  if (type == "4PICam") s.push_back({"angle", ParamType::Number, "rotation about the local z axis in degrees"});
  if (type == "2PICam") {
    s.push_back({"heading", ParamType::Number, "heading of the dome centre in degrees"});
    s.push_back({"pitch", ParamType::Number, "pitch of the dome centre in degrees"});
  }
  return s;
}

std::shared_ptr<Camera> make_camera(const ParamSet& ps, BuildContext& ctx) {
  const std::string type_in = ps.get_string("type");
  const std::string type = check_type(type_in);
  if (type.empty())
    ps.fail("type", "unknown camera type \"" + type_in + "\"" + did_you_mean(type_in, camera_type_names()) +
                        " (valid: " + join(camera_type_names()) + ")");
  Diagnostics fallback;
  ps.validate(camera_param_specs(type), ctx.diag ? *ctx.diag : fallback);

  const bool dome = type == "2PICam";
  const auto res = ps.get_vector("res", 2, dome ? std::vector<double>{100, 100} : std::vector<double>{720, 576});
  for (double r : res)
    if (!(r >= 1 && r <= 1e6) || r != double(long(r)))
      ps.fail("res", "expected two positive integers, found #(" + std::to_string(res[0]) + " " +
                         std::to_string(res[1]) + ")");
  const int w = int(res[0]), h = int(res[1]);

  auto vec3 = [&](const char* key, std::vector<double> def) {
    const auto v = ps.get_vector(key, 3, def);
    return Vec3{v[0], v[1], v[2]};
  };

  std::shared_ptr<Camera> cam;
  try {
    if (type == "PinHoleCam" || type == "PinHoleStereoCam" || type == "PanoramaCam") {
      const Vec3 dir = vec3("dir", {-1, 0, 0}), vup = vec3("vup", {0, 0, 1});
      const auto fov = ps.get_vector("fov", 2, std::vector<double>{60, 48});
      if (type == "PinHoleCam")
        cam = std::make_shared<PinholeCamera>(dir, vup, fov[0], fov[1], w, h);
      else if (type == "PanoramaCam")
        cam = std::make_shared<PanoramaCamera>(dir, vup, fov[0], fov[1], w, h);
      else
        cam = std::make_shared<PinholeStereoCamera>(dir, vup, fov[0], fov[1], w, h, ps.get_number("sep", 0.1));
    } else if (type == "4PICam") {
      cam = std::make_shared<FullSkyCamera>(ps.get_number("angle", 0.0), w, h);
    } else {
      cam = std::make_shared<DomeCamera>(ps.get_number("heading", 0.0), ps.get_number("pitch", 0.0), w);
    }
  } catch (const ParameterError& e) {
    // The camera names the key; the scene gives the location.
    throw SceneError(ps.loc(), ps.command(), e.key(), e.message());
  }
  if (ps.has("filter")) {
    const std::string f = ps.get_string("filter");
    try {
      cam->filter = parse_filter(f);
    } catch (const Error&) {
      ps.fail("filter", "unknown camera filter \"" + f + "\"" + did_you_mean(f, filter_names()) +
                            " (valid: " + join(filter_names()) + ")");
    }
  }
  cam->param = ps.get_number("param", 0.0);
  return cam;
}

void override_camera_resolution(Camera& cam, int width, int height) { cam.set_resolution(width, height); }

}  // namespace geovis
