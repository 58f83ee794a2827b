#include "apps/vascsim/renderer_program.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "apps/sweep/run_process.h"
#include "sim/scene/input_error.h"

extern char** environ;

namespace vascsim::cli {

namespace fs = std::filesystem;

#ifndef VASCSIM_RENDER_PROGRAM_FROM_BIN
#define VASCSIM_RENDER_PROGRAM_FROM_BIN "../libexec/vascsim"
#endif

std::string renderer_program() {
  const fs::path here = fs::path(sweep::vascsim_executable()).parent_path();
  const fs::path candidates[] = {here / "vascsim-render", here / VASCSIM_RENDER_PROGRAM_FROM_BIN / "vascsim-render"};
  for (const fs::path& candidate : candidates)
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.lexically_normal().string();
  throw InputError("this command draws, and vascsim-render, the program that draws, is in neither " +
                   candidates[0].string() + " nor " + candidates[1].lexically_normal().string() +
                   " (an incomplete installation?)");
}

int run_in_renderer(int argc, char** argv) {
  (void)argc;
  const std::string program = renderer_program();
  std::fflush(nullptr);  // what this process printed must not vanish with it
  ::execv(program.c_str(), argv);
  throw InputError("cannot start " + program + ": " + std::strerror(errno));
}

int run_renderer_child(const std::vector<std::string>& args) {
  const std::string program = renderer_program();
  std::fflush(nullptr);  // the child's output must come after what this process printed
  std::vector<std::string> owned = {"vascsim"};
  owned.insert(owned.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : owned) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int error = ::posix_spawn(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ);
  if (error != 0) throw InputError("cannot start " + program + ": " + std::strerror(error));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw InputError("lost " + program + ": " + std::strerror(errno));
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace vascsim::cli
