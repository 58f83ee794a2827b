// The fuzz harnesses that need the renderer (frame logs, replay requests), over their committed
// inputs (fuzz_corpus_support.h): the seeds must run clean, and every input that once crashed a
// harness must stay fixed.
#include <gtest/gtest.h>

#include "tests/fuzz/fuzz_corpus_support.h"

namespace vascsim::fuzz {
namespace {

TEST(FuzzCorpus, FrameLogRunsCleanOnEverySeedAndRegression) {
  const CorpusRun run = run_corpus("frame_log", frame_log);
  EXPECT_GE(run.seeds, 3u) << "tests/fuzz/corpus/frame_log/ should hold small logs of real runs";
}

TEST(FuzzCorpus, ReplayRequestRunsCleanOnEverySeedAndRegression) {
  const CorpusRun run = run_corpus("request", replay_request);
  EXPECT_GE(run.seeds, 10u) << "tests/fuzz/corpus/request/ should hold the page's queries";
}

}  // namespace
}  // namespace vascsim::fuzz
