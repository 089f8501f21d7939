// GeoViS PinHoleStereoCam (catalogue §2): a pinhole camera rendered once per eye.
#pragma once

#include "render/pinhole_camera.h"

namespace geovis {

/// Pinhole camera rendered once per eye; the eyes sit at ∓sep/2 along the camera's horizontal
/// axis (GeoViS GetLeft/RightEyePos). Setparam name of the separation: `eyesep`.
class PinholeStereoCamera : public PinholeCamera {
 public:
  PinholeStereoCamera(const Vec3& dir, const Vec3& vup, double fov_h_deg, double fov_v_deg, int width, int height,
                      double eye_separation);
  const char* type_name() const override { return "PinHoleStereoCam"; }
  void set_param(std::string_view name, const Value& value) override;
  std::vector<std::string> param_names() const override { return {"dir", "vup", "fov", "eyesep"}; }
  bool is_stereo() const override { return sep_ > 0; }  // GeoViS: stereo only for sep > 0
  Vec3 eye_offset(Eye eye) const override;
  double eye_separation() const { return sep_; }

 private:
  double sep_;
};

}  // namespace geovis
