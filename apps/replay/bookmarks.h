// Bookmarks of a replayed run: a named time and view, kept in RUN_DIR/bookmarks.json
// ({"format": "vascsim-bookmarks/1", "bookmarks": [{"name", "t", "view"}]}). Saved atomically
// (temporary sibling, then rename), and a file that is not ours is never overwritten.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace vascsim::replay {

// The bookmarks array of `path`; empty if the file does not exist. Throws InputError if it
// exists but is not a bookmarks file, or holds a bookmark that is not valid (naming it by JSON
// pointer).
nlohmann::json load_bookmarks(const std::string& path);
// Validates `bookmark` ({"name": 1..200 chars, "t": finite, "view": <= 4096 chars}, other keys
// kept, 64 kB at most), appends it, saves and returns the new array. Throws ParamError for a bad
// bookmark, InputError for a file that cannot be read or written.
nlohmann::json add_bookmark(const std::string& path, const nlohmann::json& bookmark);

}  // namespace vascsim::replay
