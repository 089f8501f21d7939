// GeoViS 4PICam: the full sky, equirectangular (paper eq. 4; catalogue §2).
#pragma once

#include "render/camera.h"

namespace geovis {

class FullSkyCamera : public Camera {
 public:
  /// `angle_deg` rotates the image about the local z axis (e_(3)).
  FullSkyCamera(double angle_deg, int width, int height);
  const char* type_name() const override { return "4PICam"; }
  bool direction(double px, double py, Vec3& d) const override;
  void set_param(std::string_view name, const Value& value) override;
  std::vector<std::string> param_names() const override { return {"angle"}; }
  double angle_deg() const { return angle_deg_; }

 private:
  double angle_deg_;
};

}  // namespace geovis
