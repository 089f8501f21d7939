#include "render/plugins.h"

#include <cmath>

#include "core/rotation.h"
#include "io/image.h"
#include "render/compound.h"
#include "render/csg.h"
#include "render/local_object.h"
#include "render/mesh.h"
#include "render/shapes.h"
#include "render/surface_shader.h"
#include "render/textures.h"
#include "spacetime/metric_registry.h"

namespace geovis {

namespace {


Diagnostics& diag_of(BuildContext& ctx) {
  static thread_local Diagnostics fallback;
  return ctx.diag ? *ctx.diag : fallback;
}

ParamSpec spec(std::string key, ParamType t, std::string doc, bool required = false, bool repeatable = false) {
  return ParamSpec{std::move(key), t, std::move(doc), required, repeatable};
}

Vec3 vec3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }
Color color3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

/// Finds `name` in `valid` case-insensitively; fails with the closest valid name.
std::string canonical_name(const ParamSet& ps, std::string_view key, const std::string& name,
                           const std::vector<std::string>& valid, std::string_view kind) {
  for (const auto& v : valid)
    if (to_lower(v) == to_lower(name)) return v;
  ps.fail(key, "unknown " + std::string(kind) + " \"" + name + "\"" + did_you_mean(name, valid) +
                   " (valid: " + join(valid) + ")");
}

double positive(const ParamSet& ps, std::string_view key, double v) {
  if (!(v > 0) || !std::isfinite(v))
    ps.fail(key, "expected a positive number, found " + Value(v).describe());
  return v;
}

// ---- textures -----------------------------------------------------------------------------------

std::vector<ParamSpec> texture_common() {
  return {spec("type", ParamType::String, "texture type", true), spec("id", ParamType::String, "texture id"),
          spec("transform", ParamType::Transform, "2D transform of (u, v) (scale-obj, rotate-obj, translate-obj)")};
}

std::vector<ParamSpec> texture_specific(const std::string& type) {
  if (type == "UniTex")
    return {spec("color", ParamType::Vec3, "RGB colour"), spec("colorgray", ParamType::Number, "grey value")};
  if (type == "CheckerT2D" || type == "DieT2D")
    return {spec("texture", ParamType::String, "texture id (give two)", true, true)};
  if (type == "ChequeredT2D")
    return {spec("texture", ParamType::String, "texture id (give two)", true, true),
            spec("width", ParamType::Number, "border width in (0, 0.5), default 0.25")};
  if (type == "ChequeredTimeT2D")
    return {spec("texture", ParamType::String, "texture id (give two)", true, true),
            spec("deltat", ParamType::Number, "period in coordinate time, default 1")};
  if (type == "ColorGradTex")
    return {spec("color1", ParamType::Vec3, "start colour, default black"),
            spec("color2", ParamType::Vec3, "end colour, default white"),
            spec("start", ParamType::Vec2, "start point in (u, v), default #(0 0.5)"),
            spec("end", ParamType::Vec2, "end point in (u, v), default #(1 0.5)"),
            spec("gradtype", ParamType::String, "linear | radial | hsv | texCoords")};
  if (type == "Image")
    return {spec("file", ParamType::String, "image file", true),
            spec("sampling", ParamType::String,
                 "geovis extension: nearest (default, as GeoViS), bilinear or bicubic texel interpolation")};
  return {};
}

std::pair<TexturePtr, TexturePtr> two_textures(const ParamSet& ps, BuildContext& ctx) {
  const auto ids = ps.get_strings("texture");
  if (ids.size() != 2)
    ps.fail("texture", "expected two texture ids (give the key twice), found " + std::to_string(ids.size()));
  return {ctx.lookup(ctx.textures, ids[0], ps, "texture", "texture"),
          ctx.lookup(ctx.textures, ids[1], ps, "texture", "texture")};
}

// ---- objects ------------------------------------------------------------------------------------

std::vector<ParamSpec> primitive_common(bool with_motion = true) {
  std::vector<ParamSpec> s = {
      spec("objtype", ParamType::Int, "gpObjTypeInCoords (1, default) or gpObjTypeLocal (0)"),
      spec("id", ParamType::String, "object id"),
      spec("shader", ParamType::String, "surface shader id"),
      spec("metric", ParamType::String, "metric id (the device's metric is used)"),
      spec("transform", ParamType::Transform, "object-to-coordinates transform"),
      spec("chart", ParamType::Int, "coordinate chart of the object (default 0)")};
  if (with_motion) s.push_back(spec("motion", ParamType::String, "motion id (e.g. ConstVelocity)"));
  return s;
}

std::vector<ParamSpec> with(std::vector<ParamSpec> a, const std::vector<ParamSpec>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<ParamSpec> object_specific(const std::string& cmd) {
  if (cmd == "solid-ellipsoid")
    return with(primitive_common(), {spec("center", ParamType::Vec3, "centre, default #(0 0 0)"),
                                     spec("axlen", ParamType::Vec3, "semi-axes, default #(1 1 1)")});
  if (cmd == "solid-box")
    return with(primitive_common(), {spec("cornerll", ParamType::Vec3, "first corner", true),
                                     spec("cornerur", ParamType::Vec3, "opposite corner", true)});
  if (cmd == "solid-cylinder")
    return with(primitive_common(), {spec("base", ParamType::Vec3, "centre of the base", true),
                                     spec("top", ParamType::Vec3, "centre of the top", true),
                                     spec("radii", ParamType::Vec2, "the two radii", true)});
  if (cmd == "solid-ring")
    return with(primitive_common(), {spec("base", ParamType::Vec3, "centre of the base", true),
                                     spec("top", ParamType::Vec3, "centre of the top", true),
                                     spec("radii", ParamType::Vec2, "outer radii", true),
                                     spec("innerradii", ParamType::Vec2, "inner radii", true)});
  if (cmd == "solid-background") return primitive_common(false);
  if (cmd == "plane-ring")
    return with(primitive_common(), {spec("center", ParamType::Vec3, "centre, default #(0 0 0)"),
                                     spec("normal", ParamType::Vec3, "normal, default #(0 0 1)"),
                                     spec("rout", ParamType::Number, "outer radius", true),
                                     spec("rin", ParamType::Number, "inner radius, default 0"),
                                     spec("emitter", ParamType::String,
                                          "geovis: velocity of the emitting matter for 1+z: \"rest\" (default, at rest "
                                          "in the natural frame) or \"keplerian\" (thin disk on circular geodesics "
                                          "turning in +phi; spherical coordinates, centre 0, normal along z)")});
  if (cmd == "plane-triangle" || cmd == "plane-parallelogram")
    return with(primitive_common(), {spec("p1", ParamType::Vec3, "corner", true), spec("p2", ParamType::Vec3, "corner", true),
                                     spec("p3", ParamType::Vec3, "corner", true)});
  if (cmd == "mesh-obj")
    return with(primitive_common(), {spec("filename", ParamType::String, "Wavefront OBJ file", true),
                                     spec("pathname", ParamType::String, "folder of the file"),
                                     spec("rotate", ParamType::Vec4, "#(angle_deg ax ay az) rotation before transform")});
  if (cmd == "csg-object")
    return {spec("csgtype", ParamType::Int, "1 difference, 2 union, 3 intersection"),
            spec("obj1", ParamType::String, "first solid", true), spec("obj2", ParamType::String, "second solid", true),
            spec("id", ParamType::String, "object id")};
  if (cmd == "comp-object")
    return {spec("obj", ParamType::String, "object id", false, true),
            spec("transform", ParamType::Transform, "transform of the whole group"),
            spec("id", ParamType::String, "object id")};
  if (cmd == "comp-octree-object")
    return {spec("obj", ParamType::String, "object id", false, true),
            spec("lower", ParamType::Vec3, "octree box corner (a BVH is used instead)"),
            spec("upper", ParamType::Vec3, "octree box corner (a BVH is used instead)"),
            spec("subdivs", ParamType::Int, "octree subdivisions (a BVH is used instead)"),
            spec("id", ParamType::String, "object id")};
  if (cmd == "local-comp-object")
    return {spec("obj", ParamType::String, "object of gpObjTypeLocal", true, true),
            spec("localtetrad", ParamType::String, "static local tetrad id"),
            spec("motion", ParamType::String, "motion id"),
            spec("timeboxsize", ParamType::Number, "accepted for GeoViS compatibility (world tube from the motion's samples)"),
            spec("id", ParamType::String, "object id")};
  return {};
}

ObjType object_type_of(const SceneObject& o);

ObjType object_type_of(const SceneObject& o) {
  if (auto* p = dynamic_cast<const PrimitiveData*>(&o)) return p->objtype;
  if (auto* c = dynamic_cast<const CompoundObject*>(&o)) {
    for (const auto& ch : c->children())
      if (object_type_of(*ch) == ObjType::Local) return ObjType::Local;
    return ObjType::InCoords;
  }
  if (auto* csg = dynamic_cast<const CsgObject*>(&o)) return object_type_of(*csg->first);
  return ObjType::InCoords;  // local-comp-object and moving objects are placed in coordinates
}

const SceneObjectPtr& ref_object(const ParamSet& ps, BuildContext& ctx, const std::string& id, std::string_view key) {
  return ctx.lookup(ctx.objects, id, ps, key, "object");
}

/// Children of a group: every `obj`.
std::vector<SceneObjectPtr> group_children(const ParamSet& ps, BuildContext& ctx) {
  std::vector<SceneObjectPtr> out;
  for (const auto& id : ps.get_strings("obj")) {
    // GeoViS ignores objtype when intersecting: an object of gpObjTypeLocal inside a plain group
    // is placed in coordinates like any other (appViewMovBall.scm).
    out.push_back(ref_object(ps, ctx, id, "obj"));
  }
  return out;
}

std::shared_ptr<const Metric> require_metric(const ParamSet& ps, BuildContext& ctx, std::string_view key) {
  if (!ctx.metric) ps.fail(key, "needs a metric: define one with init-metric before this command");
  return ctx.metric;
}

/// Shader, objID, objtype, transform, chart, id of a primitive; wraps it in a moving frame when
/// `motion` is given.
SceneObjectPtr finish_primitive(const ParamSet& ps, BuildContext& ctx, std::shared_ptr<SceneObject> obj,
                                PrimitiveData& data, bool count_id = true,
                                const Transform* pre_rotation = nullptr) {
  if (ps.has("shader")) {
    data.shader_owner = ctx.ref(ctx.shaders, ps, "shader", "shader");
    data.shader = data.shader_owner.get();
  }
  const int ot = ps.get_int("objtype", 1);
  if (ot != 0 && ot != 1)
    ps.fail("objtype", "expected gpObjTypeLocal (0) or gpObjTypeInCoords (1), found " + std::to_string(ot));
  data.objtype = ot == 0 ? ObjType::Local : ObjType::InCoords;
  if (ps.has("transform") || pre_rotation) {
    try {
      const Transform t = ps.get_transform("transform", Transform::identity(3));
      data.set_transform(pre_rotation ? t * *pre_rotation : t);
    } catch (const SceneError&) {
      throw;
    } catch (const Error& e) {
      ps.fail("transform", e.what());
    }
  }
  obj->chart = ps.get_int("chart", 0);
  obj->id = ps.get_string("id", "");
  if (count_id) data.object_id = ctx.next_object_id();
  if (ps.has("motion")) {
    const MotionPtr& motion = ctx.ref(ctx.motions, ps, "motion", "motion");
    auto metric = require_metric(ps, ctx, "motion");
    try {
      const bool pseudo_cartesian = std::string_view(motion->type_name()) == "ConstVelocity" &&
                                    !metric->info().inertial_cartesian;
      if (pseudo_cartesian) {
        diag_of(ctx).warn(ps.loc(), ps.command(), "motion",
                          "the ConstVelocity motion \"" + ps.get_string("motion") + "\" is special-relativistic; in the " +
                              metric->name() +
                              " metric it is applied, as GeoViS does, to the pseudo-Cartesian coordinates (t, x, y, "
                              "z) of the rays as if they were Minkowski coordinates: a kinematic effect, not a motion "
                              "of this spacetime");
        metric = make_metric("Minkowski");
      }
      auto moving = std::make_shared<LocalObject>(obj, LocalFrame(metric, motion));
      moving->id = obj->id;
      moving->chart = obj->chart;
      if (pseudo_cartesian) return std::make_shared<PseudoCartesianMotionObject>(moving);
      return moving;
    } catch (const SceneError&) {
      throw;
    } catch (const Error& e) {
      ps.fail("motion", e.what());
    }
  }
  return obj;
}

template <class T>
SceneObjectPtr primitive(const ParamSet& ps, BuildContext& ctx, std::shared_ptr<T> obj) {
  return finish_primitive(ps, ctx, obj, *obj);
}

Vec3 get3(const ParamSet& ps, std::string_view key, std::optional<std::vector<double>> def = {}) {
  return vec3(ps.get_vector(key, 3, std::move(def)));
}

SceneObjectPtr make_csg(const ParamSet& ps, BuildContext& ctx) {
  int type = ps.get_int("csgtype", 0);
  if (type == 0) {
    diag_of(ctx).warn(ps.loc(), ps.command(), "csgtype",
                      "missing or 0: using difference (1), as GeoViS does (valid: 1 difference, 2 union, 3 intersection)");
    type = 1;
  }
  if (type < 1 || type > 3)
    ps.fail("csgtype", "expected 1 (difference), 2 (union) or 3 (intersection), found " + std::to_string(type));
  const std::string id1 = ps.get_string("obj1"), id2 = ps.get_string("obj2");
  const SceneObjectPtr& a = ref_object(ps, ctx, id1, "obj1");
  const SceneObjectPtr& b = ref_object(ps, ctx, id2, "obj2");
  auto moving_a = std::dynamic_pointer_cast<const LocalObject>(a);
  auto moving_b = std::dynamic_pointer_cast<const LocalObject>(b);
  SceneObjectPtr sa = a, sb = b;
  if (moving_a || moving_b) {
    // Both solids must move together: the CSG is then built in their common rest frame and
    // moved as a whole.
    if (!moving_a || !moving_b || !moving_a->frame().moving() || !moving_b->frame().moving() ||
        moving_a->frame().motion() != moving_b->frame().motion())
      ps.fail("obj2", "\"" + id1 + "\" and \"" + id2 +
                          "\" must both be solids at rest in coordinates or both move with the same motion");
    sa = moving_a->child();
    sb = moving_b->child();
  }
  auto solid_a = std::dynamic_pointer_cast<const Solid>(sa);
  auto solid_b = std::dynamic_pointer_cast<const Solid>(sb);
  if (!solid_a) ps.fail("obj1", "\"" + id1 + "\" is not a solid (csg-object combines solid-* objects and csg-objects)");
  if (!solid_b) ps.fail("obj2", "\"" + id2 + "\" is not a solid (csg-object combines solid-* objects and csg-objects)");
  auto csg = std::make_shared<CsgObject>(static_cast<CsgOp>(type), solid_a, solid_b);
  csg->id = ps.get_string("id", "");
  if (moving_a) {
    auto moving = std::make_shared<LocalObject>(csg, moving_a->frame());
    moving->id = csg->id;
    moving->chart = csg->chart;
    return moving;
  }
  return csg;
}

SceneObjectPtr make_local_comp(const ParamSet& ps, BuildContext& ctx) {
  const bool has_tetrad = ps.has("localtetrad"), has_motion = ps.has("motion");
  if (has_tetrad == has_motion)
    ps.fail(has_tetrad ? "motion" : "localtetrad",
            has_tetrad ? "give either localtetrad or motion, not both" : "needs a static localtetrad or a motion");
  const auto ids = ps.get_strings("obj");
  std::vector<SceneObjectPtr> children;
  for (const auto& id : ids) {
    const SceneObjectPtr& o = ref_object(ps, ctx, id, "obj");
    if (object_type_of(*o) != ObjType::Local)
      diag_of(ctx).warn(ps.loc(), ps.command(), "obj",
                        "object \"" + id + "\" has objtype gpObjTypeInCoords; inside local-comp-object it is "
                        "interpreted in the local frame");
    children.push_back(o);
  }
  SceneObjectPtr child = children.size() == 1 ? children[0] : std::make_shared<CompoundObject>(children);
  auto metric = require_metric(ps, ctx, has_motion ? "motion" : "localtetrad");
  try {
    auto obj = has_motion
                   ? std::make_shared<LocalObject>(child, LocalFrame(metric, ctx.ref(ctx.motions, ps, "motion", "motion")))
                   : std::make_shared<LocalObject>(
                         child, LocalFrame(metric, ctx.ref(ctx.tetrads, ps, "localtetrad", "local tetrad")));
    obj->id = ps.get_string("id", "");
    return obj;
  } catch (const SceneError&) {
    throw;
  } catch (const Error& e) {
    ps.fail("obj", e.what());
  }
}

SceneObjectPtr make_mesh(const ParamSet& ps, BuildContext& ctx) {
  const std::string file = ps.get_string("filename");
  const std::string dir = ps.get_string("pathname", "");
  const std::string name = dir.empty() ? file : dir + "/" + file;
  std::shared_ptr<MeshObject> mesh;
  try {
    mesh = MeshObject::load(find_file(name, ctx.search_paths, "OBJ mesh"));
  } catch (const SceneError&) {
    throw;
  } catch (const Error& e) {
    ps.fail("filename", e.what());
  }
  Transform rot = Transform::identity(3);
  if (ps.has("rotate")) {
    const auto r = ps.get_vector("rotate", 4);
    Vec3 axis{r[1], r[2], r[3]};
    if (norm(axis) == 0) ps.fail("rotate", "expected #(angle_deg ax ay az) with a non-zero axis");
    axis = normalize(axis);
    // Rotation about the axis, applied before the transform.
    const Matrix3 R = rotation_about_axis({axis.x, axis.y, axis.z}, r[0] * kDegToRad);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rot(i, j) = R[i][j];
  }
  return finish_primitive(ps, ctx, mesh, *mesh, true, ps.has("rotate") ? &rot : nullptr);
}

}  // namespace

// ---- public -------------------------------------------------------------------------------------

std::vector<std::string> texture_types() {
  return {"UniTex", "CheckerT2D", "ChequeredT2D", "ChequeredTimeT2D", "DieT2D", "ColorGradTex", "Image"};
}
std::vector<std::string> shader_types() { return {"SurfShader"}; }
std::vector<std::string> light_types() { return {"PointLight"}; }
std::vector<std::string> object_commands() {
  return {"solid-ellipsoid", "solid-box",      "solid-cylinder",      "solid-ring", "solid-background",
          "plane-ring",      "plane-triangle", "plane-parallelogram", "mesh-obj",   "csg-object",
          "comp-object",     "comp-octree-object", "local-comp-object"};
}

std::vector<ParamSpec> texture_keys(const std::string& type) {
  auto s = texture_specific(type);
  if (s.empty() && type != "UniTex") return {};
  return with(texture_common(), s);
}

std::vector<ParamSpec> object_keys(const std::string& command) { return object_specific(command); }

TexturePtr make_texture(const ParamSet& ps, BuildContext& ctx) {
  const std::string type = canonical_name(ps, "type", ps.get_string("type"), texture_types(), "texture type");
  ps.validate(texture_keys(type), diag_of(ctx));
  std::shared_ptr<Texture2D> tex;
  if (type == "UniTex") {
    Color c{0, 0, 0};
    if (ps.has("color")) c = color3(ps.get_vector("color", 3));
    else if (ps.has("colorgray")) {
      const double g = ps.get_number("colorgray");
      c = {g, g, g};
    }
    tex = std::make_shared<UniTexture>(c);
  } else if (type == "CheckerT2D") {
    auto [a, b] = two_textures(ps, ctx);
    tex = std::make_shared<CheckerTexture>(a, b);
  } else if (type == "DieT2D") {
    auto [a, b] = two_textures(ps, ctx);
    tex = std::make_shared<DieTexture>(a, b);
  } else if (type == "ChequeredT2D") {
    auto [a, b] = two_textures(ps, ctx);
    const double w = ps.get_number("width", 0.25);
    if (!(w > 0 && w < 0.5)) ps.fail("width", "expected a border width in (0, 0.5), found " + Value(w).describe());
    tex = std::make_shared<ChequeredTexture>(a, b, w);
  } else if (type == "ChequeredTimeT2D") {
    auto [a, b] = two_textures(ps, ctx);
    tex = std::make_shared<ChequeredTimeTexture>(a, b, positive(ps, "deltat", ps.get_number("deltat", 1.0)));
  } else if (type == "ColorGradTex") {
    const auto c1 = ps.get_vector("color1", 3, std::vector<double>{0, 0, 0});
    const auto c2 = ps.get_vector("color2", 3, std::vector<double>{1, 1, 1});
    const auto st = ps.get_vector("start", 2, std::vector<double>{0, 0.5});
    const auto en = ps.get_vector("end", 2, std::vector<double>{1, 0.5});
    const std::string g = canonical_name(ps, "gradtype", ps.get_string("gradtype", "linear"),
                                         ColorGradTexture::kind_names(), "gradient type");
    const auto& names = ColorGradTexture::kind_names();
    const auto kind = static_cast<ColorGradTexture::Kind>(std::find(names.begin(), names.end(), g) - names.begin());
    tex = std::make_shared<ColorGradTexture>(color3(c1), color3(c2), st[0], st[1], en[0], en[1], kind);
  } else {  // Image
    const std::string file = ps.get_string("file");
    const auto& names = ImageTexture::sampling_names();
    const std::string s = canonical_name(ps, "sampling", ps.get_string("sampling", "nearest"), names, "sampling");
    const auto sampling = static_cast<ImageTexture::Sampling>(std::find(names.begin(), names.end(), s) - names.begin());
    try {
      tex = std::make_shared<ImageTexture>(load_image_cached(find_file(file, ctx.search_paths, "texture image")),
                                           sampling);
    } catch (const SceneError&) {
      throw;
    } catch (const Error& e) {
      ps.fail("file", e.what());
    }
  }
  if (ps.has("transform")) tex->uv_transform = UVTransform::from(ps.get_transform("transform"));
  return tex;
}

std::vector<ParamSpec> shader_keys() {
  return {spec("type", ParamType::String, "SurfShader"), spec("id", ParamType::String, "shader id"),
          spec("objcolor", ParamType::String, "texture id of the object colour"),
          spec("normalmap", ParamType::String, "texture id of a normal map"),
          spec("ambient", ParamType::Number, "ambient reflectance, default 1"),
          spec("diffuse", ParamType::Number, "diffuse reflectance, default 0")};
}

std::vector<ParamSpec> light_keys() {
  return {spec("type", ParamType::String, "PointLight"), spec("id", ParamType::String, "light id"),
          spec("pos", ParamType::Any, "event #(t x y z) (or position #(x y z))", true),
          spec("color", ParamType::Vec3, "RGB colour, default #(1 1 1)"),
          spec("atten", ParamType::Vec3, "constant, linear, quadratic attenuation, default #(0 0 0)")};
}

std::vector<ParamSpec> light_manager_keys() {
  return {spec("id", ParamType::String, "light manager id"),
          spec("ambient", ParamType::Vec3, "ambient light, default #(1 1 1)"),
          spec("diffuse", ParamType::Vec3, "diffuse light from the observer, default #(1 1 1)"),
          spec("light", ParamType::String, "light id", false, true),
          spec("shadows", ParamType::Bool, "point-light shadow rays (Minkowski only), default #f")};
}

ShaderPtr make_shader(const ParamSet& ps, BuildContext& ctx) {
  canonical_name(ps, "type", ps.get_string("type", "SurfShader"), shader_types(), "shader type");
  ps.validate(shader_keys(), diag_of(ctx));
  auto sh = std::make_shared<SurfaceShader>();
  if (ps.has("objcolor")) sh->objcolor = ctx.ref(ctx.textures, ps, "objcolor", "texture");
  if (ps.has("normalmap")) sh->normalmap = ctx.ref(ctx.textures, ps, "normalmap", "texture");
  sh->ambient = ps.get_number("ambient", 1.0);
  sh->diffuse = ps.get_number("diffuse", 0.0);
  return sh;
}

PointLight make_point_light(const ParamSet& ps, BuildContext& ctx) {
  canonical_name(ps, "type", ps.get_string("type", "PointLight"), light_types(), "light type");
  ps.validate(light_keys(), diag_of(ctx));
  PointLight l;
  const auto p = ps.get_vector_any("pos", {3, 4});
  l.pos = p.size() == 4 ? Vec4{{p[0], p[1], p[2], p[3]}} : Vec4{{0, p[0], p[1], p[2]}};
  l.color = color3(ps.get_vector("color", 3, std::vector<double>{1, 1, 1}));
  const auto a = ps.get_vector("atten", 3, std::vector<double>{0, 0, 0});
  for (int i = 0; i < 3; ++i)
    if (a[i] < 0) ps.fail("atten", "attenuation coefficients must be >= 0");
  l.atten = vec3(a);
  return l;
}

LightManager make_light_manager(const ParamSet& ps, BuildContext& ctx) {
  ps.validate(light_manager_keys(), diag_of(ctx));
  LightManager m;
  m.ambient = color3(ps.get_vector("ambient", 3, std::vector<double>{1, 1, 1}));
  m.diffuse = color3(ps.get_vector("diffuse", 3, std::vector<double>{1, 1, 1}));
  for (const auto& id : ps.get_strings("light")) m.lights.push_back(ctx.lookup(ctx.lights, id, ps, "light", "light"));
  m.shadows = ps.get_bool("shadows", false);
  return m;
}

SceneObjectPtr make_object(const ParamSet& ps, BuildContext& ctx) {
  const auto cmds = object_commands();
  const std::string& cmd = ps.command();
  if (std::find(cmds.begin(), cmds.end(), cmd) == cmds.end())
    ps.fail("", "unknown object command" + did_you_mean(cmd, cmds) + " (valid: " + join(cmds) + ")");
  ps.validate(object_specific(cmd), diag_of(ctx));

  if (cmd == "solid-ellipsoid") {
    const Vec3 ax = get3(ps, "axlen", std::vector<double>{1, 1, 1});
    for (int i = 0; i < 3; ++i) positive(ps, "axlen", ax[i]);
    return primitive(ps, ctx, std::make_shared<Ellipsoid>(get3(ps, "center", std::vector<double>{0, 0, 0}), ax));
  }
  if (cmd == "solid-background")
    return primitive(ps, ctx, std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 1, 1}));
  if (cmd == "solid-box") {
    const Vec3 a = get3(ps, "cornerll"), b = get3(ps, "cornerur");
    for (int i = 0; i < 3; ++i)
      if (a[i] == b[i]) ps.fail("cornerur", "the box has zero extent along axis " + std::to_string(i));
    return primitive(ps, ctx, std::make_shared<Box>(a, b));
  }
  if (cmd == "solid-cylinder" || cmd == "solid-ring") {
    const Vec3 base = get3(ps, "base"), top = get3(ps, "top");
    if (norm(top - base) == 0) ps.fail("top", "top equals base: the cylinder has no height");
    const auto r = ps.get_vector("radii", 2);
    positive(ps, "radii", r[0]);
    positive(ps, "radii", r[1]);
    if (cmd == "solid-cylinder") return primitive(ps, ctx, std::make_shared<Cylinder>(base, top, r[0], r[1]));
    const auto ri = ps.get_vector("innerradii", 2);
    positive(ps, "innerradii", ri[0]);
    positive(ps, "innerradii", ri[1]);
    if (!(ri[0] < r[0] && ri[1] < r[1])) ps.fail("innerradii", "inner radii must be smaller than the radii");
    return primitive(ps, ctx, std::make_shared<Ring>(base, top, r[0], r[1], ri[0], ri[1]));
  }
  if (cmd == "plane-ring") {
    const Vec3 n = get3(ps, "normal", std::vector<double>{0, 0, 1});
    if (norm(n) == 0) ps.fail("normal", "expected a non-zero normal vector");
    const double rout = positive(ps, "rout", ps.get_number("rout"));
    const double rin = ps.get_number("rin", 0.0);
    if (!(rin >= 0 && rin < rout)) ps.fail("rin", "expected 0 <= rin < rout, found rin = " + Value(rin).describe());
    const Vec3 center = get3(ps, "center", std::vector<double>{0, 0, 0});
    auto ring = std::make_shared<PlaneRing>(center, n, rin, rout);
    const std::string emitter = canonical_name(ps, "emitter", ps.get_string("emitter", "rest"),
                                               {"rest", "keplerian"}, "emitter velocity");
    if (emitter == "keplerian") {
      // circular_orbit_velocity needs the equatorial plane of spherical-like coordinates.
      if (!ctx.metric || ctx.metric->info().coord_type != CoordType::Spherical)
        ps.fail("emitter", "\"keplerian\" needs a metric in spherical coordinates (t, r, theta, phi)" +
                               (ctx.metric ? std::string(", found ") + ctx.metric->name() : std::string()));
      if (norm(center) != 0 || n.x != 0 || n.y != 0 || ps.has("transform"))
        ps.fail("emitter", "\"keplerian\" needs a ring in the equatorial plane: centre #(0 0 0), normal along z, "
                           "no transform");
      ring->keplerian_disk = true;
    }
    return primitive(ps, ctx, ring);
  }
  if (cmd == "plane-triangle" || cmd == "plane-parallelogram") {
    const Vec3 p1 = get3(ps, "p1"), p2 = get3(ps, "p2"), p3 = get3(ps, "p3");
    if (norm(cross(p2 - p1, p3 - p1)) == 0) ps.fail("p3", "the three points are collinear");
    if (cmd == "plane-triangle") return primitive(ps, ctx, std::make_shared<Triangle>(p1, p2, p3));
    return primitive(ps, ctx, std::make_shared<Parallelogram>(p1, p2, p3));
  }
  if (cmd == "mesh-obj") return make_mesh(ps, ctx);
  if (cmd == "csg-object") return make_csg(ps, ctx);
  if (cmd == "local-comp-object") return make_local_comp(ps, ctx);
  // comp-object, comp-octree-object
  auto comp = std::make_shared<CompoundObject>(group_children(ps, ctx));
  if (cmd == "comp-object" && ps.has("transform")) {
    try {
      comp->set_transform(ps.get_transform("transform"));
    } catch (const SceneError&) {
      throw;
    } catch (const Error& e) {
      ps.fail("transform", e.what());
    }
  }
  if (cmd == "comp-octree-object" && ps.has("subdivs") && ps.get_int("subdivs") < 0)
    ps.fail("subdivs", "expected a non-negative number of subdivisions");
  comp->id = ps.get_string("id", "");
  return comp;
}

}  // namespace geovis
