#include "sim/env/iso_contour.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace vascsim {

namespace {

// The lattice of pixel centres, with a frame of grey-0 nodes around the image. Node (X, Y) is the
// centre of pixel (col X, row height - 1 - Y), so Y points up as the world's y does; X runs over
// -1..width and Y over -1..height. Edges between neighbouring nodes carry the contour's vertices:
// horizontal edge (X, Y)-(X+1, Y) and vertical edge (X, Y)-(X, Y+1) get distinct ids.
class Lattice {
 public:
  Lattice(const std::vector<std::uint8_t>& grey, int width, int height, double level, double pixel_size)
      : grey_(grey), width_(width), height_(height), nx_(width + 2), ny_(height + 2), level_(level), h_(pixel_size) {}

  double value(int x, int y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return 0.0;
    return grey_[static_cast<std::size_t>(height_ - 1 - y) * width_ + x];
  }
  bool inside(int x, int y) const { return value(x, y) > level_; }
  std::int64_t horizontal(int x, int y) const { return std::int64_t(y + 1) * nx_ + (x + 1); }
  std::int64_t vertical(int x, int y) const { return std::int64_t(nx_) * ny_ + std::int64_t(y + 1) * nx_ + (x + 1); }

  // The crossing on an edge, interpolated linearly between its two nodes: sub-pixel where the
  // image is anti-aliased. One formula per edge, so the two cells sharing it agree exactly.
  Vec2 crossing(std::int64_t id) const {
    const bool vert = id >= std::int64_t(nx_) * ny_;
    const std::int64_t local = vert ? id - std::int64_t(nx_) * ny_ : id;
    const int x0 = static_cast<int>(local % nx_) - 1, y0 = static_cast<int>(local / nx_) - 1;
    const int x1 = vert ? x0 : x0 + 1, y1 = vert ? y0 + 1 : y0;
    const double f0 = value(x0, y0), f1 = value(x1, y1);
    const double t = (level_ - f0) / (f1 - f0);  // in (0, 1): one node is above level, one below
    return Vec2((x0 + t * (x1 - x0) + 0.5) * h_, (y0 + t * (y1 - y0) + 0.5) * h_);
  }

 private:
  const std::vector<std::uint8_t>& grey_;
  int width_, height_, nx_, ny_;
  double level_, h_;
};

}  // namespace

std::vector<Polyline> iso_contours(const std::vector<std::uint8_t>& grey, int width, int height, double level,
                                   double pixel_size) {
  if (width < 0 || height < 0 || grey.size() != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("iso_contours: image size does not match its pixels");
  if (!(level > 0.0 && level <= 255.0)) throw std::invalid_argument("iso_contours: level outside (0, 255]");
  // Grey levels are integers: comparing with a level a hair lower keeps "at or above `level` is
  // inside" and means no node ever lies exactly on the contour, so every crossing is strictly
  // inside its edge and no two rings share a point.
  const Lattice lat(grey, width, height, level - 1e-6, pixel_size);

  // Each cell's contour segments, oriented with the inside on the left. Walking round a cell
  // counter-clockwise (bottom, right, top, left edge), the inside lies to the left of the walk;
  // a segment therefore starts at a crossing where the walk leaves the inside and ends at the
  // next one where it re-enters, cutting off the outside corners between them. Every crossing
  // edge is left by exactly one of its two cells and entered by the other, so the segments chain
  // into closed rings.
  std::vector<std::pair<std::int64_t, std::int64_t>> segments;  // (from edge, to edge)
  for (int y = -1; y < height; ++y) {
    for (int x = -1; x < width; ++x) {
      const int cx[4] = {x, x + 1, x + 1, x}, cy[4] = {y, y, y + 1, y + 1};  // a, b, c, d: counter-clockwise
      bool in[4];
      for (int k = 0; k < 4; ++k) in[k] = lat.inside(cx[k], cy[k]);
      if (in[0] == in[1] && in[1] == in[2] && in[2] == in[3]) continue;
      const std::int64_t edge[4] = {lat.horizontal(x, y), lat.vertical(x + 1, y), lat.horizontal(x, y + 1),
                                    lat.vertical(x, y)};
      std::int64_t cross[4];
      bool leaving[4];
      int n = 0;
      for (int k = 0; k < 4; ++k) {
        if (in[k] == in[(k + 1) % 4]) continue;
        cross[n] = edge[k];
        leaving[n] = in[k];
        ++n;
      }
      if (n == 2) {
        segments.emplace_back(leaving[0] ? cross[0] : cross[1], leaving[0] ? cross[1] : cross[0]);
        continue;
      }
      // Saddle: inside corners a, c and outside b, d, or the reverse. A centre at or above the
      // level joins the inside corners (each leaving crossing goes to the next entering one,
      // cutting off one outside corner); else each goes to the previous one.
      double mean = 0.0;
      for (int k = 0; k < 4; ++k) mean += lat.value(cx[k], cy[k]);
      const bool joined = mean / 4.0 > level - 1e-6;
      for (int k = 0; k < 4; ++k) {
        if (!leaving[k]) continue;
        segments.emplace_back(cross[k], cross[(k + (joined ? 1 : 3)) % 4]);
      }
    }
  }
  std::sort(segments.begin(), segments.end());

  // Chain the segments: from each unvisited one (in edge order) follow "to" until the ring closes.
  std::vector<Polyline> rings;
  std::vector<bool> used(segments.size(), false);
  const auto find = [&](std::int64_t from) {
    const auto it = std::lower_bound(segments.begin(), segments.end(), std::make_pair(from, std::int64_t(-1)));
    if (it == segments.end() || it->first != from) throw std::logic_error("iso_contours: open contour");
    return static_cast<std::size_t>(it - segments.begin());
  };
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (used[s]) continue;
    Polyline ring;
    std::size_t i = s;
    while (!used[i]) {
      used[i] = true;
      ring.push_back(lat.crossing(segments[i].first));
      i = find(segments[i].second);
    }
    if (i != s) throw std::logic_error("iso_contours: contour joins another");
    rings.push_back(std::move(ring));
  }
  return rings;
}

}  // namespace vascsim
