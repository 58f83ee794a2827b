#include "tests/cli_test_support.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace vascsim::test {

namespace {

CommandResult run_vascsim_via(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  CommandResult result;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("popen failed for " + command);
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

}  // namespace

CommandResult run_shell(const std::string& command_line) { return run_vascsim_via(command_line); }

CommandResult run_vascsim(const std::string& arguments) {
  return run_vascsim_via(std::string(VASCSIM_EXE) + " " + arguments);
}

CommandResult run_vascsim_killed_after(const std::string& arguments, double seconds) {
  // coreutils timeout sends the signal to the command itself, as a user's kill -9 would.
  return run_vascsim_via("timeout -s KILL " + std::to_string(seconds) + " " + std::string(VASCSIM_EXE) + " " + arguments);
}

pid_t start_vascsim(const std::vector<std::string>& arguments, const StartOptions& options) {
  std::vector<std::string> words = {VASCSIM_EXE};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    if (options.own_process_group) ::setsid();
    if (options.ignored_signal) std::signal(options.ignored_signal, SIG_IGN);  // kept across exec
    const int file = ::open(options.output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(file, STDOUT_FILENO);
    ::dup2(file, STDERR_FILENO);
    ::execv(VASCSIM_EXE, argv.data());
    ::_exit(127);
  }
  return pid;
}

bool wait_for_files(const std::vector<std::string>& paths, double seconds) {
  const auto all_there = [&] {
    for (const std::string& path : paths)
      if (!std::filesystem::exists(path)) return false;
    return true;
  };
  for (int k = 0; k < static_cast<int>(seconds * 100) && !all_there(); ++k) ::usleep(10000);
  return all_there();
}

std::string fresh_temp_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("vascsim_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + path);
}

std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string source_path(const std::string& relative) { return std::string(VASCSIM_SOURCE_DIR) + "/" + relative; }

}  // namespace vascsim::test
