// GeoViS PinHoleCam (paper eq. 3; catalogue §2).
#pragma once

#include "render/camera.h"

namespace geovis {

class PinholeCamera : public Camera {
 public:
  /// dir/vup in the observer's local frame; fov = (horizontal, vertical) full angles in degrees.
  PinholeCamera(const Vec3& dir, const Vec3& vup, double fov_h_deg, double fov_v_deg, int width, int height);
  const char* type_name() const override { return "PinHoleCam"; }
  bool direction(double px, double py, Vec3& d) const override;
  void set_param(std::string_view name, const Value& value) override;
  std::vector<std::string> param_names() const override { return {"dir", "vup", "fov"}; }

  const CameraFrame& frame() const { return frame_; }
  double fov_h_deg() const { return fov_h_; }
  double fov_v_deg() const { return fov_v_; }

 protected:
  void install();  // recompute the frame and the half extents (GeoViS install())
  Vec3 dir_, vup_;
  double fov_h_, fov_v_;
  CameraFrame frame_{};
  double tan_half_h_ = 0, tan_half_v_ = 0;
};

}  // namespace geovis
