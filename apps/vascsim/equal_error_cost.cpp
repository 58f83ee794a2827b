#include "apps/vascsim/equal_error_cost.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vascsim::cli {

double wall_time_at_error(std::vector<ErrorCost> runs, double error) {
  std::sort(runs.begin(), runs.end(), [](const ErrorCost& a, const ErrorCost& b) { return a.wall_time < b.wall_time; });
  std::vector<ErrorCost> front;
  for (const auto& r : runs)
    if (r.error > 0 && r.wall_time > 0 && (front.empty() || r.error < front.back().error)) front.push_back(r);
  for (std::size_t k = 0; k + 1 < front.size(); ++k) {
    const ErrorCost& coarse = front[k];
    const ErrorCost& fine = front[k + 1];
    if (error <= coarse.error && error >= fine.error) {
      const double s = std::log(error / coarse.error) / std::log(fine.error / coarse.error);
      return coarse.wall_time * std::pow(fine.wall_time / coarse.wall_time, s);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace vascsim::cli
