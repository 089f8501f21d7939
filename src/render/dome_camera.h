// GeoViS 2PICam: "DomeMaster" fisheye images for planetarium projection (paper eq. 6 and appendix;
// catalogue §2). The image is square (only res[0] is used); pixels outside the inscribed disk are
// not traced.
#pragma once

#include "render/camera.h"

namespace geovis {

class DomeCamera : public Camera {
 public:
  DomeCamera(double heading_deg, double pitch_deg, int size);
  const char* type_name() const override { return "2PICam"; }
  bool direction(double px, double py, Vec3& d) const override;
  /// Square image: the height follows the width (GeoViS uses res[0] only).
  void set_resolution(int width, int height) override;
  void set_param(std::string_view name, const Value& value) override;
  std::vector<std::string> param_names() const override { return {"heading", "pitch"}; }

 private:
  void install();
  double heading_deg_, pitch_deg_;
  double R_[3][3]{};  // R_z(−heading) R_y(−pitch) R_z(3π/2)
};

}  // namespace geovis
