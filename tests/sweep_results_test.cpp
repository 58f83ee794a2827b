// What a sweep reads back from a run's directory and tabulates (sim/io/sweep_outcome.h,
// sim/io/sweep_results.h): done, failed and missing runs from summary.json and status.json,
// a corrupt summary a failure that says so, CSV quoting, the timing columns last, the per-axis
// summary over the other axes.
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <nlohmann/json.hpp>
#include <string>

#include "sim/io/sweep_manifest.h"
#include "sim/io/sweep_outcome.h"
#include "sim/io/sweep_results.h"
#include "tests/cli_test_support.h"
#include "tests/sweep_test_support.h"

namespace vascsim {
namespace {

const char* const kSummary = R"({"format": "vascsim-summary/1", "ok": true, "failure": null, "steps": 300,
  "rejected_steps": 1, "newton_iterations": {"total": 301, "mean": 1.0, "max": 2}, "wall_time": 0.25,
  "real_time_factor": 1.2, "navigation": {"goal_reached": true, "goal_time": 12.5, "tip_error_rms": 0.001,
  "tip_error_max": 0.002, "actuation_force_max": 0.003, "contact_force_max": 0.0, "max_penetration": 0.0}})";

TEST(SweepOutcome, TellsDoneFailedAndMissingRunsApart) {
  const std::string dir = test::fresh_temp_dir("sweep_outcome");
  EXPECT_EQ(read_run_outcome(dir).status, "missing");

  test::write_text(dir + "/summary.json", kSummary);
  RunOutcome done = read_run_outcome(dir);
  EXPECT_EQ(done.status, "done");
  EXPECT_EQ(done.metrics[kGoalReached], 1.0);
  EXPECT_EQ(done.metrics[kGoalTime], 12.5);
  EXPECT_EQ(done.metrics[kNewtonIterations], 301.0);
  EXPECT_EQ(done.metrics[kRejectedSteps], 1.0);
  EXPECT_EQ(done.wall_time, 0.25);
  EXPECT_FALSE(done.has_status);

  std::string failed = kSummary;
  const std::string ok = "\"ok\": true, \"failure\": null";
  failed.replace(failed.find(ok), ok.size(), "\"ok\": false, \"failure\": \"Newton diverged at t = 3\"");
  test::write_text(dir + "/summary.json", failed);
  EXPECT_EQ(read_run_outcome(dir).status, "failed");
  EXPECT_EQ(read_run_outcome(dir).failure, "Newton diverged at t = 3");

  test::write_text(dir + "/summary.json", "{\"format\": \"vascsim-summary/1\", \"ok\": tru");
  const RunOutcome corrupt = read_run_outcome(dir);
  EXPECT_EQ(corrupt.status, "failed");
  EXPECT_NE(corrupt.failure.find("unreadable summary: " + dir + "/summary.json: not valid JSON"), std::string::npos) << corrupt.failure;

  // No summary: the process's end, from status.json, says why.
  std::remove((dir + "/summary.json").c_str());
  RunStatusRecord killed;
  killed.signal = SIGKILL;
  killed.wall_time = 1.5;
  test::write_text(dir + "/status.json", run_status_json(killed));
  const RunOutcome k = read_run_outcome(dir);
  EXPECT_EQ(k.status, "failed");
  EXPECT_EQ(k.failure, "vascsim run was killed by signal 9 (Killed)");
  EXPECT_EQ(k.process.wall_time, 1.5);
  RunStatusRecord refused;
  refused.exit_code = 2;
  test::write_text(dir + "/status.json", run_status_json(refused));
  test::write_text(dir + "/run.log", "vascsim run: runs/0001/scene.json: /maze/rows: expected an integer\n\n");
  EXPECT_EQ(read_run_outcome(dir).failure,
            "vascsim run exited with code 2: vascsim run: runs/0001/scene.json: /maze/rows: expected an integer");
  test::write_text(dir + "/status.json", "garbage");
  EXPECT_EQ(read_run_outcome(dir).status, "missing") << "an unreadable status says nothing";
}

// A run stopped by a signal writes a summary that says so (/stopped_by). Stopped by the sweep
// itself (which then records no status.json: its Ctrl-C, Slurm's SIGTERM to the whole job, the
// kernel's after the sweep was killed), it was not run to its end and is run again on resume, as
// before runs wrote such a summary; stopped by a signal the sweep saw end it (someone killed that
// one run), it failed, and says who stopped it.
TEST(SweepOutcome, ARunStoppedBySignalIsMissingUnlessTheSweepSawItEnd) {
  const std::string dir = test::fresh_temp_dir("sweep_outcome_stopped");
  std::string stopped = kSummary;
  const std::string ok = "\"ok\": true, \"failure\": null";
  stopped.replace(stopped.find(ok), ok.size(),
                  "\"ok\": false, \"failure\": \"stopped by SIGTERM at t = 2.5 s, before the run's end (30 s)\", "
                  "\"stopped_by\": \"SIGTERM\"");
  test::write_text(dir + "/summary.json", stopped);
  const RunOutcome by_sweep = read_run_outcome(dir);
  EXPECT_EQ(by_sweep.status, "missing");
  EXPECT_EQ(by_sweep.failure, "");
  EXPECT_TRUE(std::isnan(by_sweep.metrics[kGoalTime])) << "a stopped run's figures are not results";
  RunStatusRecord killed;
  killed.signal = SIGTERM;
  test::write_text(dir + "/status.json", run_status_json(killed));
  const RunOutcome by_someone = read_run_outcome(dir);
  EXPECT_EQ(by_someone.status, "failed");
  EXPECT_EQ(by_someone.failure, "stopped by SIGTERM at t = 2.5 s, before the run's end (30 s)");
}

