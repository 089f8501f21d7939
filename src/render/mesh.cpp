#include "render/mesh.h"

#include <tiny_obj_loader.h>

#include "core/error.h"
#include "core/rotation.h"
#include "io/image.h"
#include "render/object_type.h"

namespace geovis {

std::shared_ptr<MeshObject> MeshObject::load(const std::string& path) {
  tinyobj::ObjReaderConfig cfg;
  cfg.triangulate = true;
  const auto slash = path.find_last_of('/');
  cfg.mtl_search_path = slash == std::string::npos ? std::string("./") : path.substr(0, slash + 1);
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, cfg)) {
    std::string msg = reader.Error();
    while (!msg.empty() && (msg.back() == '\n' || msg.back() == '\r')) msg.pop_back();
    throw Error("cannot read OBJ mesh \"" + path + "\"" + (msg.empty() ? std::string() : ": " + msg));
  }
  const auto& attrib = reader.GetAttrib();
  std::vector<Vec3> v(attrib.vertices.size() / 3), n(attrib.normals.size() / 3);
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = {attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]};
  for (size_t i = 0; i < n.size(); ++i)
    n[i] = {attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]};
  std::vector<double> vt(attrib.texcoords.begin(), attrib.texcoords.end());
  std::vector<Tri> tris;
  for (const auto& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (unsigned char fv : shape.mesh.num_face_vertices) {
      if (fv == 3) {
        Tri t;
        for (int k = 0; k < 3; ++k) {
          const auto& ix = shape.mesh.indices[offset + k];
          t.v[k] = ix.vertex_index;
          t.vt[k] = ix.texcoord_index;
          t.vn[k] = ix.normal_index;
        }
        tris.push_back(t);
      }
      offset += fv;
    }
  }
  if (tris.empty()) throw Error("OBJ mesh \"" + path + "\" contains no triangle faces");
  for (const Tri& t : tris)
    for (int k = 0; k < 3; ++k) {
      const bool bad_v = t.v[k] < 0 || static_cast<size_t>(t.v[k]) >= v.size();
      const bool bad_vt = t.vt[k] >= 0 && 2 * static_cast<size_t>(t.vt[k]) + 1 >= vt.size();
      const bool bad_vn = t.vn[k] >= 0 && static_cast<size_t>(t.vn[k]) >= n.size();
      if (bad_v || bad_vt || bad_vn)
        throw Error("OBJ mesh \"" + path + "\": a face refers to a " +
                    std::string(bad_v ? "vertex" : (bad_vt ? "texture coordinate" : "normal")) +
                    " that does not exist");
    }
  return std::make_shared<MeshObject>(std::move(v), std::move(vt), std::move(n), std::move(tris));
}

MeshObject::MeshObject(std::vector<Vec3> vertices, std::vector<double> texcoords, std::vector<Vec3> normals,
                       std::vector<Tri> tris)
    : vertices_(std::move(vertices)),
      texcoords_(std::move(texcoords)),
      normals_(std::move(normals)),
      tris_(std::move(tris)) {
  finalize();
}

void MeshObject::finalize() {
  std::vector<Bounds3> boxes(tris_.size());
  local_bounds_ = Bounds3{};
  for (size_t i = 0; i < tris_.size(); ++i) {
    for (int k = 0; k < 3; ++k) boxes[i].expand(vertices_[tris_[i].v[k]]);
    local_bounds_.expand(boxes[i]);
  }
  bvh_.build(boxes);
}

Bounds3 MeshObject::bounds() const { return transformed ? to_parent.bounds(local_bounds_) : local_bounds_; }

