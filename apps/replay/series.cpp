#include "apps/replay/series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vascsim::replay {

SeriesReduce reduce_for(const LogChannel& c, const std::string& name) {
  switch (c.layout) {
    case ChannelLayout::kNodeVectors:
      if (name == "max") return SeriesReduce::kMax;
      if (name == "sum") return SeriesReduce::kSum;
      if (name == "norm") return SeriesReduce::kNorm;
      throw std::invalid_argument("expected max, sum or norm for the node-vector channel '" + c.name + "'");
    case ChannelLayout::kVector:
      if (name == "x") return SeriesReduce::kX;
      if (name == "y") return SeriesReduce::kY;
      if (name == "max" || name == "norm") return SeriesReduce::kValue;
      throw std::invalid_argument("expected norm (or max, the default: the same), x or y for the vector channel '" + c.name + "'");
    case ChannelLayout::kScalars:
      if (name == "max" || name == "norm") return name == "norm" ? SeriesReduce::kNorm : SeriesReduce::kValue;
      throw std::invalid_argument("expected max (the first value) or norm for the scalar channel '" + c.name + "'");
  }
  throw std::invalid_argument("unknown channel layout");
}

double reduce_values(const double* v, const LogChannel& c, SeriesReduce r) {
  const std::size_t n = c.count;
  switch (r) {
    case SeriesReduce::kMax: {
      double m = 0;
      for (std::size_t i = 0; i + 1 < n; i += 2) m = std::max(m, std::hypot(v[i], v[i + 1]));
      return m;
    }
    case SeriesReduce::kSum: {
      double x = 0, y = 0;
      for (std::size_t i = 0; i + 1 < n; i += 2) x += v[i], y += v[i + 1];
      return std::hypot(x, y);
    }
    case SeriesReduce::kNorm: {
      double s = 0;
      for (std::size_t i = 0; i < n; ++i) s += v[i] * v[i];
      return std::sqrt(s);
    }
    case SeriesReduce::kX: return v[0];
    case SeriesReduce::kY: return v[1];
    case SeriesReduce::kValue: return c.layout == ChannelLayout::kVector ? std::hypot(v[0], v[1]) : v[0];
  }
  return 0;
}

DecimatedSeries decimate_min_max(const std::vector<double>& times, const std::vector<float>& values, double from,
                                 double to, int points) {
  DecimatedSeries out;
  const std::size_t n = std::min(times.size(), values.size());
  if (n == 0 || points < 1 || !(to >= from)) return out;
  const double width = (to - from) / points;
  auto begin = std::lower_bound(times.begin(), times.begin() + static_cast<long>(n), from);
  std::size_t i = static_cast<std::size_t>(begin - times.begin());
  for (int k = 0; k < points && i < n; ++k) {
    // The last bucket is closed so a frame exactly at `to` is kept.
    const double end = k + 1 == points ? to : from + (k + 1) * width;
    double lo = INFINITY, hi = -INFINITY;
    bool any = false;
    for (; i < n && (times[i] < end || (k + 1 == points && times[i] <= end)); ++i) {
      const double x = values[i];
      if (std::isnan(x)) continue;
      lo = std::min(lo, x), hi = std::max(hi, x), any = true;
    }
    if (!any) continue;
    out.t.push_back(width > 0 ? from + (k + 0.5) * width : from);
    out.min.push_back(lo);
    out.max.push_back(hi);
  }
  return out;
}

}  // namespace vascsim::replay
