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
constexpr std::size_t kMaxBookmarkBytes = 64 * 1024;

// 1..200 characters (UTF-8 code points, as the page's input counts them; the JSON reader has
// checked the encoding), not all spaces (Unicode's too: a name of no-break spaces shows as
// nothing), no control characters.
bool readable_name(const std::string& name) {
  std::size_t characters = 0;
  bool visible = false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if ((c & 0xC0) == 0x80) continue;  // a continuation byte
    ++characters;
    if (c < 0x20 || c == 0x7F) return false;
    // The code point, from its lead byte and continuation bytes.
    const int length = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
    char32_t code = length == 1 ? c : c & (0x7F >> length);
    for (int k = 1; k < length && i + k < name.size(); ++k) code = code << 6 | (static_cast<unsigned char>(name[i + k]) & 0x3F);
    const bool space = code == U' ' || code == 0xA0 || code == 0x1680 || (code >= 0x2000 && code <= 0x200B) ||
                       code == 0x2028 || code == 0x2029 || code == 0x202F || code == 0x205F || code == 0x3000 || code == 0xFEFF;
    if (!space) visible = true;
  }
  return characters >= 1 && characters <= 200 && visible;
}

// The whole file: other tools (or a later version) may keep their own keys beside "bookmarks",
// and adding a bookmark keeps them.
json load_bookmark_file(const std::string& path, std::string* text_read = nullptr) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return json{{"format", "vascsim-bookmarks/1"}, {"bookmarks", json::array()}};
  if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) > (16u << 20))
    throw InputError(path + ": not a bookmarks file (not a regular file of at most 16 MiB); left untouched");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (text_read) *text_read = text.str();
  json doc;
  try {
    doc = io::parse_json_strictly(text.str(), path);
  } catch (const InputError& e) {
    // The reader's message names the file and where the JSON breaks.
    throw InputError(std::string(e.what()) + " (not a vascsim-bookmarks/1 file; left untouched)");
  }
  const auto refuse = [&](const std::string& what) {
    throw InputError(path + ": " + what + " (not a vascsim-bookmarks/1 file; left untouched)");
  };
  if (!doc.is_object()) refuse("expected a JSON object");
  if (doc.value("format", "") != "vascsim-bookmarks/1") refuse("/format: expected \"vascsim-bookmarks/1\"");
  if (!doc.contains("bookmarks") || !doc["bookmarks"].is_array()) refuse("/bookmarks: expected an array");
  return doc;
}

// What is wrong with bookmark `b`, naming its field (empty if nothing). One rule for a posted
// bookmark and for those a file holds: the page shows and seeks to what the file says.
std::string bookmark_problem(const json& b, std::string& field) {
  const auto wrong = [&field](const char* name, const char* expected) {
    field = name;
    return std::string(expected);
  };
  if (!b.is_object()) return wrong("", "expected a JSON object {\"name\", \"t\", \"view\"}");
  if (!b.contains("name") || !b["name"].is_string() || !readable_name(b["name"].get<std::string>()))
    return wrong("name", "expected a string of 1..200 characters, not only spaces, without control characters");
  if (!b.contains("t") || !b["t"].is_number() || !(std::abs(b["t"].get<double>()) <= 1e12))
    return wrong("t", "expected a time in seconds within [-1e12, 1e12], as /api/frame.png takes it");
  if (b.contains("view") && (!b["view"].is_string() || b["view"].get<std::string>().size() > 4096))
    return wrong("view", "expected a string of at most 4096 characters");
  // Keys of the page's own or another tool's are kept, within reason for a file read whole.
  if (b.dump().size() > kMaxBookmarkBytes) return wrong("", "expected a bookmark of at most 64 kB as JSON");
  field.clear();
  return "";
}

// The file's bookmarks, each checked: a hand-edited entry the page cannot show is named.
json checked_bookmarks(const std::string& path, const json& doc) {
  const json& list = doc["bookmarks"];
  for (std::size_t k = 0; k < list.size(); ++k) {
    std::string field;
    if (const std::string problem = bookmark_problem(list[k], field); !problem.empty())
      throw InputError(path + ": /bookmarks/" + std::to_string(k) + (field.empty() ? "" : "/" + field) + ": " + problem +
                       "; left untouched");
  }
  return list;
}

}  // namespace

json load_bookmarks(const std::string& path) { return checked_bookmarks(path, load_bookmark_file(path)); }

json add_bookmark(const std::string& path, const json& b) {
  std::string field;
  if (const std::string problem = bookmark_problem(b, field); !problem.empty())
    throw ParamError(field.empty() ? "body" : field, problem);
  // Another server on this run may add one at the same moment: read, add and write in turn.
  const DirectoryLock lock(std::filesystem::path(path).parent_path().string());
  std::string text;
  json doc = load_bookmark_file(path, &text);
  checked_bookmarks(path, doc);
  // The file is written back whole: a number it would change is refused, not rounded.
  if (const std::string inexact = io::first_inexact_number(text); !inexact.empty())
    throw InputError(path + ": " + inexact + ": more digits than vascsim can write back (a 64-bit integer or a double); "
                     "left untouched (write it as a string to add bookmarks here)");
  json& list = doc["bookmarks"];
  if (list.size() >= kMaxBookmarks) throw ParamError("name", "this run already has 10000 bookmarks");
  json entry = b;
  entry["view"] = b.value("view", "");
  list.push_back(std::move(entry));
  write_file_atomically(path, doc.dump(2) + "\n");
  return list;
}

}  // namespace vascsim::replay
