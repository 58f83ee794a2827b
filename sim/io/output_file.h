// Safe output: nothing a user wrote is overwritten without --force, and no half-written file ever
// stands under its final name (write to a temporary sibling, then rename, which is atomic on POSIX).
#pragma once

#include <string>
#include <vector>

namespace vascsim {

// Throws InputError if `path` exists and `overwrite` is false, or if its directory does not exist.
void check_output_path(const std::string& path, bool overwrite, const std::string& option_hint = "--force");
// check_output_path, and also, whatever `overwrite` says: `path` must not be anything but a
// regular file (a device, a directory, a socket is never replaced) and must not be one of
// `inputs` (an output never replaces what it is computed from).
void check_replaceable_output(const std::string& path, bool overwrite, const std::vector<std::string>& inputs,
                              const std::string& option_hint = "--force");
// Writes `content` to a temporary file beside `path`, then renames it over `path`.
// Throws InputError (naming the path and the system's reason) on failure, leaving nothing behind.
void write_file_atomically(const std::string& path, const std::string& content);
// A temporary sibling name for `path` ("<dir>/.<name>.tmp-<pid>"); rename it into place when complete.
std::string temporary_sibling(const std::string& path);

}  // namespace vascsim
