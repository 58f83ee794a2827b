#include "apps/replay/bookmarks.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/replay/request_params.h"
#include "sim/io/json_fields.h"
#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"

namespace vascsim::replay {

using nlohmann::json;

namespace {
constexpr std::size_t kMaxBookmarks = 10000;

// 1..200 characters (UTF-8 code points, as the page's input counts them; the JSON reader has
// checked the encoding), not all spaces, no control characters.
bool readable_name(const std::string& name) {
  std::size_t characters = 0;
  bool visible = false;
  for (const unsigned char c : name) {
    if ((c & 0xC0) != 0x80) ++characters;  // not a continuation byte
    if (c < 0x20 || c == 0x7F) return false;
    if (c != ' ') visible = true;
  }
  return characters >= 1 && characters <= 200 && visible;
}

// The whole file: other tools (or a later version) may keep their own keys beside "bookmarks",
// and adding a bookmark keeps them.
json load_bookmark_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return json{{"format", "vascsim-bookmarks/1"}, {"bookmarks", json::array()}};
  if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) > (16u << 20))
    throw InputError(path + ": not a bookmarks file (not a regular file of at most 16 MB); left untouched");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  json doc;
  try {
    doc = io::parse_json_strictly(text.str(), path);
  } catch (const InputError&) {
    throw InputError(path + ": not a vascsim-bookmarks/1 file; left untouched");
  }
  if (!doc.is_object() || doc.value("format", "") != "vascsim-bookmarks/1" ||
      !doc.contains("bookmarks") || !doc["bookmarks"].is_array())
    throw InputError(path + ": not a vascsim-bookmarks/1 file; left untouched");
  return doc;
}

}  // namespace

json load_bookmarks(const std::string& path) { return load_bookmark_file(path)["bookmarks"]; }

json add_bookmark(const std::string& path, const json& b) {
  if (!b.is_object()) throw ParamError("body", "expected a JSON object {\"name\", \"t\", \"view\"}");
  if (!b.contains("name") || !b["name"].is_string() || !readable_name(b["name"].get<std::string>()))
    throw ParamError("name", "expected a string of 1..200 characters, not only spaces, without control characters");
  if (!b.contains("t") || !b["t"].is_number() || !(std::abs(b["t"].get<double>()) <= 1e12))
    throw ParamError("t", "expected a time in seconds within [-1e12, 1e12], as /api/frame.png takes it");
  if (b.contains("view") && (!b["view"].is_string() || b["view"].get<std::string>().size() > 4096))
    throw ParamError("view", "expected a string of at most 4096 characters");
  // Another server on this run may add one at the same moment: read, add and write in turn.
  const DirectoryLock lock(std::filesystem::path(path).parent_path().string());
  json doc = load_bookmark_file(path);
  json& list = doc["bookmarks"];
  if (list.size() >= kMaxBookmarks) throw ParamError("name", "this run already has 10000 bookmarks");
  list.push_back({{"name", b["name"]}, {"t", b["t"]}, {"view", b.value("view", "")}});
  write_file_atomically(path, doc.dump(2) + "\n");
  return list;
}

}  // namespace vascsim::replay
