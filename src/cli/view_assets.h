// The page of `geovis view` (web/: TypeScript, WebGL2, three.js), built with npm when geovis is
// configured and embedded in the binary as byte arrays (cmake/embed_assets.cmake writes the
// definitions), so that nothing is loaded from elsewhere at run time.
#pragma once

#include <cstddef>
#include <span>

namespace geovis::cli {

struct ViewAsset {
  const char* path;  ///< URL path, e.g. "/index.html", "/assets/index-1a2b.js"
  const unsigned char* data;
  std::size_t size;
};

/// The page's files; empty when the page was not built.
std::span<const ViewAsset> view_assets();

/// Why the page was not built (npm missing, build failed, ...); "" when it was.
const char* view_page_missing_reason();

}  // namespace geovis::cli
