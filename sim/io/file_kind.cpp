#include "sim/io/file_kind.h"

#include "sim/io/json_fields.h"
#include "sim/scene/input_error.h"

namespace vascsim::io {

std::string file_kind_hint(const nlohmann::json& format) {
  if (!format.is_string()) return "";
  const std::string f = format.get<std::string>();
  if (f == "vascsim-scene/1")
    return "it is a scene: `vascsim run FILE --out DIR` runs it, and a sweep names it in its \"scene\" (docs/sweeps.md)";
  if (f == "vascsim-maze/1")
    return "it is a maze written by `vascsim maze` for inspection; a scene makes its maze from the settings in its "
           "\"maze\" section (this file's /scene/maze holds them; docs/scenes.md)";
  if (f == "vascsim-vessels/1")
    return "it is a vessel network written by `vascsim vessels` for inspection; a scene describes its vessels in its "
           "\"vessels\" section (this file's /scene/vessels holds it; docs/scenes.md)";
  if (f == "vascsim-sweep/1") return "it is a sweep: `vascsim sweep FILE --out DIR` runs it (docs/sweeps.md)";
  if (f == "vascsim-summary/1") return "it is the summary.json of a run, written by `vascsim run`";
  if (f == "vascsim-sweep-manifest/1" || f == "vascsim-sweep-results/1" || f == "vascsim-sweep-status/1")
    return "it is a file of a sweep's directory, written by `vascsim sweep`";
  if (f == "vascsim-bookmarks/1") return "it is the bookmarks.json of a run, written by `vascsim replay`";
  return "";
}

void check_format(const nlohmann::json& root, const std::string& expected, const std::string& label) {
  if (!root.is_object() || !root.contains("format") || root["format"] == expected) return;
  const nlohmann::json& got = root["format"];
  const std::string hint = file_kind_hint(got);
  throw InputError(label + ": /format: expected \"" + expected + "\", got " + describe(got) +
                   (hint.empty() ? "" : ": " + hint));
}

}  // namespace vascsim::io
