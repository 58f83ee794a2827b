// How much of a long sweep a test runs. Under AddressSanitizer and UndefinedBehaviorSanitizer the
// traversal and brute-force loops run 10-15x slower than optimised, and a sweep over many mazes or
// points adds cases, not code paths. CI runs the tests in both builds (scripts/test), so the
// optimised build runs every case and the sanitizer build every code path on a sample of them.
#pragma once

namespace vascsim::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

// `full` in an optimised build, `sample` under the sanitizers.
constexpr int sweep_size(int full, int sample) { return kSanitizedBuild ? sample : full; }

}  // namespace vascsim::test
