// The summary table `vascsim sweep` prints (apps/sweep/sweep_merge.h): nothing in it is cut, long
// axis values (objects) get a short name in their row and appear in full below, and the goal
// column counts the completed runs.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "apps/sweep/sweep_merge.h"
#include "sim/io/sweep_manifest.h"
#include "sim/io/sweep_results.h"

namespace vascsim::sweep {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(SweepSummaryTable, ShowsLongPointersObjectValuesAndWideFiguresWhole) {
  const std::string pointer = "/vessels/segments/3/stenosis/severity_fraction";
  const std::string object = R"({"centre":[0.01,0.002],"radius":0.004,"wall":{"stiffness":20000,"damping":0.5}})";
  SweepManifest m;
  m.name = "long";
  m.scene = "s.json";
  m.axes = {{pointer, {"0.25", object, "\"x\""}}};
  for (std::size_t i = 0; i < 3; ++i) m.runs.push_back({i, sweep_run_id(i, 3), 0, {m.axes[0].values[i]}, ""});
  std::vector<RunOutcome> o(3);
  for (auto& x : o) x.metrics.assign(kMetricCount, NAN);
  o[0].status = "done", o[0].metrics[kTipErrorRms] = -1.23456e5, o[0].metrics[kGoalTime] = 12.5,
              o[0].metrics[kGoalReached] = 1;
  o[1].status = "done", o[1].metrics[kTipErrorRms] = 0.002;
  // o[2] is missing.
  const std::string table = summary_table(m, o, SweepKind{true, true, false});
  const auto lines = lines_of(table);
  ASSERT_GE(lines.size(), 7u) << table;
  EXPECT_EQ(table.find("..."), std::string::npos) << "a cell was cut:\n" << table;
  EXPECT_EQ(lines[2].rfind(pointer + "  runs", 0), 0u) << table;
  // The figure (mm) in full: mean, min and max of one run.
  EXPECT_TRUE(has(table, "-1.23e+08 [-1.23e+08, -1.23e+08]")) << table;
  // The object is named in its row and given whole below the table.
  EXPECT_EQ(lines[5].rfind("value 2 ", 0), 0u) << table;
  EXPECT_TRUE(has(table, "\n  value 2: " + object + "\n")) << table;
  EXPECT_EQ(lines[4].rfind("0.25 ", 0), 0u) << table;
  EXPECT_EQ(lines[6].rfind("x ", 0), 0u) << table;
  // Columns line up: every row's second column starts where the header's does.
  const std::size_t runs_column = lines[2].find("runs");
  for (std::size_t k = 4; k <= 6; ++k) EXPECT_NE(lines[k][runs_column], ' ') << k << "\n" << table;
  for (std::size_t k = 4; k <= 6; ++k) EXPECT_EQ(lines[k][runs_column - 1], ' ') << k << "\n" << table;
  // Goals over the completed runs; none completed is "-", not 0/1.
  const std::size_t goal_column = lines[2].find("goal");
  EXPECT_EQ(lines[4].substr(goal_column, 4), "1/1 ") << table;
  EXPECT_EQ(lines[5].substr(goal_column, 4), "0/1 ") << table;
  EXPECT_EQ(lines[6].substr(goal_column, 2), "- ") << table;
}

}  // namespace
}  // namespace vascsim::sweep
