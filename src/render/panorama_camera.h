// GeoViS PanoramaCam (paper eq. 5; catalogue §2).
#pragma once

#include "render/camera.h"

namespace geovis {

class PanoramaCamera : public Camera {
 public:
  /// fov = (horizontal, vertical) in degrees.
  PanoramaCamera(const Vec3& dir, const Vec3& vup, double fov_h_deg, double fov_v_deg, int width, int height);
  const char* type_name() const override { return "PanoramaCam"; }
  bool direction(double px, double py, Vec3& d) const override;
  void set_param(std::string_view name, const Value& value) override;
  std::vector<std::string> param_names() const override { return {"dir", "vup"}; }
  const CameraFrame& frame() const { return frame_; }

 private:
  Vec3 dir_, vup_;
  double fov_h_rad_, fov_v_rad_;
  CameraFrame frame_{};
};

}  // namespace geovis
