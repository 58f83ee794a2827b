#include "tests/fuzz/fuzz_corpus_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace vascsim::fuzz {

namespace fs = std::filesystem;

namespace {

std::size_t run_folder(const fs::path& dir, Harness harness) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(in.good() || in.eof()) << file << ": cannot read";
    EXPECT_LE(bytes.size(), kMaxCommittedInput) << file << ": a committed fuzz input must stay under 100 kB";
    // Named before the run: a sanitizer report aborts without returning here.
    std::fprintf(stderr, "fuzz input %s (%zu bytes)\n", file.c_str(), bytes.size());
    try {
      harness(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch (const std::exception& e) {
      ADD_FAILURE() << file << ": the harness threw: " << e.what();
    } catch (...) {
      ADD_FAILURE() << file << ": the harness threw something that is not a std::exception";
    }
  }
  return files.size();
}

}  // namespace

CorpusRun run_corpus(const std::string& name, Harness harness) {
  const fs::path root = fs::path(VASCSIM_SOURCE_DIR) / "tests" / "fuzz";
  CorpusRun run;
  run.seeds = run_folder(root / "corpus" / name, harness);
  run.regressions = run_folder(root / "regressions" / name, harness);
  return run;
}

}  // namespace vascsim::fuzz
