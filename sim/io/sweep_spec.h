// A parameter sweep file (`vascsim-sweep/1`, docs/sweeps.md): a base scene, named by a path
// relative to the sweep file, and axes, each a JSON pointer into that scene with the values it
// takes (a list, or a range with a step or a count), combined as a product (every combination,
// the first axis varying slowest) or zipped (the i-th value of every axis together), optionally
// repeated, plus overrides applied to every run. Reading checks the file itself (errors name the
// file, the JSON pointer and what was expected); sweep_expand.h turns it into runs and checks
// every run's scene.
//
// Values stay JSON: each is held as compact JSON text ("4", "0.001", "\"fast\"", "true"), so an
// override can set a number, a string, a boolean or a whole object, and the io layer keeps
// nlohmann-json to itself.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace vascsim {

// The largest sweep a file may describe: a manifest of this many runs is a few tens of MB.
inline constexpr std::size_t kMaxSweepRuns = 100000;
// The largest sweep file read.
inline constexpr std::size_t kMaxSweepFileBytes = std::size_t(4) << 20;

struct SweepAxis {
  std::string pointer;              // JSON pointer into the scene, e.g. "/control/kp"
  std::vector<std::string> values;  // compact JSON text, in the order they are run
};

enum class SweepCombine { kProduct, kZip };

struct SweepSpec {
  std::string file;        // the sweep file as named (messages)
  std::string name;        // "name", or the sweep file's stem
  std::string scene;       // the base scene as written in the sweep file (relative to it)
  std::string scene_path;  // the base scene as a path usable from the working directory
  std::vector<SweepAxis> axes;  // in the order written
  std::vector<std::pair<std::string, std::string>> overrides;  // pointer, JSON text: every run
  SweepCombine combine = SweepCombine::kProduct;
  int repeats = 1;  // each combination run this many times (for timing; results are deterministic)
};

// Reads and checks a sweep file. Throws InputError naming the file, the JSON pointer and what
// was expected. Does not read the scene (expand_sweep does).
SweepSpec read_sweep_file(const std::string& path);
// The text of a sweep file, read once (at most the sweep file's size limit), for a caller that
// both parses it (read_sweep_text) and keeps it (the sweep directory's copy). Throws InputError.
std::string read_sweep_file_text(const std::string& path);
// As read_sweep_file, from text; `label` names it in messages and resolves the scene path.
SweepSpec read_sweep_text(const std::string& text, const std::string& label);
// Runs the spec describes: the product of the axes' lengths (or their common length when
// zipped), times repeats.
std::size_t sweep_run_count(const SweepSpec& spec);

}  // namespace vascsim