TEST(SweepResults, OneRowPerRunQuotedTimingLastAndSummariesOverTheOtherAxes) {
  SweepManifest m;
  m.name = "t";
  m.scene = "s.json";
  m.axes = {{"/control/kp", {"2", "4"}}, {"/solver/preset", {"\"fast\"", "\"a, b\""}}};
  for (std::size_t i = 0; i < 4; ++i) m.runs.push_back({i, sweep_run_id(i, 4), 0, {m.axes[0].values[i / 2], m.axes[1].values[i % 2]}, ""});
  std::vector<RunOutcome> o(4);
  for (auto& x : o) x.metrics.assign(kMetricCount, NAN);
  o[0].status = "done", o[0].metrics[kTipErrorRms] = 0.001, o[0].metrics[kSteps] = 10, o[0].wall_time = 0.5;
  o[1].status = "done", o[1].metrics[kTipErrorRms] = 0.003, o[1].metrics[kSteps] = 10;
  o[2].status = "failed", o[2].failure = "it said \"no\", twice";
  o[2].has_status = true, o[2].process.host = "node7", o[2].process.wall_time = 2;
  const std::string csv = sweep_results_csv(m, o);
  const auto rows = test::parse_csv(csv);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0][3], "/control/kp");
  EXPECT_EQ(rows[0].back(), "host");
  EXPECT_EQ(rows[0][rows[0].size() - 5], "wall_time_s");
  EXPECT_EQ(rows[2][4], "a, b");
  EXPECT_EQ(test::csv_cell(csv, 0, "tip_error_rms_m"), "0.001");
  EXPECT_EQ(test::csv_cell(csv, 0, "steps"), "10");
  EXPECT_EQ(test::csv_cell(csv, 0, "wall_time_s"), "0.5");
  EXPECT_EQ(test::csv_cell(csv, 2, "failure"), "it said \"no\", twice");
  EXPECT_EQ(test::csv_cell(csv, 2, "host"), "node7");
  EXPECT_EQ(test::csv_cell(csv, 3, "status"), "missing");
  EXPECT_NE(csv.find("\"it said \"\"no\"\", twice\""), std::string::npos) << csv;

  const auto axes = summarise_sweep(m, o);
  ASSERT_EQ(axes.size(), 2u);
  const SweepValueSummary& kp2 = axes[0].values[0];
  EXPECT_EQ(kp2.runs, 2u);
  EXPECT_EQ(kp2.done, 2u);
  EXPECT_DOUBLE_EQ(kp2.mean[kTipErrorRms], 0.002);
  EXPECT_DOUBLE_EQ(kp2.min[kTipErrorRms], 0.001);
  EXPECT_DOUBLE_EQ(kp2.max[kTipErrorRms], 0.003);
  const SweepValueSummary& kp4 = axes[0].values[1];
  EXPECT_EQ(kp4.failed, 1u);
  EXPECT_EQ(kp4.missing, 1u);
  EXPECT_TRUE(std::isnan(kp4.mean[kTipErrorRms]));
  const std::string json = sweep_results_json(m, o);
  EXPECT_NE(json.find("\"counts\": {\n    \"runs\": 4,\n    \"done\": 2,\n    \"failed\": 1,\n    \"missing\": 1"), std::string::npos) << json;
  // Counts are integers in results.json as in results.csv ("steps": 10.0 before).
  const auto parsed = nlohmann::json::parse(json);
  EXPECT_TRUE(parsed["runs"][0]["steps"].is_number_integer()) << parsed["runs"][0].dump();
  EXPECT_TRUE(parsed["runs"][0]["tip_error_rms_m"].is_number_float());
  EXPECT_TRUE(parsed["per_axis"][0]["values"][0]["steps"]["max"].is_number_integer());
}

// A zipped axis that repeats a value (and 2 beside 2.0): one summary row per distinct value,
// holding all its runs (each row claimed the runs of both before).
TEST(SweepResults, AValueRepeatedOnAZippedAxisIsOneSummaryRow) {
  SweepManifest m;
  m.name = "t";
  m.scene = "s.json";
  m.axes = {{"/control/kp", {"2", "4", "2.0"}}, {"/maze/seed", {"1", "2", "3"}}};
  for (std::size_t i = 0; i < 3; ++i) m.runs.push_back({i, sweep_run_id(i, 3), 0, {m.axes[0].values[i], m.axes[1].values[i]}, ""});
  std::vector<RunOutcome> o(3);
  for (auto& x : o) x.metrics.assign(kMetricCount, NAN), x.status = "done";
  o[0].metrics[kTipErrorRms] = 0.001, o[1].metrics[kTipErrorRms] = 0.005, o[2].metrics[kTipErrorRms] = 0.003;
  const auto axes = summarise_sweep(m, o);
  ASSERT_EQ(axes[0].values.size(), 2u);
  EXPECT_EQ(axes[0].values[0].value, "2");
  EXPECT_EQ(axes[0].values[0].runs, 2u);
  EXPECT_DOUBLE_EQ(axes[0].values[0].mean[kTipErrorRms], 0.002);
  EXPECT_EQ(axes[0].values[1].runs, 1u);
  EXPECT_EQ(axes[1].values.size(), 3u);
}

}  // namespace
}  // namespace vascsim
