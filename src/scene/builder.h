// Turns an evaluated scene (scene/description.h: the ordered GeoViS command calls) into one
// RenderJob per output image (catalogue §1, §8-§10).
//
// The calls are processed in order, as GeoViS's parser does: every definition (metric, solver,
// camera, raygen, local tetrad, projector, lights, textures, shaders, objects, motions) is stored as
// its parameter set; set-parameter and add-object patch the stored set immediately; init-device
// takes a snapshot of the definitions at that point together with its setparam list. Building a
// device patches copies of the targets of its setparams (that frame only) and builds what the
// device uses, reusing everything whose parameters (and dependencies) did not change; motions, the
// expensive part, are cached by the contents of the motion, its metric and its solver.
#pragma once

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "render/render_job.h"
#include "scene/description.h"

namespace geovis {

struct BuildOptions {
  std::vector<std::string> search_paths;          ///< texture/mesh folders (scene dir, --texture-path, cwd)
  std::optional<std::pair<int, int>> resolution;  ///< --res: overrides every camera's resolution
  int supersample = 1;                            ///< n x n samples per pixel
  Diagnostics* diag = nullptr;                    ///< warnings (unknown keys, ...); may be null
  /// Folder of the files gvs-print-motion, calc-ray and calc-proj-ray write ("" = the current
  /// folder); a relative file name is relative to it.
  std::string output_dir;
  /// Sandboxed scene (docs/security.md): those files must stay below output_dir.
  bool confine_output = true;
  /// false (geovis check): run_actions checks and computes everything but writes no file.
  bool write_action_files = true;
};

struct FrameJob {
  int device = 0;
  std::string eye;  ///< "", "left", "right"
  RenderJob job;
  /// Extensions of the filter data files to write next to the image (".pdz", ".jac", ".pt", ".dat").
  std::vector<std::string> data_files_wanted;
};

class SceneBuilder {
 public:
  /// Processes every call (definitions, set-parameter, add-object, devices); throws SceneError
  /// ("file:line: command: key: ...") on the first bad call.
  SceneBuilder(SceneDescription scene, BuildOptions opts);
  ~SceneBuilder();
  SceneBuilder(SceneBuilder&&) noexcept;
  SceneBuilder& operator=(SceneBuilder&&) noexcept;

  /// Number of init-device calls (= frames; a stereo device renders two images per frame).
  int device_count() const;
  /// The render jobs of device `device` (0-based): one, or two (left, right) for a stereo camera.
  std::vector<FrameJob> build(int device) const;
  /// Multi-line description: metric and parameters, observer, camera, objects by kind, frames.
  std::string summary() const;

  /// Runs the scene's actions in order (gvs-print-motion, calc-ray, calc-proj-ray write files;
  /// gvs-print writes to `out`), each with the definitions as they were when it was called.
  void run_actions(std::ostream& out) const;
  /// Number of action calls in the scene.
  int action_count() const;

 private:
  friend class DeviceBuild;  // builds one device from the stored definitions (builder.cpp)
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace geovis
