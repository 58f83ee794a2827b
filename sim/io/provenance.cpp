#include "sim/io/provenance.h"

#include <cstdint>
#include <cstdio>

#include "vascsim_build_info.h"

namespace vascsim {

std::string scene_hash(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a offset basis
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ull;  // FNV prime
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

Provenance provenance_of(const std::string& canonical_scene_json) {
  return {VASCSIM_VERSION, VASCSIM_COMMIT, canonical_scene_json.empty() ? "" : scene_hash(canonical_scene_json)};
}

std::string version_line() { return std::string("vascsim ") + VASCSIM_VERSION + " (commit " + VASCSIM_COMMIT + ")"; }

}  // namespace vascsim
