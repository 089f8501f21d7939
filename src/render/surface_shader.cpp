#include "render/surface_shader.h"

#include <cmath>

#include "render/shader_type.h"

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

namespace {

// GeoViS SurfShader (docs/geovis-catalogue.md §6).
const TypeRegistrar<ShaderType> surface_shader_registrar{
    {{"SurfShader",
      {},
      "object colour from a texture, ambient and diffuse reflection, point lights",
      {{"objcolor", ParamType::String, "texture id of the object colour (none: black)"},
       {"normalmap", ParamType::String, "texture id of a normal map"},
       {"ambient", ParamType::Number, "ambient reflectance ka", false, false, 1.0},
       {"diffuse", ParamType::Number, "diffuse reflectance kd", false, false, 0.0}}},
     [](const ParamReader& keys, BuildContext& ctx) -> ShaderPtr {
       auto sh = std::make_shared<SurfaceShader>();
       if (keys.has("objcolor")) sh->objcolor = ctx.ref(ctx.textures, keys.params(), "objcolor", "texture");
       if (keys.has("normalmap")) sh->normalmap = ctx.ref(ctx.textures, keys.params(), "normalmap", "texture");
       sh->ambient = keys.number("ambient");
       sh->diffuse = keys.number("diffuse");
       return sh;
     }}};

}  // namespace

}  // namespace geovis
