// libFuzzer's entry point for one harness: compiled once per fuzz executable with
// VASCSIM_FUZZ_HARNESS naming the function of tests/fuzz/fuzz_harnesses.h it forwards to.
#include "tests/fuzz/fuzz_harnesses.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return vascsim::fuzz::VASCSIM_FUZZ_HARNESS(data, size);
}
