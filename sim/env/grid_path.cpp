#include "sim/env/grid_path.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace vascsim {

std::vector<int> cheapest_grid_path(const std::vector<double>& cost, int width, int height, int start, int goal) {
  const int n = width * height;
  if (width < 0 || height < 0 || cost.size() != static_cast<std::size_t>(n))
    throw std::invalid_argument("cheapest_grid_path: cost size does not match the grid");
  const auto passable = [&](int i) { return cost[i] > 0.0 && std::isfinite(cost[i]); };
  if (start < 0 || start >= n || goal < 0 || goal >= n || !passable(start) || !passable(goal)) return {};

  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(n, kInf);
  std::vector<int> from(n, -1);
  // (distance, pixel): the lexicographic order breaks ties by pixel index.
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  dist[start] = 0.0;
  open.emplace(0.0, start);
  static const int dx[8] = {1, -1, 0, 0, 1, -1, 1, -1}, dy[8] = {0, 0, 1, -1, 1, 1, -1, -1};
  const double diagonal = std::sqrt(2.0);
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[i]) continue;  // a stale entry
    if (i == goal) break;
    const int x = i % width, y = i / width;
    for (int k = 0; k < 8; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
      const int j = ny * width + nx;
      if (!passable(j)) continue;
      if (k >= 4 && (!passable(y * width + nx) || !passable(ny * width + x))) continue;
      const double nd = d + (k >= 4 ? diagonal : 1.0) * 0.5 * (cost[i] + cost[j]);
      if (nd < dist[j]) {
        dist[j] = nd;
        from[j] = i;
        open.emplace(nd, j);
      }
    }
  }
  if (dist[goal] == kInf) return {};
  std::vector<int> path;
  for (int i = goal; i != -1; i = from[i]) path.push_back(i);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace vascsim
