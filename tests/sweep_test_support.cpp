#include "tests/sweep_test_support.h"

#include <stdexcept>

#include "sim/io/sweep_results.h"
#include "tests/cli_test_support.h"

namespace vascsim::test {

std::string write_maze_sweep(const std::string& dir, const std::string& name, const std::string& axes, double duration,
                             const std::string& extra) {
  const std::string path = dir + "/" + name + ".json";
  write_text(path, R"({"format": "vascsim-sweep/1", "scene": ")" + source_path("scenes/maze_default.json") +
                       R"(", "axes": )" + axes + R"(, "overrides": {"/run/duration": )" + std::to_string(duration) + "}" +
                       extra + "}\n");
  return path;
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string cell;
  bool quoted = false, in_row = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    in_row = true;
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') cell += '"', ++i;
      else if (c == '"') quoted = false;
      else cell += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(cell), cell.clear();
    } else if (c == '\n') {
      row.push_back(cell), cell.clear();
      rows.push_back(row), row.clear();
      in_row = false;
    } else {
      cell += c;
    }
  }
  if (quoted) throw std::runtime_error("CSV ends inside a quoted cell");
  if (in_row) throw std::runtime_error("CSV does not end with a line break");
  return rows;
}

std::string deterministic_columns(const std::string& csv_text) {
  const std::size_t timing = sweep_timing_columns().size();
  std::string out;
  for (const auto& row : parse_csv(csv_text)) {
    if (row.size() < timing) throw std::runtime_error("a results.csv row with fewer cells than the timing columns");
    for (std::size_t i = 0; i + timing < row.size(); ++i) {
      const std::string& c = row[i];
      const bool quote = c.find_first_of(",\"\n") != std::string::npos;
      out += (i ? "," : "") + (quote ? "\"" + c + "\"" : c);
    }
    out += "\n";
  }
  return out;
}

std::string csv_cell(const std::string& csv_text, std::size_t row, const std::string& column) {
  const auto rows = parse_csv(csv_text);
  for (std::size_t i = 0; i < rows.at(0).size(); ++i)
    if (rows[0][i] == column) return rows.at(row + 1).at(i);
  throw std::runtime_error("results.csv has no column " + column);
}

}  // namespace vascsim::test
