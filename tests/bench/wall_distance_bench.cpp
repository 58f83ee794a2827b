// Speed of the wall distance query on a 60 x 60 maze (about 3700 cells' worth of walls): the bucket
// grid against the brute-force loop over every wall, for thick and line walls and two query radii.
// Run: build with -DVASCSIM_BENCHMARKS=ON (Release), then build-dir/tests/vascsim_benchmarks.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "sim/env/environment.h"
#include "sim/env/wall_distance.h"

namespace vascsim {
namespace {

MazeSpec maze_60(double lumen) {
  MazeSpec m;
  m.rows = m.cols = 60;
  m.width = m.height = 12.0;  // 0.2 m cells
  m.lumen_width = lumen;
  m.seed = 2024;
  return m;
}

// 4096 query points spread over the maze, the same for every run.
std::vector<Vec2> query_points(const Environment& env) {
  std::mt19937_64 rng(7);
  std::vector<Vec2> points;
  for (int k = 0; k < 4096; ++k) {
    const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53, v = static_cast<double>(rng() >> 11) * 0x1.0p-53;
    points.emplace_back(env.bounds.min.x() + u * (env.bounds.max.x() - env.bounds.min.x()),
                        env.bounds.min.y() + v * (env.bounds.max.y() - env.bounds.min.y()));
  }
  return points;
}

// Args: lumen width in mm (100: 0.1 m thick walls; 200: line walls), query radius in mm.
void BM_NearestGrid(benchmark::State& state) {
  const Environment env = build_environment(maze_60(state.range(0) * 1e-3));
  const double radius = state.range(1) * 1e-3;
  const WallDistanceField field(env.walls, radius);
  const std::vector<Vec2> points = query_points(env);
  std::size_t k = 0;
  int found = 0;
  for (auto _ : state) {
    WallHit hit;
    found += field.nearest(points[k++ & 4095], radius, hit);
    benchmark::DoNotOptimize(hit);
  }
  state.counters["walls"] = static_cast<double>(env.walls.size());
  state.counters["buckets"] = static_cast<double>(field.buckets_x()) * field.buckets_y();
  state.counters["hit_rate"] = static_cast<double>(found) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_NearestGrid)->Args({100, 5})->Args({100, 100})->Args({200, 5})->Args({200, 100});

void BM_NearestBruteForce(benchmark::State& state) {
  const Environment env = build_environment(maze_60(state.range(0) * 1e-3));
  const std::vector<Vec2> points = query_points(env);
  std::size_t k = 0;
  for (auto _ : state) {
    WallHit hit;
    WallDistanceField::nearest_brute_force(env.walls, points[k++ & 4095], hit);
    benchmark::DoNotOptimize(hit);
  }
  state.counters["walls"] = static_cast<double>(env.walls.size());
}
BENCHMARK(BM_NearestBruteForce)->Arg(100)->Arg(200);

void BM_BuildField(benchmark::State& state) {
  const Environment env = build_environment(maze_60(0.1));
  for (auto _ : state) {
    WallDistanceField field(env.walls, state.range(0) * 1e-3);
    benchmark::DoNotOptimize(field);
  }
}
BENCHMARK(BM_BuildField)->Arg(5)->Arg(100)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vascsim
