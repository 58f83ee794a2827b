// Safe output: nothing a user wrote is overwritten without --force, and no half-written file ever
// stands under its final name (write to a temporary sibling, then rename, which is atomic on POSIX).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
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

// While it lives, the temporary name `path` is removed if the process is ended by SIGINT,
// SIGTERM or SIGHUP (Ctrl-C, kill, a closed terminal), so a stopped render leaves nothing behind
// (it left its video's temporary for the next writer to find); the signal then ends the process
// as it would have. Signals the program handles or ignores itself are left to it. Up to 64 names
// at once (more are left to remove_stale_temporaries, as SIGKILL's always are).
class RemovedOnSignal {
 public:
  explicit RemovedOnSignal(const std::string& path);
  ~RemovedOnSignal();
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

  // Installs the removing handlers now rather than with the first name (once; not over a
  // signal handled or ignored already). A program that then handles these signals itself and
  // passes them on to the handlers it found (`vascsim run`'s StopOnSignal) calls it first, so
  // that names guarded later are still removed when it does.
  static void install_handlers();

 private:
  int slot_ = -1;
};

// While it lives, SIGINT, SIGTERM or SIGHUP (where they would end the process, as for
// RemovedOnSignal) first print `message` and a newline on stderr, so a user who stops a long
// step learns what it left (a sweep directory half written, say) instead of a silent exit.
// One notice at a time: a newer one replaces an older one until it ends.
class NoticeOnSignal {
 public:
  explicit NoticeOnSignal(const std::string& message);
  ~NoticeOnSignal();
  NoticeOnSignal(const NoticeOnSignal&) = delete;
  NoticeOnSignal& operator=(const NoticeOnSignal&) = delete;
};

// Files that appear together or not at all (the CSV files of one export): each is written under
// its temporary name as it is added, and commit() renames them all into place; destroyed before
// that, the set removes its temporaries, so an error halfway (a full disk) leaves none of them.
// Throws InputError naming the file that could not be written.
class OutputFileSet {
 public:
  OutputFileSet() = default;
  OutputFileSet(const OutputFileSet&) = delete;
  OutputFileSet& operator=(const OutputFileSet&) = delete;
  ~OutputFileSet();
  void add(const std::string& path, const std::string& content);
  void commit();

 private:
  struct Pending {
    std::string temporary, final;
    std::unique_ptr<RemovedOnSignal> guard;
  };
  std::vector<Pending> pending_;
};

// The claim of one `vascsim run` on its output directory, held for the object's life: a second
// run into the directory while the first writes is refused (two at once left one's log beside
// the other's summary). A lock of its own (an open file description lock, fcntl F_OFD_SETLK, on
// the hidden file DIR/.vascsim-run.lock, removed when the claim ends, also by Ctrl-C or kill;
// kill -9 leaves it, harmless), not DirectoryLock's: a replay server adding a bookmark to a live
// run must not wait for the run to end. An OFD lock rather than flock because it can be asked
// about without being taken (held()): a reader taking it, even briefly, would make a run starting
// at that moment refuse its directory. Throws InputError naming the directory if another process
// (or another claim in this one) holds it.
class RunDirectoryClaim {
 public:
  explicit RunDirectoryClaim(const std::string& dir);
  ~RunDirectoryClaim();
  RunDirectoryClaim(const RunDirectoryClaim&) = delete;
  RunDirectoryClaim& operator=(const RunDirectoryClaim&) = delete;
  // The claim's file name, which a run directory may hold beside a run's outputs.
  static constexpr const char* kFileName = ".vascsim-run.lock";

  // Whether a run holds the claim on `dir` now, that is whether a run is writing there:
  //   kRun        a run holds it;
  //   kNoClaim    no claim file: no run writes there (none did, or the last one ended);
  //   kAbandoned  the claim file with no run holding it: the run that made it was killed (kill -9,
  //               a crash, the machine out of memory) and did not end; it has no summary.json;
  //   kUnknown    the file system cannot say (one without locks, a file not ours to read).
  // Never throws.
  enum class Holder { kRun, kNoClaim, kAbandoned, kUnknown };
  static Holder holder(const std::string& dir);

 private:
  std::string path_;
  int fd_ = -1;
  std::unique_ptr<RemovedOnSignal> guard_;
};

// An exclusive lock on a directory (flock on the directory itself, so no lock file is left in
// it), held for the object's life: processes that choose or update files there (two replay
// servers numbering exports, adding bookmarks) take turns. Blocks until the lock is free.
// Throws InputError naming the directory if it cannot be opened or locked.
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::string& dir);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

// Temporary names. Every output (a video, each PNG, a summary) is written under a hidden name of
// its own, unique to the writing process, and renamed into place when complete:
//   <dir>/.<name>.tmp-<host>-<pid>
// Unique, so two processes writing the same output never write into one file (the last complete
// rename wins); hidden, so a process killed with SIGKILL (which no program can clean up after)
// leaves no file that looks like an output. What such a process left is removed by the next
// vascsim that writes into the same directory (remove_stale_temporaries): a temporary name is
// stale when its host is this machine and its pid no longer runs.
std::string temporary_sibling(const std::string& path);
// Removes the stale temporary files directly in `dir` (see above); returns how many. Files of
// other hosts (a shared file system) and of running processes are left alone. Never throws.
std::size_t remove_stale_temporaries(const std::string& dir);
// Whether a running process on this machine is writing `path` under a temporary name.
bool temporary_in_use(const std::string& path);


}  // namespace vascsim
