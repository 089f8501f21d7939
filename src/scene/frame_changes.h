// Per-frame changes of definitions: setparam of init-device / set-changeobj and set-parameter
// (docs/geovis-catalogue.md §10). Which names a definition accepts comes from the command table.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/definitions.h"

namespace geovis::scene_build {

/// ParamSet key a setparam name changes (GeoViS uses a few names that differ from the keys).
std::string setparam_key(const std::string& command, const std::string& name);
/// Names a change may set for `d`; `any` = every parameter of its type (metrics, cameras).
std::vector<std::string> settable_names(const Def& d, bool& any);
/// Applies one change to a copy of `d`; `where` is the command making it (for the error location).
DefPtr apply_change(const DefPtr& d, const std::string& name, const Value& value, const SourceLoc& loc,
                    const ParamSet& where, std::string_view key_for_errors);

}  // namespace geovis::scene_build
