// Cost of FrameLogReader::replaced(), which the replay server asks on every request (issue 16's
// notes: a stat, an fstat and a re-read of the header to compare). Headers from the maze's size
// (about 5 kB) to a traced vessel mask's (160 kB, its lumen outline in the metadata). Compare
// with a frame render of about 8 ms (docs/replay.md). Run: build with -DVASCSIM_BENCHMARKS=ON
// (Release), then build-dir/tests/vascsim_benchmarks --benchmark_filter=Replaced.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "sim/log/frame_log.h"

namespace vascsim {
namespace {

void BM_FrameLogReplacedCheck(benchmark::State& state) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("vascsim_bench_replaced_" + std::to_string(::getpid()) + ".vlog")).string();
  FrameLogHeader header;
  header.node_count = 50;
  header.channels.push_back({"rod/position", "m", ChannelLayout::kNodeVectors, 100});
  header.metadata.assign(static_cast<std::size_t>(state.range(0)), 'x');
  {
    FrameLogWriter writer(path, header);
    const std::vector<double> values(100, 0.0);
    for (int k = 0; k < 100; ++k) writer.append(0.01 * k, values);
    writer.close();
  }
  const FrameLogReader reader(path);
  for (auto _ : state) benchmark::DoNotOptimize(reader.replaced());
  state.counters["header_bytes"] = static_cast<double>(state.range(0));
  std::filesystem::remove(path);
}
BENCHMARK(BM_FrameLogReplacedCheck)->Arg(5 << 10)->Arg(160 << 10)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vascsim