bool MeshObject::intersect(const Segment& seg, Hit& hit) const {
  if (seg.chart0 != chart || seg.chart1 != chart) return false;
  const Vec3 o = transformed ? to_local.point(seg.p0) : seg.p0;
  const Vec3 d = (transformed ? to_local.point(seg.p1) : seg.p1) - o;
  double best = std::min(1.0, hit.s);
  int best_tri = -1;
  double best_b1 = 0, best_b2 = 0;
  bvh_.traverse(o, d, best, [&](int32_t i) {
    const Tri& t = tris_[i];
    double s, b1, b2;
    if (segment_triangle(o, d, vertices_[t.v[0]], vertices_[t.v[1]], vertices_[t.v[2]], best, s, b1, b2)) {
      best = s;
      best_tri = i;
      best_b1 = b1;
      best_b2 = b2;
    }
    return best;
  });
  if (best_tri < 0) return false;
  const Tri& t = tris_[best_tri];
  const double b0 = 1.0 - best_b1 - best_b2;
  const Vec3 dw = seg.p1 - seg.p0;
  hit.s = best;
  hit.point = seg.p0 + best * dw;
  hit.ray_dir = normalize(dw);
  // Shading normal: interpolated vertex normals when the file has them, else the geometric
  // normal of the counter-clockwise face (outward for a consistently oriented closed mesh).
  Vec3 n;
  if (t.vn[0] >= 0 && t.vn[1] >= 0 && t.vn[2] >= 0)
    n = b0 * normals_[t.vn[0]] + best_b1 * normals_[t.vn[1]] + best_b2 * normals_[t.vn[2]];
  else
    n = cross(vertices_[t.v[1]] - vertices_[t.v[0]], vertices_[t.v[2]] - vertices_[t.v[0]]);
  hit.normal = normalize(transformed ? to_local.transposed_dir(n) : n);
  hit.shade_normal = hit.normal;
  hit.shade_dir = hit.ray_dir;
  if (t.vt[0] >= 0 && t.vt[1] >= 0 && t.vt[2] >= 0) {
    hit.u = b0 * texcoords_[2 * t.vt[0]] + best_b1 * texcoords_[2 * t.vt[1]] + best_b2 * texcoords_[2 * t.vt[2]];
    hit.v = b0 * texcoords_[2 * t.vt[0] + 1] + best_b1 * texcoords_[2 * t.vt[1] + 1] +
            best_b2 * texcoords_[2 * t.vt[2] + 1];
  } else {
    hit.u = best_b1;
    hit.v = best_b2;
  }
  hit.shader = shader;
  hit.object_id = object_id;
  hit.time = seg.x0[0] + best * (seg.x1[0] - seg.x0[0]);
  hit.emitter_u = Vec4{{0, 0, 0, 0}};
  hit.keplerian = false;
  hit.part = 0;
  return true;
}

// ---- registration (docs/geovis-catalogue.md §4) -------------------------------------------------

namespace {

const TypeRegistrar<ObjectType> mesh_registrar{
    {{"mesh-obj",
      {},
      "a triangle mesh from a Wavefront OBJ file",
      primitive_keys_and({{"filename", ParamType::String, "Wavefront OBJ file", true},
                          {"pathname", ParamType::String, "folder of the file", false, false, std::string()},
                          {"rotate", ParamType::Vec4, "#(angle_deg ax ay az) rotation before transform"}}),
      {"objfilename"}},
     [](const ParamReader& keys, BuildContext& ctx) -> SceneObjectPtr {
       const std::string file = keys.string("filename");
       const std::string dir = keys.string("pathname");
       const std::string name = dir.empty() ? file : dir + "/" + file;
       const std::shared_ptr<MeshObject> mesh =
           keys.blame("filename", [&] { return MeshObject::load(find_file(name, ctx.search_paths, "OBJ mesh")); });
       if (!keys.has("rotate")) return finish_primitive(keys, ctx, mesh);
       const auto r = keys.vector("rotate", 4);
       Vec3 axis{r[1], r[2], r[3]};
       if (norm(axis) == 0) keys.fail("rotate", "expected #(angle_deg ax ay az) with a non-zero axis");
       axis = normalize(axis);
       // Rotation about the axis, applied before the transform.
       Transform rot = Transform::identity(3);
       const Matrix3 R = rotation_about_axis({axis.x, axis.y, axis.z}, r[0] * kDegToRad);
       for (int i = 0; i < 3; ++i)
         for (int j = 0; j < 3; ++j) rot(i, j) = R[i][j];
       return finish_primitive(keys, ctx, mesh, *mesh, &rot);
     }}};

}  // namespace

}  // namespace geovis
