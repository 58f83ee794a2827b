// The replay page's files (apps/replay/assets/), compiled into the executable by
// apps/replay/embed_assets.cmake so the server works offline and never reads from disk.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vascsim::replay {

struct EmbeddedAsset {
  std::string name;          // file name, e.g. "replay.js"
  const unsigned char* data;
  std::size_t size;
};

const std::vector<EmbeddedAsset>& embedded_assets();

}  // namespace vascsim::replay
