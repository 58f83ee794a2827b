#include "sim/io/output_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>

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

DirectoryLock::DirectoryLock(const std::string& dir) {
  fd_ = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw InputError(dir + ": cannot open the directory to lock it (" + std::strerror(errno) + ")");
  int result;
  while ((result = ::flock(fd_, LOCK_EX)) != 0 && errno == EINTR) {
  }
  if (result != 0) {
    const int e = errno;
    ::close(fd_);
    throw InputError(dir + ": cannot lock the directory (" + std::strerror(e) + ")");
  }
}

DirectoryLock::~DirectoryLock() { ::close(fd_); }

namespace {

// A write lock on all of a file, as F_OFD_SETLK takes it and F_OFD_GETLK asks about it.
struct flock whole_file_lock() {
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  lock.l_start = 0;
  lock.l_len = 0;  // to the end, however long
  lock.l_pid = 0;  // OFD locks require it
  return lock;
}

}  // namespace

RunDirectoryClaim::RunDirectoryClaim(const std::string& dir) : path_((fs::path(dir) / kFileName).string()) {
  // A run that ends removes its claim's file: one that opened it just before may lock the removed
  // file, so the lock counts only if the name still leads to the file locked.
  for (int attempt = 0; attempt < 3; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) throw InputError(dir + ": cannot claim the directory for this run (" + path_ + ": " + std::strerror(errno) + ")");
    struct flock whole = whole_file_lock();
    int result;
    while ((result = ::fcntl(fd_, F_OFD_SETLK, &whole)) != 0 && errno == EINTR) {
    }
    if (result != 0) {
      const int e = errno;
      ::close(fd_);
      fd_ = -1;
      if (e == EAGAIN || e == EACCES)
        throw InputError(dir + ": another vascsim run is writing into this directory; wait for it, or choose another --out");
      throw InputError(dir + ": cannot claim the directory for this run (" + std::strerror(e) + ")");
    }
    struct stat locked {}, named {};
    if (::fstat(fd_, &locked) == 0 && ::stat(path_.c_str(), &named) == 0 && locked.st_ino == named.st_ino &&
        locked.st_dev == named.st_dev) {
      guard_ = std::make_unique<RemovedOnSignal>(path_);
      return;
    }
    ::close(fd_);
    fd_ = -1;
  }
  throw InputError(dir + ": cannot claim the directory for this run (other runs keep starting and ending in it)");
}

RunDirectoryClaim::~RunDirectoryClaim() {
  ::unlink(path_.c_str());  // before the lock goes, so a waiting run finds the name free or its own
  ::close(fd_);
}

RunDirectoryClaim::Holder RunDirectoryClaim::holder(const std::string& dir) {
  const std::string path = (fs::path(dir) / kFileName).string();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return errno == ENOENT ? Holder::kNoClaim : Holder::kUnknown;
  struct flock probe = whole_file_lock();
  const int result = ::fcntl(fd, F_OFD_GETLK, &probe);
  ::close(fd);
  if (result != 0) return Holder::kUnknown;
  return probe.l_type == F_UNLCK ? Holder::kAbandoned : Holder::kRun;
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

namespace {

// This machine's name, as temporary names carry it (the pid follows the last '-', so a host
// name with '-' in it parses too).
const std::string& host_name() {
  static const std::string name = [] {
    char buffer[256] = {};
    if (::gethostname(buffer, sizeof buffer - 1) != 0 || !buffer[0]) return std::string("localhost");
    return std::string(buffer);
  }();
  return name;
}

// The pid of a temporary name of `name`'s form ".<output>.tmp-<host>-<pid>" written on this
// host, or 0 if `name` is not one.
pid_t temporary_owner(const std::string& name) {
  const std::string marker = ".tmp-" + host_name() + "-";
  const std::size_t at = name.rfind(marker);
  if (name.size() < 2 || name[0] != '.' || at == std::string::npos || at == 0) return 0;
  const std::string digits = name.substr(at + marker.size());
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return 0;
  return static_cast<pid_t>(std::stol(digits));
}

bool process_runs(pid_t pid) { return ::kill(pid, 0) == 0 || errno == EPERM; }

}  // namespace

std::string temporary_sibling(const std::string& path) {
  const fs::path p(path);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp-" + host_name() + "-" + std::to_string(::getpid())))
      .string();
}

std::size_t remove_stale_temporaries(const std::string& dir) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(dir.empty() ? "." : dir, ec), end; !ec && it != end; it.increment(ec)) {
    const pid_t owner = temporary_owner(it->path().filename().string());
    if (owner > 0 && owner != ::getpid() && !process_runs(owner) && it->is_regular_file(ec)) stale.push_back(it->path());
  }
  std::size_t removed = 0;
  for (const auto& p : stale) removed += fs::remove(p, ec);
  return removed;
}

