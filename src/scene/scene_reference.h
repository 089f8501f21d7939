// The scene reference (docs/scene-reference.md): every command of the scene language, every type
// its `type` key accepts, and every key with its type and one-line doc — written from the command
// table (command_table.h) and the registries it points to, so it cannot drift from the code.
#pragma once

#include <string>

namespace geovis {

/// The whole reference as Markdown (`geovis reference` prints or writes it).
std::string scene_reference_markdown();

}  // namespace geovis
