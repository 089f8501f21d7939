// Scene builder: GeoViS command calls -> render jobs (see builder.h for the overall scheme).
//
// References between definitions follow GeoViS's parser (catalogue §1, §10):
//  * an id given under a key must name a definition of the right kind, else the error names the
//    closest id of that kind;
//  * a key left out means the last definition of that kind made before the referencing command
//    (GeoViS's default when only one exists; we extend it to "the last-defined one");
//  * the symbols GeoViS commands return (gtTexture, gtShader, gtLocTed, ...) mean "the most
//    recently created one of that kind";
//  * the last scene object created before init-device is the default scene graph.
//
// The pieces, one file each: definitions.h (what is stored), builder_impl.h (reading the calls,
// references, cache), frame_changes.cpp (setparam / set-parameter), scene_files.cpp (files named
// by a scene), cache_keys.cpp, device_assembly.h (one device -> render jobs), scene_actions.cpp
// (calc-ray, calc-proj-ray, gvs-print, gvs-print-motion).
#include "scene/builder.h"

#include <sstream>

#include "scene/builder_impl.h"
#include "scene/device_assembly.h"

namespace geovis {

SceneBuilder::SceneBuilder(SceneDescription scene, BuildOptions opts)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(opts))) {
  if (impl_->opts.supersample < 1)
    throw Error("--supersample: expected a positive number of samples, found " +
                std::to_string(impl_->opts.supersample));
  impl_->process();
}
SceneBuilder::~SceneBuilder() = default;
SceneBuilder::SceneBuilder(SceneBuilder&&) noexcept = default;
SceneBuilder& SceneBuilder::operator=(SceneBuilder&&) noexcept = default;

int SceneBuilder::device_count() const { return static_cast<int>(impl_->devices.size()); }
int SceneBuilder::action_count() const { return static_cast<int>(impl_->actions.size()); }

std::vector<FrameJob> SceneBuilder::build(int device) const {
  if (device < 0 || device >= device_count())
    throw Error("device " + std::to_string(device) + " does not exist: the scene has " +
                std::to_string(device_count()) + " device(s)" +
                (device_count() ? " (0 to " + std::to_string(device_count() - 1) + ")" : std::string()));
  DeviceBuild b(*impl_, impl_->devices[device]);
  auto jobs = b.build(device, nullptr);
  impl_->trim_cache();
  return jobs;
}

std::string SceneBuilder::summary() const {
  std::ostringstream os;
  const std::string name = impl_->scene.file.empty() ? std::string("(scene)") : impl_->scene.file;
  os << "scene:    " << name << "\n";
  if (impl_->devices.empty()) {
    os << "frames:   0 (the scene has no init-device)\n";
    return os.str();
  }
  DeviceInfo info;
  DeviceBuild b(*impl_, impl_->devices[0]);
  const auto jobs = b.build(0, &info);
  os << "metric:   " << info.metric_line << "\n";
  os << "observer: " << info.observer_line << "\n";
  os << "camera:   " << info.camera_line << "\n";
  os << "objects:  " << info.objects_line << "\n";
  os << "frames:   " << device_count() << (jobs.size() == 2 ? " (stereo: 2 images per frame)" : "") << "\n";
  if (!impl_->actions.empty()) os << "actions:  " << impl_->actions.size() << "\n";
  return os.str();
}

}  // namespace geovis
