// GeoViS PointLight (docs/geovis-catalogue.md §7): the light the surface shader's point-light term
// uses (render/surface_shader.h).
#include "render/light_type.h"

namespace geovis {

namespace {

const TypeRegistrar<LightType> point_light_registrar{
    {{"PointLight",
      {},
      "a point light at an event, with colour and distance attenuation",
      {{"pos", ParamType::Any, "event #(t x y z) (or position #(x y z) at t = 0)", true},
       {"color", ParamType::Vec3, "RGB colour", false, false, std::vector<double>{1, 1, 1}},
       {"atten", ParamType::Vec3, "constant, linear, quadratic attenuation (all 0: none)", false, false,
        std::vector<double>{0, 0, 0}, ParamRange::non_negative()}}},
     [](const ParamReader& keys) {
       PointLight l;
       const auto p = keys.params().get_vector_any("pos", {3, 4});
       l.pos = p.size() == 4 ? Vec4{{p[0], p[1], p[2], p[3]}} : Vec4{{0, p[0], p[1], p[2]}};
       const auto c = keys.vector("color", 3), a = keys.vector("atten", 3);
       l.color = {c[0], c[1], c[2]};
       l.atten = {a[0], a[1], a[2]};
       return l;
     }}};

}  // namespace

}  // namespace geovis
