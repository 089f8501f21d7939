#include "render/bvh.h"

namespace geovis {

void Bvh::build(const std::vector<Bounds3>& item_bounds, int leaf_size) {
  nodes_.clear();
  items_.clear();
  const int32_t n = static_cast<int32_t>(item_bounds.size());
  if (n == 0) return;
  std::vector<Vec3> centroid(n);
  for (int32_t i = 0; i < n; ++i) centroid[i] = 0.5 * (item_bounds[i].lo + item_bounds[i].hi);
  items_.resize(n);
  for (int32_t i = 0; i < n; ++i) items_[i] = i;
  nodes_.reserve(2 * static_cast<size_t>(n));
  build_node(items_, item_bounds, centroid, 0, n, std::max(1, leaf_size), 0);
}

int32_t Bvh::build_node(std::vector<int32_t>& idx, const std::vector<Bounds3>& b, const std::vector<Vec3>& c,
                        int32_t lo, int32_t hi, int leaf_size, int depth) {
  const int32_t me = static_cast<int32_t>(nodes_.size());
  nodes_.push_back({});
  Bounds3 box, cbox;
  for (int32_t i = lo; i < hi; ++i) {
    box.expand(b[idx[i]]);
    cbox.expand(c[idx[i]]);
  }
  nodes_[me].box = box;
  const Vec3 ext = cbox.hi - cbox.lo;
  const int axis = (ext.x >= ext.y && ext.x >= ext.z) ? 0 : (ext.y >= ext.z ? 1 : 2);
  // Depth limit keeps the traversal stack (64) safe; equal centroids cannot be split.
  if (hi - lo <= leaf_size || ext[axis] <= 0 || depth >= 60) {
    nodes_[me].first = lo;
    nodes_[me].count = hi - lo;
    return me;
  }
  const int32_t mid = lo + (hi - lo) / 2;
  std::nth_element(idx.begin() + lo, idx.begin() + mid, idx.begin() + hi,
                   [&](int32_t a, int32_t bb) { return c[a][axis] < c[bb][axis]; });
  build_node(idx, b, c, lo, mid, leaf_size, depth + 1);
  const int32_t right = build_node(idx, b, c, mid, hi, leaf_size, depth + 1);
  nodes_[me].first = right;
  nodes_[me].count = 0;
  nodes_[me].axis = axis;
  return me;
}

}  // namespace geovis
