// The commands that draw (render, diff, replay, run --render, sweep merge with its plots, bench
// render and replay) run in vascsim-render: the same command line, linked with the renderer.
// vascsim itself is not, because OSMesa (with LLVM) and libav* bring about 130 shared libraries
// that take 40-100 ms and 75 MB to load, which every `vascsim run` that GNU parallel or a Slurm
// array starts would pay for a run that may take 50 ms. vascsim finds vascsim-render next to
// itself (a build tree) or in ../libexec/vascsim (an installation, cmake/install.cmake) and
// hands it the command line. A build without the renderer has neither.
#pragma once

#include <string>
#include <vector>

namespace vascsim::cli {

// Where vascsim-render is; throws InputError naming the places looked in if it is in none.
std::string renderer_program();
// Replaces this process by vascsim-render with the same arguments (argv as main got it); the
// exit code is then vascsim-render's. Returns only by throwing InputError.
[[noreturn]] int run_in_renderer(int argc, char** argv);
// Runs vascsim-render with `args` (without the program name) as a child sharing this process's
// standard streams and returns its exit code (128 + N if signal N ended it).
int run_renderer_child(const std::vector<std::string>& args);

}  // namespace vascsim::cli
