// Dome mapping as implemented in GeoViS Gvs2PICam::GetRayDir (paper eq. 6; the code, which GeoViS
// scenes were made with, differs from the printed equation in signs and an extra quarter turn):
//   sx = 2 (1/2 − px/W),  sy = 2 (1/2 − py/W),  r² = sx² + sy² (no ray when r² > 1),
//   ŝ = (sx, sy, sqrt(1 − r²)),   d = R_z(−h) R_y(−p) R_z(3π/2) ŝ,
// where R_a(α) is the right-handed rotation by α about axis a (Motion4D RotateMat3D, Graphics Gems
// "Rotation Tools"). The angle between d and the dome centre R_z(−h) R_y(−p) ẑ is arcsin r.
#include "render/dome_camera.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "render/camera_type.h"

namespace geovis {

namespace {
using M3 = double[3][3];
void rot_z(double a, M3& m) {
  const double c = std::cos(a), s = std::sin(a);
  const double r[3][3] = {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = r[i][j];
}
void rot_y(double a, M3& m) {
  const double c = std::cos(a), s = std::sin(a);
  const double r[3][3] = {{c, 0, s}, {0, 1, 0}, {-s, 0, c}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = r[i][j];
}
void mul(const M3& a, const M3& b, M3& out) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      out[i][j] = 0;
      for (int k = 0; k < 3; ++k) out[i][j] += a[i][k] * b[k][j];
    }
}
}  // namespace

DomeCamera::DomeCamera(double heading_deg, double pitch_deg, int size)
    : Camera(size, size), heading_deg_(heading_deg), pitch_deg_(pitch_deg) {
  Camera::set_resolution(size, size);
  if (!std::isfinite(heading_deg) || !std::isfinite(pitch_deg))
    throw ParameterError("2PICam", std::isfinite(heading_deg) ? "pitch" : "heading",
                         "expected a finite angle in degrees");
  install();
}

void DomeCamera::install() {
  constexpr double deg = std::numbers::pi / 180.0;
  double a[3][3], b[3][3], c[3][3], ab[3][3];
  rot_z(-heading_deg_ * deg, a);
  rot_y(-pitch_deg_ * deg, b);
  rot_z(1.5 * std::numbers::pi, c);
  mul(a, b, ab);
  mul(ab, c, R_);
}

void DomeCamera::set_resolution(int width, int /*height*/) { Camera::set_resolution(width, width); }

bool DomeCamera::direction(double px, double py, Vec3& d) const {
  const double n = width_;
  const double sx = 2.0 * (0.5 - px / n), sy = 2.0 * (0.5 - py / n);
  const double r2 = sx * sx + sy * sy;
  if (r2 > 1.0) return false;
  const double s[3] = {sx, sy, std::sqrt(1.0 - r2)};
  d = {R_[0][0] * s[0] + R_[0][1] * s[1] + R_[0][2] * s[2], R_[1][0] * s[0] + R_[1][1] * s[1] + R_[1][2] * s[2],
       R_[2][0] * s[0] + R_[2][1] * s[1] + R_[2][2] * s[2]};
  return true;
}

void DomeCamera::set_param(std::string_view name, const Value& value) {
  const std::string n = to_lower(name);
  if (n != "heading" && n != "pitch") unknown_param(name);
  const double a = value_as_number(value, "2PICam", n);
  if (!std::isfinite(a)) throw ParameterError("2PICam", n, "expected a finite number, found " + value.describe());
  (n == "heading" ? heading_deg_ : pitch_deg_) = a;
  install();
}

namespace {
// GeoViS 2PICam (docs/geovis-catalogue.md §2): square, only res[0] is used.
const TypeRegistrar<CameraType> dome_camera_registrar{
    {{"2PICam",
      {},
      "dome (fisheye) camera: the half sky around heading and pitch on a square image",
      {camera_resolution_key(100, 100),
       {"heading", ParamType::Number, "heading of the dome centre in degrees", false, false, 0.0},
       {"pitch", ParamType::Number, "pitch of the dome centre in degrees", false, false, 0.0}}},
     [](const ParamReader& keys, int width, int) -> std::shared_ptr<Camera> {
       return std::make_shared<DomeCamera>(keys.number("heading"), keys.number("pitch"), width);
     }}};
}  // namespace

}  // namespace geovis
