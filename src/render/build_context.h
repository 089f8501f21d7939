// What plugin factories see while a scene is built (scene/builder): the device's metric, every
// object built so far by id, the texture search path and the diagnostics sink.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/params.h"
#include "render/object.h"
#include "render/shader.h"
#include "render/texture.h"
#include "spacetime/metric.h"
#include "spacetime/motion.h"

namespace geovis {

/// A static local tetrad (GeoViS local-tetrad): position and the four base vectors in coordinates.
struct LocalTetrad {
  Vec4 pos{{0, 0, 0, 0}};
  Tetrad e{};
};

class BuildContext {
 public:
  Diagnostics* diag = nullptr;
  /// `*diag`, or a sink of this thread when none is set (factories used outside a scene build).
  Diagnostics& diagnostics() {
    static thread_local Diagnostics fallback;
    return diag ? *diag : fallback;
  }
  std::vector<std::string> search_paths;  ///< scene folder, --texture-path dirs, working dir
  std::shared_ptr<const Metric> metric;   ///< the metric of the device being built

  std::map<std::string, TexturePtr> textures;
  std::map<std::string, ShaderPtr> shaders;
  std::map<std::string, SceneObjectPtr> objects;
  std::map<std::string, MotionPtr> motions;
  std::map<std::string, LocalTetrad> tetrads;
  std::map<std::string, PointLight> lights;

  /// Looks up the id stored under `key` of `ps` in `table`; a missing id is a SceneError naming
  /// the command, key, the id and the closest defined id of that kind.
  template <class T>
  const T& ref(const std::map<std::string, T>& table, const ParamSet& ps, std::string_view key,
               std::string_view kind) const {
    return lookup(table, ps.get_string(key), ps, key, kind);
  }
  template <class T>
  const T& lookup(const std::map<std::string, T>& table, const std::string& id, const ParamSet& ps,
                  std::string_view key, std::string_view kind) const {
    auto it = table.find(id);
    if (it != table.end()) return it->second;
    std::vector<std::string> ids;
    for (const auto& [k, v] : table) ids.push_back(k);
    ps.fail(key, "unknown " + std::string(kind) + " id \"" + id + "\"" + did_you_mean(id, ids) +
                     (ids.empty() ? " (no " + std::string(kind) + " is defined before this command)"
                                  : " (defined: " + join(ids) + ")"));
  }

  /// GeoViS objID: primitives are numbered 1, 2, ... in creation order.
  int next_object_id() { return ++object_counter_; }
  /// Number of objIDs handed out so far (the builder reuses cached primitives and keeps the
  /// numbering of GeoViS's creation order).
  int object_count() const { return object_counter_; }
  void set_object_count(int n) { object_counter_ = n; }

 private:
  int object_counter_ = 0;
};

}  // namespace geovis
