#include "apps/sweep/run_process.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <climits>
#include <cstring>
#include <filesystem>
#include <vector>

#include "sim/io/output_file.h"
#include "sim/io/sweep_outcome.h"
#include "sim/scene/input_error.h"

namespace vascsim::sweep {

namespace fs = std::filesystem;

std::string vascsim_executable() {
  char path[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) throw InputError(std::string("cannot find the vascsim executable (/proc/self/exe: ") + std::strerror(errno) + ")");
  return std::string(path, static_cast<std::size_t>(n));
}

RunProcess::RunProcess(RunProcess&& o) noexcept { *this = std::move(o); }

RunProcess& RunProcess::operator=(RunProcess&& o) noexcept {
  if (this == &o) return *this;
  if (lock_fd_ >= 0) ::close(lock_fd_);
  sweep_dir_ = std::move(o.sweep_dir_), run_dir_ = std::move(o.run_dir_), id_ = std::move(o.id_);
  index_ = o.index_, lock_fd_ = o.lock_fd_, pid_ = o.pid_, start_ = o.start_;
  o.lock_fd_ = -1, o.pid_ = -1;
  return *this;
}

RunProcess::~RunProcess() {
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

bool RunProcess::lock(const SweepDirectory& sweep, std::size_t index) {
  sweep_dir_ = sweep.dir;
  index_ = index;
  id_ = sweep.manifest.runs.at(index).id;
  run_dir_ = run_directory(sweep, index);
  const std::string path = run_dir_ + "/.lock";
  // O_CLOEXEC: only the run started for this entry keeps the lock (start()), no other child.
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    ::close(fd);
    if (e == EWOULDBLOCK) return false;
    throw InputError(path + ": cannot lock (" + std::strerror(e) + ")");
  }
  lock_fd_ = fd;
  return true;
}

void RunProcess::start(const std::string& exe, const std::function<int(int, char**)>& run_command) {
  std::error_code ec;
  fs::remove(fs::path(run_dir_) / "status.json", ec);
  // Paths relative to the sweep directory: the child starts there.
  const std::string out = "runs/" + id_;
  std::vector<std::string> args = {exe, "run", run_scene_path(id_), "--out", out, "--force", "--quiet"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string log = out + "/run.log";
  start_ = std::chrono::steady_clock::now();
  std::fflush(nullptr);  // nothing buffered in the sweep may be written twice
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw InputError(std::string("cannot start a vascsim run process (fork: ") + std::strerror(errno) + ")");
  if (pid == 0) {
    // The child. The sweep's handlers would only set its stop flag: a run stops on SIGINT and
    // SIGTERM as `vascsim run` does.
    for (int signal : {SIGINT, SIGTERM, SIGALRM}) std::signal(signal, SIG_DFL);
    // A sweep killed with SIGKILL cannot stop its runs: the kernel does (SIGTERM, which a run
    // obeys as on Ctrl-C). Without this, a resumed sweep would start the same entry beside the
    // orphan still writing it. The parent may have died before the request took effect.
    if (::prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || ::getppid() != parent) ::_exit(143);
    if (::chdir(sweep_dir_.c_str()) != 0) ::_exit(126);
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = ::open("/dev/null", O_RDONLY);
    if (fd < 0 || null < 0) ::_exit(126);
    ::dup2(null, STDIN_FILENO);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    // The run holds its own lock (as descriptor 3, kept across exec) for as long as it runs,
    // also if the sweep is gone. Every other descriptor is the sweep's: above all the locks of
    // the other running runs, which this child must not keep held after they end.
    if (::dup2(lock_fd_, 3) != 3 || ::fcntl(3, F_SETFD, 0) != 0) ::_exit(126);
    ::close_range(4, ~0U, 0);
    if (run_command) {
      const int code = run_command(static_cast<int>(args.size()), argv.data());
      std::fflush(nullptr);
      ::_exit(code);  // not exit(): the sweep's static objects belong to the sweep
    }
    ::execv(exe.c_str(), argv.data());
    const char message[] = "vascsim sweep: cannot execute the vascsim executable\n";
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, message, sizeof message - 1);
    ::_exit(127);
  }
  pid_ = pid;
}

double RunProcess::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void RunProcess::finish(int wait_status, double cpu_time, bool interrupted) {
  std::string failure;
  if (!interrupted) {
    RunStatusRecord s;
    if (WIFSIGNALED(wait_status)) s.signal = WTERMSIG(wait_status);
    else s.exit_code = WEXITSTATUS(wait_status);
    s.wall_time = elapsed();
    s.cpu_time = cpu_time;
    char host[256] = {0};
    if (::gethostname(host, sizeof host - 1) == 0) s.host = host;
    try {
      write_file_atomically(run_dir_ + "/status.json", run_status_json(s));
    } catch (const InputError& e) {
      // On a full disk the run's own message (its run.log) is lost as well: say how it ended.
      const bool ok = s.exit_code == 0 && s.signal == 0;
      failure = "run " + id_ + (s.signal ? " was killed by signal " + std::to_string(s.signal)
                                         : " ended with exit code " + std::to_string(s.exit_code)) +
                (ok ? "" : " (its own message may be lost too: " + run_dir_ + "/run.log)") +
                ", and its status could not be recorded: " + e.what() +
                "; it counts as not run, and running the sweep again repeats it";
    }
  }
  pid_ = -1;
  if (lock_fd_ >= 0) ::close(lock_fd_);
  lock_fd_ = -1;
  if (!failure.empty()) throw InputError(failure);
}

}  // namespace vascsim::sweep
