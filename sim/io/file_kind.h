// What a vascsim JSON file is, from its "format", for the error a file of one kind given where
// another was expected gets: `vascsim run` of the maze that `vascsim maze` wrote, `vascsim sweep`
// of a scene. The message then says what the file is and what to do with it, not only that its
// format is not the one expected. Internal to the io layer, like json_fields.h (it includes
// nlohmann-json).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace vascsim::io {

// "a maze written by `vascsim maze` ...": what a file whose "format" is `format` is and how it is
// used instead; empty for a format vascsim does not write (or not a string).
std::string file_kind_hint(const nlohmann::json& format);

// Throws InputError "LABEL: /format: expected "EXPECTED", got "OTHER": HINT" (the hint where
// file_kind_hint gives one) unless `root`'s "format" is `expected`; an absent "format" is left to
// the caller (scenes may omit it, sweeps may not).
void check_format(const nlohmann::json& root, const std::string& expected, const std::string& label);

}  // namespace vascsim::io
