// Cache keys of built artefacts: a definition's parameters and changes serialised exactly (a
// metric, object or texture built once is reused by every frame whose key is the same).
#pragma once

#include <string>
#include <vector>

#include "core/params.h"

namespace geovis::scene_build {

/// Every entry of `ps` and then `changes`, with numbers written exactly (hex floats).
std::string serialize(const ParamSet& ps, const std::vector<Param>& changes = {});

}  // namespace geovis::scene_build
