// Helpers for the sweep tests: a small sweep file over the default maze scene, and results.csv
// read back as cells (RFC 4180 quoting) with its timing columns cut off, so the tables of two
// engines can be compared byte for byte where they must agree.
#pragma once

#include <string>
#include <vector>

#include "tests/cli_test_support.h"

namespace vascsim::test {

// The axes of the test sweep: two gains by four maze seeds, 8 runs.
inline const char* const kAxes = R"({"/control/kp": [2, 4], "/maze/seed": {"from": 1, "to": 4}})";

inline bool has(const std::string& text, const std::string& needle) { return text.find(needle) != std::string::npos; }

// `vascsim sweep ARGUMENTS`.
inline CommandResult sweep_command(const std::string& arguments) { return run_vascsim("sweep " + arguments); }

// Writes DIR/NAME.json: scenes/maze_default.json with `axes` (a JSON object text) and
// run.duration `duration` s, and returns its path. `extra` is added to the top-level object.
std::string write_maze_sweep(const std::string& dir, const std::string& name, const std::string& axes, double duration,
                             const std::string& extra = "");
std::vector<std::vector<std::string>> parse_csv(const std::string& text);
// results.csv without the timing columns (the last five), one line per row, cells joined by ','
// as written (quoted again where needed).
std::string deterministic_columns(const std::string& csv_text);
// The cell of `column` (by header name) in data row `row` (0 = the first run).
std::string csv_cell(const std::string& csv_text, std::size_t row, const std::string& column);

}  // namespace vascsim::test
