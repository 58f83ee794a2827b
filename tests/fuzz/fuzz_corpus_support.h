// Runs a fuzz harness over its committed inputs as an ordinary test: every file of
// tests/fuzz/corpus/<harness>/ (the seeds) and tests/fuzz/regressions/<harness>/ (inputs that
// once crashed it). Under the sanitized CI build this replays them with ASan and UBSan.
#pragma once

#include <cstddef>
#include <string>

#include "tests/fuzz/fuzz_harnesses.h"

namespace vascsim::fuzz {

// Inputs bigger than this are not committed: a seed should be small (the fuzzer mutates it
// byte by byte) and CI quick.
inline constexpr std::size_t kMaxCommittedInput = 100 * 1024;

struct CorpusRun {
  std::size_t seeds = 0, regressions = 0;  // files run from each folder
};

// Calls `harness` on each file, in name order. A file the harness throws on (anything but
// its documented refusal, which it catches itself) or a file over kMaxCommittedInput is a
// test failure naming the file; a sanitizer report ends the test binary, after the file's
// name was printed to stderr.
CorpusRun run_corpus(const std::string& name, Harness harness);

}  // namespace vascsim::fuzz
