#include "scene/scene_files.h"

#include <filesystem>

#include "core/error.h"
#include "io/image.h"

namespace geovis::scene_build {

// ---- files named by the scene -------------------------------------------------------------------

/// GeoViS scenes name their texture images and meshes by paths of the author's machine
/// (`(string-append (getenv "HOME") "/local/Texturen/...")`, or "examples/eso0932a.tif" relative
/// to the folder GeoViS was started in). When `name` exists neither as given nor relative to a
/// search folder, the file of the same name in a search folder (scene folder, --texture-path,
/// working folder) is used instead; returns that path, or "" when there is none (the factory then
/// reports the file as missing, listing every place searched).
std::string find_by_file_name(const std::string& name, const std::vector<std::string>& dirs) {
  namespace fs = std::filesystem;
  try {
    (void)find_file(name, dirs);
    return "";  // found as given: nothing to substitute
  } catch (const Error&) {
  }
  const fs::path file = fs::path(name).filename();
  if (file.empty()) return "";
  std::error_code ec;
  for (const auto& dir : dirs) {
    const fs::path c = fs::path(dir) / file;
    if (fs::is_regular_file(c, ec)) return c.string();
  }
  return "";
}

/// `ps` with its image file (init-texture Image) or mesh file (mesh-obj) replaced by the file of
/// the same name in a search folder when the named one does not exist (find_by_file_name), with
/// a warning saying so. Otherwise `ps` unchanged.
ParamSet with_files_found(const ParamSet& ps, const std::vector<std::string>& dirs, Diagnostics* diag) {
  const std::string& cmd = ps.command();
  std::string key, name;
  if (cmd == "init-texture" && to_lower(ps.get_string("type", std::string())) == "image") {
    const Param* p = ps.find("file");
    if (!p || !p->value.is_string()) return ps;
    key = "file";
    name = std::get<std::string>(p->value.v);
  } else if (cmd == "mesh-obj") {
    const Param* p = ps.find("filename");
    if (!p || !p->value.is_string()) return ps;
    const Param* d = ps.find("pathname");
    const std::string dir = d && d->value.is_string() ? std::get<std::string>(d->value.v) : std::string();
    key = "filename";
    name = dir.empty() ? std::get<std::string>(p->value.v) : dir + "/" + std::get<std::string>(p->value.v);
  } else {
    return ps;
  }
  const std::string found = find_by_file_name(name, dirs);
  if (found.empty()) return ps;
  ParamSet out = ps;
  const SourceLoc loc = ps.find(key)->loc;
  out.set(key, Value(found), loc);
  if (cmd == "mesh-obj") out.set("pathname", Value(std::string()), loc);
  if (diag)
    diag->warn(loc, cmd, key,
               "\"" + name + "\" does not exist; using \"" + found + "\" (the file of that name in a search folder)");
  return out;
}

}  // namespace geovis::scene_build
