// Temporary output names (sim/io/output_file.h): hidden, unique to the process, and removed by
// the next writer into the directory once their process is gone, so a `kill -9` leaves nothing
// that looks like an output and nothing that blocks the next one.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"
#include "tests/cli_test_support.h"

namespace vascsim {
namespace {

namespace fs = std::filesystem;

// The pid of a process that has exited and been reaped: no process runs under it.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

// `path`'s temporary name as process `pid` on this host would have it.
std::string temporary_of(const std::string& path, pid_t pid) {
  const std::string mine = temporary_sibling(path), own = std::to_string(::getpid());
  return mine.substr(0, mine.size() - own.size()) + std::to_string(pid);
}

void touch(const std::string& path) { std::ofstream(path) << "partial"; }

TEST(OutputFile, TemporaryNameIsHiddenBesideTheOutputAndNamesHostAndPid) {
  const std::string t = temporary_sibling("/some/dir/out.mp4");
  EXPECT_EQ(t.rfind("/some/dir/.out.mp4.tmp-", 0), 0u) << t;
  EXPECT_EQ(t.substr(t.rfind('-') + 1), std::to_string(::getpid())) << t;
}

TEST(OutputFile, StaleTemporariesOfDeadProcessesAreRemovedOthersKept) {
  const std::string dir = test::fresh_temp_dir("stale_temporaries");
  const std::string out = dir + "/out.mp4";
  const std::string stale = temporary_of(out, dead_pid());
  const std::string stale_frame = temporary_of(dir + "/frame_000003.png", dead_pid());
  const std::string running = temporary_of(out, ::getppid());  // the test's parent runs
  const std::string other_host = dir + "/.out.mp4.tmp-another-host-" + std::to_string(dead_pid());
  const std::string lookalike = dir + "/out.mp4.tmp-1";  // not hidden: not ours
  for (const auto& p : {stale, stale_frame, running, other_host, lookalike, out}) touch(p);
  EXPECT_TRUE(temporary_in_use(out));  // `running`
  EXPECT_EQ(remove_stale_temporaries(dir), 2u);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_FALSE(fs::exists(stale_frame));
  for (const auto& p : {running, other_host, lookalike, out}) EXPECT_TRUE(fs::exists(p)) << p;
  fs::remove(running);
  EXPECT_FALSE(temporary_in_use(out)) << "only another host's leftover remains";
  EXPECT_EQ(remove_stale_temporaries(dir + "/no_such_dir"), 0u);
  fs::remove_all(dir);
}

// A run directory holding only what a stopped render left under temporary names is empty to the
// next run (it was refused as "not empty" without --force, though the leftovers are no one's).
TEST(OutputFile, ARunDirectoryHoldingOnlyStaleTemporariesIsEmptyToTheNextRun) {
  const std::string dir = test::fresh_temp_dir("stale_run_dir");
  test::write_text(dir + "/scene.json", R"({"maze": null, "rod": {"nodes": 10}, "run": {"duration": 0.02}})");
  fs::create_directories(dir + "/run");
  const std::string stale = temporary_of(dir + "/run/video.mp4", dead_pid());
  touch(stale);
  const test::CommandResult r = test::run_vascsim("run " + dir + "/scene.json --out " + dir + "/run --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(stale));
  fs::remove_all(dir);
}

TEST(OutputFile, WriteFileAtomicallyLeavesOnlyTheFinalName) {
  const std::string dir = test::fresh_temp_dir("atomic_write");
  write_file_atomically(dir + "/a.json", "{}");
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.path().filename() == "a.json" ? 1 : 100;
  EXPECT_EQ(entries, 1u);
  EXPECT_EQ(test::read_text(dir + "/a.json"), "{}");
  fs::remove_all(dir);
}

// A run directory's claim tells a run still writing from one killed with kill -9, which leaves
// the claim's file but no holder; asking takes nothing, so a run starting meanwhile is not refused.
TEST(OutputFile, TheRunClaimSaysWhetherARunIsWritingWithoutTakingIt) {
  const std::string dir = vascsim::test::fresh_temp_dir("run_claim_holder");
  EXPECT_EQ(RunDirectoryClaim::holder(dir), RunDirectoryClaim::Holder::kNoClaim) << "never claimed";
  {
    RunDirectoryClaim claim(dir);
    EXPECT_EQ(RunDirectoryClaim::holder(dir), RunDirectoryClaim::Holder::kRun);
    EXPECT_THROW(RunDirectoryClaim second(dir), InputError) << "two claims in one process";
    EXPECT_EQ(RunDirectoryClaim::holder(dir), RunDirectoryClaim::Holder::kRun) << "the refused claim let go of the first";
  }
  EXPECT_FALSE(fs::exists(fs::path(dir) / RunDirectoryClaim::kFileName));
  EXPECT_EQ(RunDirectoryClaim::holder(dir), RunDirectoryClaim::Holder::kNoClaim);

  // Another process claims the directory and tells us so; we ask while it holds the claim, then
  // it ends without cleaning up, as kill -9 leaves it.
  int ready[2], done[2];
  ASSERT_EQ(::pipe(ready), 0);
  ASSERT_EQ(::pipe(done), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    RunDirectoryClaim* claim = new RunDirectoryClaim(dir);  // never destroyed: no unlink, as after kill -9
    (void)claim;
    char c = 1;
    (void)!::write(ready[1], &c, 1);
    (void)!::read(done[0], &c, 1);
    ::_exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  EXPECT_EQ(RunDirectoryClaim::holder(dir), RunDirectoryClaim::Holder::kRun);
  EXPECT_THROW(RunDirectoryClaim refused(dir), InputError);
  EXPECT_EQ(RunDirectoryClaim::holder(dir), RunDirectoryClaim::Holder::kRun) << "asking took the claim from its run";
  ASSERT_EQ(::write(done[1], &c, 1), 1);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(fs::exists(fs::path(dir) / RunDirectoryClaim::kFileName)) << "the killed run's claim file stays";
  EXPECT_EQ(RunDirectoryClaim::holder(dir), RunDirectoryClaim::Holder::kAbandoned);
  RunDirectoryClaim next(dir);  // and the next run takes the directory over
  EXPECT_EQ(RunDirectoryClaim::holder(dir), RunDirectoryClaim::Holder::kRun);
  for (int fd : {ready[0], ready[1], done[0], done[1]}) ::close(fd);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vascsim
