// Where a result comes from: the vascsim version and git commit that made it, and a hash of the
// canonical scene it ran. Every summary.json and every frame log's metadata carry these, so a
// result can be traced to the code and the input (docs/frame-log.md).
#pragma once

#include <string>

namespace vascsim {

struct Provenance {
  std::string version;     // e.g. "0.1.0"
  std::string commit;      // `git describe --always --dirty` of the source tree at build time
  std::string scene_hash;  // scene_hash() of the canonical scene, or empty
};

// This build's version and commit, with the hash of `canonical_scene_json` (scene_to_json).
Provenance provenance_of(const std::string& canonical_scene_json);
// "vascsim 0.1.0 (commit 1a2b3c4d5e6f)".
std::string version_line();
// FNV-1a, 64 bit, as 16 hex digits: tells two inputs apart and names one; not a security hash
// (nobody is trusted or refused by it), so no cryptographic library is pulled into sim/.
std::string scene_hash(const std::string& canonical_scene_json);

}  // namespace vascsim