bool temporary_in_use(const std::string& path) {
  const fs::path p(path);
  const std::string prefix = "." + p.filename().string() + ".tmp-";
  std::error_code ec;
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const pid_t owner = temporary_owner(name);
    if (owner > 0 && process_runs(owner)) return true;
  }
  return false;
}

namespace {

// Writes `content` to `tmp`, `path`'s temporary name, flushed to the disk. Throws InputError
// naming `path`, leaving nothing behind.
void write_temporary(const std::string& tmp, const std::string& path, const std::string& content) {
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw InputError(path + ": cannot write (" + std::strerror(errno) + ")");
  // Flushed to the disk before the rename: after a power cut the final name holds the old
  // content or the new, never an empty file.
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size() && std::fflush(f) == 0 &&
                       ::fsync(fileno(f)) == 0;
  const int saved_errno = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed) {
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot write (" + std::strerror(written ? errno : saved_errno) + ")");
  }
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int e = errno;
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot write (" + std::strerror(e) + ")");
  }
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_sibling(path);
  RemovedOnSignal guard(tmp);
  write_temporary(tmp, path, content);
  rename_into_place(tmp, path);
}

void OutputFileSet::add(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_sibling(path);
  auto guard = std::make_unique<RemovedOnSignal>(tmp);
  write_temporary(tmp, path, content);
  pending_.push_back({tmp, path, std::move(guard)});
}

void OutputFileSet::commit() {
  for (const Pending& p : pending_) rename_into_place(p.temporary, p.final);
  pending_.clear();
}

OutputFileSet::~OutputFileSet() {
  for (const Pending& p : pending_) std::remove(p.temporary.c_str());
}

namespace {

// The names RemovedOnSignal guards, in fixed storage a signal handler may read: a slot is free
// (0), being filled or emptied (1), or holds a name to remove (2).
struct GuardedName {
  std::atomic<int> state{0};
  char path[4096];
};
GuardedName g_guarded[64];
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};

// NoticeOnSignal's message, in the same kind of storage: set (2) or not.
struct Notice {
  std::atomic<int> state{0};
  char text[1024];
  std::size_t size = 0;
};
Notice g_notice;

extern "C" void remove_guarded_names(int signal) {
  for (GuardedName& g : g_guarded)
    if (g.state.load() == 2) ::unlink(g.path);  // async-signal-safe
  if (g_notice.state.load() == 2) {
    const ssize_t written = ::write(STDERR_FILENO, g_notice.text, g_notice.size);  // async-signal-safe
    (void)written;
  }
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

// Only where the signal would end the process: a program that handles one itself (the replay
// server's Ctrl-C, a sweep stopping its runs) goes on after it, and its temporaries with it.
void install_cleanup_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int signal : kCleanupSignals) {
      struct sigaction before {};
      ::sigaction(signal, nullptr, &before);
      if ((before.sa_flags & SA_SIGINFO) || before.sa_handler != SIG_DFL) continue;
      struct sigaction ours {};
      ours.sa_handler = remove_guarded_names;
      sigemptyset(&ours.sa_mask);
      ::sigaction(signal, &ours, nullptr);
    }
  });
}

}  // namespace

void RemovedOnSignal::install_handlers() { install_cleanup_handlers(); }

RemovedOnSignal::RemovedOnSignal(const std::string& path) {
  if (path.size() >= sizeof g_guarded[0].path) return;
  install_cleanup_handlers();
  for (int k = 0; k < 64; ++k) {
    int free = 0;
    if (!g_guarded[k].state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(g_guarded[k].path, path.c_str(), path.size() + 1);
    g_guarded[k].state.store(2);
    slot_ = k;
    return;
  }
}

RemovedOnSignal::~RemovedOnSignal() {
  if (slot_ >= 0) g_guarded[slot_].state.store(0);
}

NoticeOnSignal::NoticeOnSignal(const std::string& message) {
  install_cleanup_handlers();
  g_notice.state.store(1);
  const std::string text = message.substr(0, sizeof g_notice.text - 2) + "\n";
  std::memcpy(g_notice.text, text.data(), text.size());
  g_notice.size = text.size();
  g_notice.state.store(2);
}

NoticeOnSignal::~NoticeOnSignal() { g_notice.state.store(0); }

}  // namespace vascsim
