#include "cli/render_outputs.h"

#include <cstdint>
#include <filesystem>
#include <system_error>

#include "core/error.h"
#include "core/hash.h"
#include "io/atomic_file.h"
#include "io/image.h"

namespace geovis::cli {

namespace fs = std::filesystem;

std::string settings_description(const std::vector<std::string>& settings) {
  // Each part is followed by its length so that ("ab", "c") and ("a", "bc") differ.
  std::uint64_t h = kFnv1a64Seed;
  for (const std::string& s : settings) {
    const std::uint64_t size = s.size();
    h = fnv1a64(s.data(), s.size(), h);
    h = fnv1a64(&size, sizeof size, h);
  }
  return "geovis-settings " + fnv1a64_text(h);
}

ResumeCheck check_resume(const std::string& path, int width, int height, const std::string& description) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return {};
  const ImageFileCheck c = check_image_file(path);
  if (!c.readable) return {false, c.problem};
  if (c.width != width || c.height != height)
    return {false, "\"" + path + "\" is " + std::to_string(c.width) + "x" + std::to_string(c.height) + ", expected " +
                       std::to_string(width) + "x" + std::to_string(height)};
  if (c.description.rfind("geovis-settings ", 0) != 0)
    return {false, "\"" + path + "\" has no geovis settings hash (not written by geovis render)"};
  if (c.description != description)
    return {false,
            "\"" + path + "\" was written with other settings (scene file, --define, --res or --supersample changed)"};
  return {true, {}};
}

std::vector<std::string> prepare_output_folder(const std::string& folder) {
  const std::string f = folder.empty() ? std::string(".") : folder;
  std::error_code ec;
  fs::create_directories(f, ec);
  if (ec) throw Error("cannot create the output folder \"" + f + "\": " + ec.message());
  check_folder_writable(f);
  return remove_stale_temporaries(f);
}

}  // namespace geovis::cli
