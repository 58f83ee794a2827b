#include "sim/io/output_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "sim/scene/input_error.h"

namespace vascsim {

namespace fs = std::filesystem;

void check_output_path(const std::string& path, bool overwrite, const std::string& option_hint) {
  std::error_code ec;
  if (fs::exists(path, ec) && !overwrite)
    throw InputError(path + ": already exists (pass " + option_hint + " to overwrite it)");
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    throw InputError(path + ": directory " + parent.string() + " does not exist");
}

void check_replaceable_output(const std::string& path, bool overwrite, const std::vector<std::string>& inputs,
                              const std::string& option_hint) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(path + ": exists and is not a regular file; refusing to replace it");
  for (const auto& input : inputs)
    if (fs::exists(path, ec) && fs::equivalent(path, input, ec))
      throw InputError(path + ": is the input " + input + "; refusing to write over it");
  check_output_path(path, overwrite, option_hint);
}

std::string temporary_sibling(const std::string& path) {
  const fs::path p(path);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp-" + std::to_string(::getpid()))).string();
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_sibling(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw InputError(path + ": cannot write (" + std::strerror(errno) + ")");
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  const int saved_errno = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed) {
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot write (" + std::strerror(written ? errno : saved_errno) + ")");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int e = errno;
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot write (" + std::strerror(e) + ")");
  }
}

}  // namespace vascsim
