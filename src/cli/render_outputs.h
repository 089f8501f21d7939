// The output side of `geovis render`: the output folder is checked before anything is rendered,
// and --resume skips a frame only if its image is complete, has the requested resolution and was
// written with the same scene settings (a hash stored in the image's description).
#pragma once

#include <string>
#include <vector>

namespace geovis::cli {

/// "geovis-settings fnv1a64:<16 hex digits>": a hash of everything that determines the pixels
/// (the scene text, --define, --res, --supersample, ...), stored in each image written.
std::string settings_description(const std::vector<std::string>& settings);

/// Whether --resume may skip the image `path`: only when it decodes completely, is width x height
/// and carries `description`. Otherwise `why` says why the frame is rendered again ("" when there
/// is no file at all).
struct ResumeCheck {
  bool skip = false;
  std::string why;
};
ResumeCheck check_resume(const std::string& path, int width, int height, const std::string& description);

/// Creates `folder` when missing, throws Error (folder and OS reason) when no file can be created
/// in it, and removes the temporary files killed runs left there. Returns the files removed.
std::vector<std::string> prepare_output_folder(const std::string& folder);

}  // namespace geovis::cli
