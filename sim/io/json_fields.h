// Internal to the io layer (includes nlohmann-json; never include it from sim/ or render/).
// FieldReader walks one JSON object of a scene file and validates each field as it is read, so
// every error names the file, the JSON pointer of the field and what was expected:
//   scenes/x.json: /maze/rows: expected an integer in [1, 200], got 0
// finish() then rejects any key that no one asked for (a typo must not be silently ignored),
// except in a file a newer vascsim may have written with keys this one does not know (a log's
// metadata): there the reader is made with UnknownKeys::kIgnore, which its nested readers keep.
#pragma once

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "sim/env/geometry.h"

namespace vascsim::io {

// A key as one reference token of a JSON pointer (RFC 6901): '~' is written "~0" and '/' "~1",
// so the key "/control/kp" of a sweep's axes is the token "~1control~1kp".
std::string escape_pointer_token(const std::string& key);

enum class UnknownKeys { kRefuse, kIgnore };

class FieldReader {
 public:
  // `object` must outlive the reader. Throws InputError if it is not a JSON object.
  FieldReader(const nlohmann::json& object, std::string file, std::string pointer,
              UnknownKeys unknown_keys = UnknownKeys::kRefuse);

  bool has(const std::string& key) const;
  // Optional fields: return `fallback` when absent, validate when present.
  double number(const std::string& key, double fallback, double min, double max);
  // As number(), but the bound is exclusive: (min, max].
  double positive(const std::string& key, double fallback, double max = 1e300);
  long long integer(const std::string& key, long long fallback, long long min, long long max);
  bool boolean(const std::string& key, bool fallback);
  std::string choice(const std::string& key, const std::string& fallback, const std::vector<std::string>& allowed);
  std::string text(const std::string& key, const std::string& fallback);
  // Each coordinate within [-max_abs, max_abs] (a position far from the origin leaves no digits
  // for the rod's edges; a huge force or acceleration overflows before the first step).
  Vec2 vec2(const std::string& key, const Vec2& fallback, double max_abs = 1e300);
  // A nested object: the returned reader is empty (every lookup falls back) when the key is absent.
  FieldReader object(const std::string& key);
  // A reader of `value` found at `key` below this object (an item of a list: "supports/0").
  FieldReader nested(const nlohmann::json& value, const std::string& key) const;
  // The raw value of a field that the caller validates itself, marking it as known.
  const nlohmann::json* raw(const std::string& key);
  // Throws for the first key not read by any accessor above (unless unknown keys are ignored).
  void finish() const;

  // `key` may be a path below this object ("pinned/0"): it is not escaped.
  std::string pointer_of(const std::string& key) const { return pointer_ + "/" + key; }
  [[noreturn]] void fail(const std::string& key, const std::string& expected, const nlohmann::json& got) const;
  const std::string& file() const { return file_; }

 private:
  const nlohmann::json* lookup(const std::string& key);

  const nlohmann::json* object_;  // null for an absent optional object
  std::string file_;
  std::string pointer_;
  UnknownKeys unknown_keys_;
  mutable std::set<std::string> known_;  // keys read or asked about (has)
};

// Short rendering of a JSON value for messages ("0", "\"abc\"", "an object", ...); never dumps
// a large or deep value.
std::string describe(const nlohmann::json& value);
// The first bytes of UTF-8 text, at most `max`, never ending inside a character: a shortened
// message stays valid UTF-8 (json::dump throws on text that is not).
std::string utf8_prefix(const std::string& text, std::size_t max);

// Deepest nesting a scene, a log's metadata or any file vascsim reads may have.
inline constexpr int kMaxJsonDepth = 64;
// Parses JSON read from `label` and refuses (InputError naming `label` and the JSON path) what
// the JSON library would accept silently or fail on badly: a key twice in one object (it keeps
// the last), a NUL byte (it stops reading there), nesting deeper than kMaxJsonDepth (messages
// and copies recurse), numbers beyond the double range.
nlohmann::json parse_json_strictly(const std::string& text, const std::string& label);
// The first number of the JSON `text` that the JSON library holds inexactly and so would write
// back changed (an integer beyond 64 bits, more significant digits than a double keeps), as
// "POINTER: NUMBER"; empty if none, or if `text` is not JSON. For files vascsim edits and writes
// back (bookmarks): what another tool keeps there must come back as it was written.
std::string first_inexact_number(const std::string& text);
// Formats a bound as the user would write it (0.1, 200, 1e+06).
std::string format_number(double value);

}  // namespace vascsim::io
