// GeoViS mesh-obj (GvsOBJMesh): a Wavefront OBJ triangle mesh read with tinyobjloader, tested
// through a BVH over its triangles (GeoViS tests them brute force). Faces with more than three
// vertices are triangulated. The mesh is one primitive with one objID (GeoViS's GvsOBJMesh stores
// faces, not GvsTriangle objects, so its triangles are not counted individually).
#pragma once

#include <string>
#include <vector>

#include "render/bvh.h"
#include "render/shapes.h"

namespace geovis {

class MeshObject final : public SceneObject, public PrimitiveData {
 public:
  struct Tri {
    int32_t v[3];
    int32_t vt[3];  ///< -1: no texture coordinates
    int32_t vn[3];  ///< -1: no normals
  };
  /// Reads `path`; throws Error naming the file (and tinyobjloader's message) on failure or when
  /// the file holds no triangle.
  static std::shared_ptr<MeshObject> load(const std::string& path);
  /// Builds from arrays (tests, generated meshes).
  MeshObject(std::vector<Vec3> vertices, std::vector<double> texcoords, std::vector<Vec3> normals,
             std::vector<Tri> tris);

  /// (Re)builds the BVH; call after changing the transform.
  void finalize();
  bool intersect(const Segment& seg, Hit& hit) const override;
  Bounds3 bounds() const override;
  size_t triangle_count() const { return tris_.size(); }

 private:
  std::vector<Vec3> vertices_;
  std::vector<double> texcoords_;  ///< u, v pairs
  std::vector<Vec3> normals_;
  std::vector<Tri> tris_;
  Bvh bvh_;
  Bounds3 local_bounds_;
};

}  // namespace geovis
