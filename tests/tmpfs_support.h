// A small tmpfs mounted for one test (needs root, as CI runs), so that a command can be made to
// run out of disk space for real: the kernel's ENOSPC, not a simulated one. Mounting is the
// test's precondition, not an option: if it fails the test fails with the reason (a skipped
// disk-full test would be a check that silently never runs).
#pragma once

#include <cstddef>
#include <string>

namespace vascsim::test {

class SmallTmpfs {
 public:
  // Mounts a tmpfs of `bytes` (rounded up to pages) on a fresh directory named after `name`.
  // ok() tells whether it worked; error() says why not (the mount(2) error, and whether the
  // process is root).
  SmallTmpfs(const std::string& name, std::size_t bytes);
  // Unmounts (lazily, so an open file cannot keep it) and removes the directory, always.
  ~SmallTmpfs();
  SmallTmpfs(const SmallTmpfs&) = delete;
  SmallTmpfs& operator=(const SmallTmpfs&) = delete;

  bool ok() const { return mounted_; }
  const std::string& error() const { return error_; }
  const std::string& path() const { return path_; }
  // Bytes still free on it (statvfs).
  std::size_t free_bytes() const;

 private:
  std::string path_, error_;
  bool mounted_ = false;
};

}  // namespace vascsim::test
