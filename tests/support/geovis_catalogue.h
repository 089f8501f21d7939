// The GeoViS reference (docs/geovis-catalogue.md) read by tests that compare our
// scene language with the original's.
#pragma once

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace geovis::testing_support {

/// The command names of the catalogue's §1 command table (every `name` in its first column; the
/// tables of later sections and of §1's subsections are not part of it). Empty when the catalogue
/// cannot be read.
inline std::vector<std::string> catalogue_commands() {
  std::ifstream in(std::filesystem::path(GEOVIS_SOURCE_DIR) / "docs" / "geovis-catalogue.md");
  std::vector<std::string> out;
  bool in_table = false;
  static const std::regex name("`([a-z0-9-]+)`");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## 1.", 0) == 0)
      in_table = true;
    else if (line.rfind("## ", 0) == 0 || line.rfind("### ", 0) == 0)
      in_table = false;
    if (!in_table || line.rfind("| `", 0) != 0) continue;
    const std::string first = line.substr(1, line.find('|', 1) - 1);
    for (std::sregex_iterator it(first.begin(), first.end(), name), end; it != end; ++it) out.push_back((*it)[1]);
  }
  return out;
}

}  // namespace geovis::testing_support
