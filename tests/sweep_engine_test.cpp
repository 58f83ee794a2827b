// The same sweep on real engines, compared with the local run's table: GNU parallel (Debian
// `parallel`) with two job slots, and a one-node Slurm cluster started on this machine by
// scripts/slurm-local (Debian `slurm-wlm` and `munge`), the emitted array script submitted with
// sbatch and merged by its dependent job. Neither test skips: a missing tool or a cluster that
// does not start is a failure with the reason and, for Slurm, the daemons' logs.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "tests/cli_test_support.h"
#include "tests/sweep_test_support.h"

namespace vascsim::test {
namespace {

namespace fs = std::filesystem;

// The local engine's table for the test sweep, as the reference.
std::string local_table(const std::string& dir, const std::string& sweep) {
  const CommandResult r = sweep_command(sweep + " --out " + dir + "/local --jobs 2 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return deterministic_columns(read_text(dir + "/local/results.csv"));
}

TEST(SweepEngines, GnuParallelWithTwoSlotsGivesTheLocalTable) {
  const CommandResult tool = run_shell("parallel --version");
  ASSERT_EQ(tool.exit_code, 0) << "GNU parallel is needed (bash scripts/setup installs Debian's parallel): " << tool.output;
  const std::string dir = fresh_temp_dir("sweep_parallel");
  const std::string sweep = write_maze_sweep(dir, "kp", kAxes, 0.3);
  const std::string reference = local_table(dir, sweep);

  const std::string out = dir + "/parallel";
  const CommandResult emit = sweep_command(sweep + " --out " + out + " --emit gnu-parallel --jobs 2");
  ASSERT_EQ(emit.exit_code, 0) << emit.output;
  const CommandResult run = run_shell("sh " + out + "/parallel/run.sh </dev/null");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // parallel's joblog: a header and one line per entry, each exit value 0 (column 7).
  const std::string joblog = read_text(out + "/parallel/joblog");
  const auto rows = parse_csv([&] {
    std::string t = joblog;
    for (char& c : t) c = c == '\t' ? ',' : c;
    return t;
  }());
  ASSERT_EQ(rows.size(), 9u) << joblog;
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i].at(6), "0") << joblog;
  for (int i = 0; i < 8; ++i) EXPECT_TRUE(fs::exists(out + "/runs/000" + std::to_string(i) + "/summary.json")) << i;

  const CommandResult merge = sweep_command("merge " + out);
  ASSERT_EQ(merge.exit_code, 0) << merge.output;
  EXPECT_TRUE(has(merge.output, "8 runs: 8 done, 0 failed, 0 missing")) << merge.output;
  EXPECT_EQ(deterministic_columns(read_text(out + "/results.csv")), reference);

  // Running it again resumes: parallel skips what its joblog lists; nothing runs twice.
  const std::string summary = read_text(out + "/runs/0003/summary.json");
  const CommandResult again = run_shell("sh " + out + "/parallel/run.sh </dev/null");
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read_text(out + "/parallel/joblog"), joblog);
  EXPECT_EQ(read_text(out + "/runs/0003/summary.json"), summary);
}

// Starts the one-node cluster in `state` and stops it (by its daemons' pids) when it goes.
class LocalSlurm {
 public:
  explicit LocalSlurm(const std::string& state) : state_(state) {
    const CommandResult r = run_shell("bash " + source_path("scripts/slurm-local") + " start " + state_ + " </dev/null");
    output_ = r.output;
    up_ = r.exit_code == 0;
    if (up_) ::setenv("SLURM_CONF", (state_ + "/slurm.conf").c_str(), 1);
  }
  ~LocalSlurm() {
    const CommandResult r = run_shell("bash " + source_path("scripts/slurm-local") + " stop " + state_ + " </dev/null");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    ::unsetenv("SLURM_CONF");
  }
  bool up() const { return up_; }
  const std::string& output() const { return output_; }
  std::string logs() const { return run_shell("bash " + source_path("scripts/slurm-local") + " logs " + state_).output; }

 private:
  std::string state_, output_;
  bool up_ = false;
};

// The value after `label` on its line of `text` ("merge job: 12" -> "12").
std::string value_after(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  if (at == std::string::npos) return "";
  const auto end = text.find('\n', at);
  return text.substr(at + label.size(), end == std::string::npos ? std::string::npos : end - at - label.size());
}

TEST(SweepEngines, SlurmArrayAndMergeJobGiveTheLocalTable) {
  for (const char* tool : {"sbatch", "squeue", "scontrol", "slurmctld", "slurmd", "munged"})
    ASSERT_EQ(run_shell(std::string("command -v ") + tool).exit_code, 0)
        << tool << " is needed (bash scripts/setup installs Debian's slurm-wlm and munge)";
  const std::string dir = fresh_temp_dir("sweep_slurm");
  const LocalSlurm cluster(dir + "/cluster");
  ASSERT_TRUE(cluster.up()) << "the local Slurm cluster did not start:\n" << cluster.output();

  const std::string sweep = write_maze_sweep(dir, "kp", kAxes, 0.3);
  const std::string reference = local_table(dir, sweep);
  const std::string out = dir + "/slurm";
  const CommandResult emit = sweep_command(sweep + " --out " + out + " --emit slurm --max-parallel 2");
  ASSERT_EQ(emit.exit_code, 0) << emit.output;
  const CommandResult submit = run_shell("bash " + out + "/slurm/submit.sh </dev/null");
  ASSERT_EQ(submit.exit_code, 0) << submit.output << "\n" << cluster.logs();
  const std::string array = value_after(submit.output, "array jobs: "), merge = value_after(submit.output, "merge job: ");
  ASSERT_FALSE(array.empty()) << submit.output;
  ASSERT_FALSE(merge.empty()) << submit.output;

  // Until neither job is pending or running (squeue lists only those), at most 10 minutes.
  const auto start = std::chrono::steady_clock::now();
  std::string queue;
  while (true) {
    const CommandResult q = run_shell("squeue -h -j " + array + "," + merge);
    ASSERT_EQ(q.exit_code, 0) << q.output << "\n" << cluster.logs();
    queue = q.output;
    if (queue.find_first_not_of(" \n") == std::string::npos) break;
    ASSERT_LT(std::chrono::steady_clock::now() - start, std::chrono::minutes(10))
        << "the jobs did not end:\n" << queue << "\n" << cluster.logs();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  const CommandResult state = run_shell("scontrol show job -o " + merge);
  EXPECT_TRUE(has(state.output, "JobState=COMPLETED")) << state.output << "\n" << cluster.logs();
  const CommandResult tasks = run_shell("scontrol show job -o " + array);
  for (int i = 0; i < 8; ++i) EXPECT_TRUE(has(tasks.output, "ArrayTaskId=" + std::to_string(i) + " ")) << tasks.output;
  EXPECT_FALSE(has(tasks.output, "JobState=FAILED")) << tasks.output;
  for (int i = 0; i < 8; ++i) EXPECT_TRUE(fs::exists(out + "/runs/000" + std::to_string(i) + "/summary.json")) << i;
  ASSERT_TRUE(fs::exists(out + "/results.csv")) << "the merge job wrote no results.csv\n" << cluster.logs();
  EXPECT_EQ(deterministic_columns(read_text(out + "/results.csv")), reference);
#ifdef VASCSIM_HAVE_RENDER
  EXPECT_TRUE(fs::exists(out + "/plots/control_kp.png")) << "the merge job draws the figures";
#endif
}

}  // namespace
}  // namespace vascsim::test
