// Files a scene names (texture images, meshes): GeoViS scenes name them by paths of the author's
// machine, so a path that does not exist here is looked up by its file name in the search folders.
#pragma once

#include <string>
#include <vector>

#include "core/params.h"

namespace geovis::scene_build {

/// The first file called like `name`'s file name in `dirs` ("" when none).
std::string find_by_file_name(const std::string& name, const std::vector<std::string>& dirs);
/// `ps` with its texture image or mesh file replaced by the one found in `dirs` (warning in `diag`).
ParamSet with_files_found(const ParamSet& ps, const std::vector<std::string>& dirs, Diagnostics* diag);

}  // namespace geovis::scene_build
