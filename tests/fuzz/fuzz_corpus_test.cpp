// The fuzz harnesses that need no renderer, over their committed inputs (fuzz_corpus_support.h):
// the seeds must run clean, and every input that once crashed a harness must stay fixed.
#include <gtest/gtest.h>

#include "tests/fuzz/fuzz_corpus_support.h"

namespace vascsim::fuzz {
namespace {

TEST(FuzzCorpus, SceneReaderRunsCleanOnEverySeedAndRegression) {
  const CorpusRun run = run_corpus("scene", scene_reader);
  EXPECT_GE(run.seeds, 10u) << "tests/fuzz/corpus/scene/ should hold at least the shipped scenes";
}

TEST(FuzzCorpus, PngReaderRunsCleanOnEverySeedAndRegression) {
  const CorpusRun run = run_corpus("png", png_reader);
  EXPECT_GE(run.seeds, 5u) << "tests/fuzz/corpus/png/ should hold PNGs of each colour type";
}

}  // namespace
}  // namespace vascsim::fuzz
