#include "render/surface_shader.h"

#include <cmath>

namespace geovis {

double light_attenuation(const Vec3& atten, double dist) {
  const double a = atten.x + atten.y * dist + atten.z * dist * dist;
  if (atten.x == 0 && atten.y == 0 && atten.z == 0) return 1.0;
  return a > 0 ? 1.0 / a : 0.0;
}

Color SurfaceShader::shade(const Hit& hit, const ShadeContext& ctx) const {
  const Color P = objcolor ? objcolor->sample_part(hit.u, hit.v, hit.time, hit.part) : Color{0, 0, 0};
  static const LightManager kDefaultLights{};
  const LightManager& lm = ctx.lights ? *ctx.lights : kDefaultLights;

  // Normal towards the viewer (the ray arrives along ray_dir).
  Vec3 n = hit.normal;
  if (dot(n, hit.ray_dir) > 0) n = -n;
  // The diffuse term in the primitive's normalised local frame (GeoViS reflArtifColor).
  Vec3 n_diffuse = hit.shade_normal;
  if (dot(n_diffuse, hit.shade_dir) > 0) n_diffuse = -n_diffuse;
  if (normalmap) {
    const Color c = normalmap->sample_part(hit.u, hit.v, hit.time, hit.part);
    const Vec3 m{c.r, c.g, c.b};
    const double len = norm(m);
    if (len > 0) n_diffuse = -(m / len);
  }
  Color c = P * ambient * lm.ambient;
  const double cos_nl = std::max(0.0, dot(n_diffuse, -hit.shade_dir));
  c += P * (diffuse * cos_nl) * lm.diffuse;

  if (ctx.light_visible) {
    for (const PointLight& light : lm.lights) {
      const Vec3 lp{light.pos[1], light.pos[2], light.pos[3]};
      const Vec3 to_light = lp - hit.point;
      const double dist = norm(to_light);
      if (!(dist > 0) || dot(to_light, n) <= 0) continue;  // light behind the lit side
      if (!ctx.light_visible(hit.point, light)) continue;
      c += P * light.color * light_attenuation(light.atten, dist);
    }
  }
  return c.clamped();
}

}  // namespace geovis
