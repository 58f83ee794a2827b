#include "sim/env/distance_transform.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace vascsim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One line of the separable transform (Felzenszwalb & Huttenlocher, "Distance Transforms of
// Sampled Functions", Theory of Computing 8 (2012) 415-428, algorithm DT(f)): d(q) = min_p
// (q - p)^2 + f(p), the lower envelope of the parabolas rooted at (p, f(p)), built left to right
// in O(n). v holds the envelope's parabolas, z the boundaries between them. Parabolas with f = inf
// are left out (the paper's version adds them, and inf - inf would be NaN); arg(q) is the p that
// attains the minimum (-1 if every f is infinite).
void lower_envelope(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& arg,
                    std::vector<int>& v, std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  v.assign(n, 0);
  z.assign(n + 1, 0.0);
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kInf) continue;
    double s = -kInf;
    while (k >= 0) {
      const int p = v[k];
      // Where the parabolas of p and q intersect.
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s > z[k]) break;
      --k;
    }
    if (k < 0) s = -kInf;
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  d.assign(n, kInf);
  arg.assign(n, -1);
  if (k < 0) return;
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < q) ++j;
    const double dq = q - v[j];
    d[q] = dq * dq + f[v[j]];
    arg[q] = v[j];
  }
}

}  // namespace

DistanceMap distance_to_background(const std::vector<std::uint8_t>& inside, int width, int height) {
  if (width < 0 || height < 0 || inside.size() != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("distance_to_background: image size does not match its pixels");
  // A frame of background one pixel wide around the image: every line then has a background
  // pixel, and lumen at the border is that close to the wall.
  const int pw = width + 2, ph = height + 2;
  std::vector<double> sq(static_cast<std::size_t>(pw) * ph);  // squared distance after the column pass
  std::vector<int> row_of(sq.size());                          // padded row of the column pass's nearest
  std::vector<double> f, d, z;
  std::vector<int> arg, v;
  // Pass 1, down each column: squared distance to the nearest background pixel in that column.
  f.resize(ph);
  for (int x = 0; x < pw; ++x) {
    for (int y = 0; y < ph; ++y) {
      const bool fg = x > 0 && x <= width && y > 0 && y <= height &&
                      inside[static_cast<std::size_t>(y - 1) * width + (x - 1)] != 0;
      f[y] = fg ? kInf : 0.0;
    }
    lower_envelope(f, d, arg, v, z);
    for (int y = 0; y < ph; ++y) {
      sq[static_cast<std::size_t>(y) * pw + x] = d[y];
      row_of[static_cast<std::size_t>(y) * pw + x] = arg[y];
    }
  }
  // Pass 2, along each row over the column pass's result: the exact 2D squared distance.
  DistanceMap out;
  out.width = width;
  out.height = height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  out.distance.resize(n);
  out.nearest_col.resize(n);
  out.nearest_row.resize(n);
  f.resize(pw);
  for (int y = 1; y <= height; ++y) {
    for (int x = 0; x < pw; ++x) f[x] = sq[static_cast<std::size_t>(y) * pw + x];
    lower_envelope(f, d, arg, v, z);
    for (int x = 1; x <= width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y - 1) * width + (x - 1);
      out.distance[i] = std::sqrt(d[x]);
      out.nearest_col[i] = arg[x] - 1;
      out.nearest_row[i] = row_of[static_cast<std::size_t>(y) * pw + arg[x]] - 1;
    }
  }
  return out;
}

}  // namespace vascsim
