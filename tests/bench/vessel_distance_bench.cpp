// Speed of the wall distance query in the shipped vessel networks against the default maze (issue 12:
// a vessel network's query should cost no more than twice the maze's). Points are drawn uniformly
// inside each lumen, where the rod's nodes are; the radius is the contact code's neighbour search
// for the Table I rod (10 mm). Run: build with -DVASCSIM_BENCHMARKS=ON (Release), then
// build-dir/tests/vascsim_benchmarks --benchmark_filter=Scene.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "sim/env/vessel_lumen.h"
#include "sim/env/wall_distance.h"
#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/navigation.h"

namespace vascsim {
namespace {

const char* const kScenes[] = {"maze_default", "bifurcation", "aneurysm", "stenosis", "tortuous", "vessel_tree"};

Environment environment_of(int index) {
  const Scene s = read_scene_file(std::string(VASCSIM_SOURCE_DIR) + "/scenes/" + kScenes[index] + ".json");
  return compile(s)->navigation->environment;
}

// 4096 points inside the lumen (for the maze: inside its bounds and farther than half a wall from
// every wall, i.e. in a channel), the same for every run.
std::vector<Vec2> lumen_points(const Environment& env) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ux(env.bounds.min.x(), env.bounds.max.x()), uy(env.bounds.min.y(), env.bounds.max.y());
  std::vector<Vec2> points;
  while (points.size() < 4096) {
    const Vec2 p(ux(rng), uy(rng));
    WallHit hit;
    WallDistanceField::nearest_brute_force(env.walls, p, hit);
    if (inside_lumen(env.lumen, p) && hit.distance > 0.0) points.push_back(p);
  }
  return points;
}

void BM_NearestInScene(benchmark::State& state) {
  const Environment env = environment_of(static_cast<int>(state.range(0)));
  const double radius = 0.01;
  const WallDistanceField field(env.walls, radius);
  const std::vector<Vec2> points = lumen_points(env);
  std::vector<WallHit> hits;
  std::size_t k = 0, found = 0;
  for (auto _ : state) {
    field.near(points[k++ & 4095], radius, hits);
    found += hits.size();
    benchmark::DoNotOptimize(hits.data());
  }
  state.SetLabel(kScenes[state.range(0)]);
  state.counters["walls"] = static_cast<double>(env.walls.size());
  state.counters["hits_per_query"] = static_cast<double>(found) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_NearestInScene)->DenseRange(0, 5);

}  // namespace
}  // namespace vascsim
