// Surface shading (paper §2.4, catalogue §6): ambient + diffuse with the light source at the
// observer (the light runs back along the same null geodesic) + point lights with shadow rays
// (Minkowski, objects at rest).
#pragma once

#include <memory>
#include <vector>

#include "core/function_ref.h"
#include "render/color.h"
#include "render/object.h"
#include "render/texture.h"

namespace geovis {

struct PointLight {
  Vec4 pos{{0, 0, 0, 0}};  ///< event (t, x, y, z); position in pseudo-Cartesian coordinates
  Color color{1, 1, 1};
  Vec3 atten{0, 0, 0};  ///< constant, linear, quadratic attenuation (GeoViS atten)
};

struct LightManager {
  Color ambient{1, 1, 1};
  Color diffuse{1, 1, 1};
  std::vector<PointLight> lights;
  bool shadows = false;
};

/// What the shader needs besides the hit.
struct ShadeContext {
  const LightManager* lights = nullptr;
  /// Returns true when `light` is visible from pseudo-Cartesian point `p` (shadow ray); empty
  /// when point-light shading is not possible (curved spacetime, moving object).
  FunctionRef<bool(const Vec3& p, const PointLight& light)> light_visible;
};

class Shader {
 public:
  virtual ~Shader() = default;
  virtual Color shade(const Hit& hit, const ShadeContext& ctx) const = 0;
};
using ShaderPtr = std::shared_ptr<Shader>;

}  // namespace geovis
