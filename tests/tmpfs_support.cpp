#include "tests/tmpfs_support.h"

#include <sys/mount.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace vascsim::test {

namespace fs = std::filesystem;

SmallTmpfs::SmallTmpfs(const std::string& name, std::size_t bytes)
    : path_((fs::temp_directory_path() / ("vascsim_tmpfs_" + std::to_string(::getpid()) + "_" + name)).string()) {
  std::error_code ec;
  fs::remove_all(path_, ec);
  fs::create_directories(path_, ec);
  const std::string options = "size=" + std::to_string(bytes) + ",mode=0755";
  if (::mount("tmpfs", path_.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, options.c_str()) != 0) {
    const int e = errno;
    error_ = "cannot mount a " + std::to_string(bytes) + "-byte tmpfs on " + path_ + ": " + std::strerror(e) +
             (::geteuid() != 0 ? " (this test needs root, as CI runs it)" : "");
    return;
  }
  mounted_ = true;
}

SmallTmpfs::~SmallTmpfs() {
  if (mounted_) ::umount2(path_.c_str(), MNT_DETACH);
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::size_t SmallTmpfs::free_bytes() const {
  struct statvfs s {};
  if (::statvfs(path_.c_str(), &s) != 0) return 0;
  return static_cast<std::size_t>(s.f_bavail) * s.f_frsize;
}

}  // namespace vascsim::test
