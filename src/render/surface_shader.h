// GeoViS SurfShader (catalogue §6, paper §2.4).
#pragma once

#include "render/shader.h"
#include "render/texture.h"

namespace geovis {

/// GvsSurfaceShader. With P the object colour (texture `objcolor` at the hit's (u, v), black
/// without one), n the surface normal turned towards the incoming ray (GeoViS inverts it when
/// n·d > 0) and d the ray direction at the hit, both in the primitive's normalised local frame
/// (Hit::shade_normal, Hit::shade_dir; GeoViS GvsSurfaceShader::reflArtifColor):
///   C = P·ka·A + P·kd·max(0, n'·(−d))·D + Σ_lights P·L_c·visible/att(dist)
/// A, D: ambient and diffuse light of the light manager (GeoViS uses its ambient light for both;
/// the two coincide in every GeoViS scene). The diffuse term is a light source at the observer:
/// its light comes back along the same null geodesic (paper §2.4). n' = −normalize(rgb of the
/// normal map) when `normalmap` is given (GeoViS: no 2c−1 remap), else n. Point-light term only
/// when ShadeContext::light_visible is set (Minkowski, object at rest, shadows on) and the light
/// lies on the lit side of the surface; att = c + l·dist + q·dist² (1 when all three are 0).
/// The result is clamped to [0, 1].
class SurfaceShader final : public Shader {
 public:
  TexturePtr objcolor;   ///< may be null (black)
  TexturePtr normalmap;  ///< may be null
  double ambient = 1.0;  ///< ka, GeoViS default 1
  double diffuse = 0.0;  ///< kd, GeoViS default 0
  Color shade(const Hit& hit, const ShadeContext& ctx) const override;
};

/// 1 / (c + l·d + q·d²), or 1 when all coefficients are zero (GeoViS atten default #(0 0 0)).
double light_attenuation(const Vec3& atten, double dist);

}  // namespace geovis
