// Bounding volume hierarchy over items with axis-aligned bounds (compound objects, mesh
// triangles): a scene of thousands of items costs O(log n) box tests per segment. Built by
// recursive median split along the longest axis of the centroid bounds; traversed front to back
// with a fixed-size stack (no heap, no virtual call on the hot path: the visitor is a template).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "render/object.h"
#include "render/shapes.h"

namespace geovis {

class Bvh {
 public:
  struct Node {
    Bounds3 box;
    int32_t first = 0;  ///< leaf: first index into items(); inner: index of the right child
    int32_t count = 0;  ///< leaf: number of items (> 0); inner: 0 (left child = this + 1)
    int32_t axis = 0;   ///< split axis (inner nodes)
  };

  /// Builds over items 0..n-1 with the given (finite, non-empty) bounds.
  void build(const std::vector<Bounds3>& item_bounds, int leaf_size = 4);
  bool empty() const { return nodes_.empty(); }
  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<int32_t>& items() const { return items_; }

  /// Visits every item whose box the segment o + t d, 0 <= t <= tmax, touches, nearest boxes
  /// first. `visit(item)` tests the item and returns the current closest hit fraction (which
  /// shrinks tmax and prunes the rest).
  template <class Visit>
  void traverse(const Vec3& o, const Vec3& d, double tmax, Visit&& visit) const {
    if (nodes_.empty()) return;
    const Vec3 inv{1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
    const bool neg[3] = {d.x < 0, d.y < 0, d.z < 0};
    int32_t stack[64];
    int sp = 0;
    int32_t node = 0;
    for (;;) {
      const Node& n = nodes_[node];
      double t0 = 0, t1 = tmax;
      if (segment_box(o, inv, n.box, t0, t1)) {
        if (n.count > 0) {
          for (int32_t k = 0; k < n.count; ++k) tmax = std::min(tmax, visit(items_[n.first + k]));
        } else {
          // Near child first: left holds the lower half along the split axis.
          const int32_t left = node + 1, right = n.first;
          if (neg[n.axis]) {
            stack[sp++] = left;
            node = right;
          } else {
            stack[sp++] = right;
            node = left;
          }
          continue;
        }
      }
      if (sp == 0) break;
      node = stack[--sp];
    }
  }

 private:
  int32_t build_node(std::vector<int32_t>& idx, const std::vector<Bounds3>& b, const std::vector<Vec3>& c, int32_t lo,
                     int32_t hi, int leaf_size, int depth);
  std::vector<Node> nodes_;
  std::vector<int32_t> items_;
};

}  // namespace geovis
