#include "sim/env/vessel_mask.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "sim/env/distance_transform.h"
#include "sim/env/grid_path.h"
#include "sim/env/iso_contour.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

// Passes of the [1/4 1/2 1/4] filter over the minimal path, at one point per pixel: a Gaussian of
// sigma = sqrt(passes / 2) = 2.4 px. The pixel path's staircase is +-0.5 px with a period of a
// few pixels, which this removes; a bend of radius rho is cut by about sigma^2 / (2 rho), 0.15 px
// for a bend of 20 px. More passes cut tight bends more (measured on the annulus test), fewer
// leave staircase (the tube test).
constexpr int kSmoothingPasses = 12;
// The step cost is d^-kCostExponent for d the distance to the wall (px): the path's pull to the
// axis against its wish to be short. 2 (Deschamps & Cohen's inverse-square potential) lets the
// path on a bend of radius 2.6 lumen radii sit 0.75 px inside the axis, 4 sits 0.5 px (the
// annulus test); straight tubes are the same with either.
constexpr double kCostExponent = 4.0;

std::string point_text(const Vec2& p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ") m";
  return s.str();
}

struct Pixel {
  int col = 0, row = 0;
  bool in_image = false;
};

Pixel pixel_of(const VesselMaskSpec& spec, const Vec2& p) {
  Pixel px;
  const double c = std::floor(p.x() / spec.pixel_size), r = spec.height - 1 - std::floor(p.y() / spec.pixel_size);
  px.in_image = c >= 0 && c < spec.width && r >= 0 && r < spec.height;
  // Clamped to the int range (a NaN to -1) only for the message; an outside point is never indexed.
  const auto to_int = [](double v) { return std::isnan(v) ? -1 : static_cast<int>(std::clamp(v, -1e9, 1e9)); };
  px.col = to_int(c);
  px.row = to_int(r);
  return px;
}

std::string pixel_text(const Pixel& px) {
  return "pixel (" + std::to_string(px.col) + ", " + std::to_string(px.row) + ")";
}

Vec2 pixel_centre(const VesselMaskSpec& spec, int col, int row) {
  return Vec2((col + 0.5) * spec.pixel_size, (spec.height - row - 0.5) * spec.pixel_size);
}

// The lumen pixel under the start or the goal (`which`), or an InputError saying why not.
int endpoint_pixel(const VesselMaskSpec& spec, const std::vector<std::uint8_t>& lumen, const Vec2& p,
                   const std::string& which) {
  const Pixel px = pixel_of(spec, p);
  std::ostringstream msg;
  msg << "/vessels/" << which << ": the " << which << " " << point_text(p) << " is at " << pixel_text(px);
  if (!px.in_image) {
    msg << ", outside " << spec.file << " (" << spec.width << " x " << spec.height << " px of " << spec.pixel_size
        << " m: 0 <= x < " << spec.width * spec.pixel_size << " m, 0 <= y < " << spec.height * spec.pixel_size << " m)";
    throw InputError(msg.str());
  }
  const int i = px.row * spec.width + px.col;
  if (!lumen[i]) {
    msg << " of " << spec.file << ", which is not lumen (grey level " << int(spec.grey[i]) << ", below the threshold "
        << spec.threshold << " x 255 = " << spec.threshold * 255.0 << ")";
    throw InputError(msg.str());
  }
  return i;
}

double length(const Polyline& p) {
  double l = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i) l += (p[i] - p[i - 1]).norm();
  return l;
}

// Points at equal arc-length steps of about `spacing` (never longer), both ends kept.
Polyline resample(const Polyline& p, double spacing) {
  const double total = length(p);
  if (p.size() < 2 || total <= 0.0) return p;
  const int segments = std::max(1, static_cast<int>(std::ceil(total / spacing - 1e-9)));
  Polyline out;
  out.reserve(segments + 1);
  out.push_back(p.front());
  std::size_t k = 1;
  double before = 0.0;  // arc length at p[k - 1]
  for (int s = 1; s < segments; ++s) {
    const double at = total * s / segments;
    while (k + 1 < p.size() && before + (p[k] - p[k - 1]).norm() < at) {
      before += (p[k] - p[k - 1]).norm();
      ++k;
    }
    const double piece = (p[k] - p[k - 1]).norm();
    const double t = piece > 0.0 ? std::clamp((at - before) / piece, 0.0, 1.0) : 0.0;
    out.push_back(p[k - 1] + t * (p[k] - p[k - 1]));
  }
  out.push_back(p.back());
  return out;
}

// Laplacian smoothing with fixed ends (Jacobi: every point from the previous pass's neighbours).
void smooth(Polyline& p, int passes) {
  Polyline prev;
  for (int pass = 0; pass < passes; ++pass) {
    prev = p;
    for (std::size_t i = 1; i + 1 < p.size(); ++i) p[i] = 0.25 * prev[i - 1] + 0.5 * prev[i] + 0.25 * prev[i + 1];
  }
}

// Lumen radius (m) at p: the distance to the nearest background pixel centre, less half a pixel
// because the traced wall lies about midway between the last lumen and the first background
// centre. The nearest background pixel of p is taken as the nearest of those of the 3 x 3 pixels
// around it (the distance map's feature transform), which is exact at pixel centres and avoids
// interpolating the distance, which sags between rows on a ridge. `beyond_border`: that pixel is
// outside the image (the border is the nearest wall).
struct LumenRadius {
  double radius = 0.0;  // m
  bool beyond_border = false;
};

LumenRadius radius_at(const VesselMaskSpec& spec, const DistanceMap& dm, const Vec2& p) {
  const Pixel px = pixel_of(spec, p);
  double best = std::numeric_limits<double>::infinity();
  bool beyond = false;
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      const int c = px.col + dc, r = px.row + dr;
      if (c < 0 || r < 0 || c >= spec.width || r >= spec.height) continue;
      const int i = r * spec.width + c;
      const int nc = dm.nearest_col[i], nr = dm.nearest_row[i];
      const double d = (p - pixel_centre(spec, nc, nr)).norm();
      if (d < best) best = d, beyond = nc < 0 || nr < 0 || nc >= spec.width || nr >= spec.height;
    }
  }
  return {std::max(best - 0.5 * spec.pixel_size, 0.5 * spec.pixel_size), beyond};
}

// Where the route starts at the image's border, the border is the nearest "wall" of its first
// points, but the vessel runs on out of the image there (the introducer continues it). Near the
// border the centre-seeking path also bends off the vessel's axis, towards one wall where the
// vessel leaves at a slant. So the points from the start until the path is both a diameter past
// the last point that has the border nearest and a diameter from the border take the largest
// radius over that stretch, the vessel's. Before, the first point had half a pixel (refused as a
// narrowing, or an introducer far thinner than its vessel), and the first point past the
// border's reach 11 px for 20 at 75 degrees. A route whose every point has the border nearest (a
// vessel lying along it) keeps those distances. Returns the index where that stretch ends (0 if
// the route does not start at the border): from there on the path is on the vessel's axis.
std::size_t extend_radius_past_border(const VesselMaskSpec& spec, const Polyline& path, std::vector<double>& radius,
                                      const std::vector<bool>& beyond_border) {
  const std::size_t n = radius.size();
  std::size_t first = 0;
  while (first < n && beyond_border[first]) ++first;
  if (first == 0 || first == n) return 0;
  const double w = spec.width * spec.pixel_size, h = spec.height * spec.pixel_size;
  const auto border_distance = [&](const Vec2& p) { return std::min({p.x(), w - p.x(), p.y(), h - p.y()}); };
  double largest = radius[first], along = 0.0;
  std::size_t end = first;
  while (end + 1 < n && (along < 2.0 * largest || border_distance(path[end]) < 2.0 * radius[end])) {
    along += (path[end + 1] - path[end]).norm();
    largest = std::max(largest, radius[++end]);
  }
  for (std::size_t i = 0; i < end; ++i) radius[i] = largest;
  return end;
}

}  // namespace

MaskTrace trace_vessel_mask(const VesselMaskSpec& spec) {
  if (spec.width <= 0 || spec.height <= 0 || spec.grey.size() != static_cast<std::size_t>(spec.width) * spec.height)
    throw std::invalid_argument("trace_vessel_mask: " + spec.file + ": image size does not match its pixels");
  if (!(spec.pixel_size > 0.0) || !std::isfinite(spec.pixel_size)) {
    std::ostringstream msg;
    msg << "/vessels/mask/pixel_size: expected a length > 0 m, got " << spec.pixel_size;
    throw InputError(msg.str());
  }
  if (!(spec.threshold > 0.0 && spec.threshold <= 1.0)) {
    std::ostringstream msg;
    msg << "/vessels/mask/threshold: expected a grey level in (0, 1], got " << spec.threshold;
    throw InputError(msg.str());
  }
  // "At or above the threshold", with iso_contours' allowance of 1e-6 grey levels, so that a
  // threshold such as 0.4 (0.4 * 255 = 102.00000000000001) counts grey 102 as lumen in both.
  const double level = spec.threshold * 255.0;
  std::vector<std::uint8_t> lumen(spec.grey.size());
  for (std::size_t i = 0; i < lumen.size(); ++i) lumen[i] = spec.grey[i] > level - 1e-6 ? 1 : 0;
  if (std::find(lumen.begin(), lumen.end(), 1) == lumen.end()) {
    std::ostringstream msg;
    msg << "/vessels/mask: " << spec.file << " has no lumen (no pixel at or above the threshold " << spec.threshold
        << ", grey level " << level << " of 255)";
    throw InputError(msg.str());
  }
  const int start = endpoint_pixel(spec, lumen, spec.start, "start");
  const int goal = endpoint_pixel(spec, lumen, spec.goal, "goal");

  MaskTrace trace;
  trace.outline = iso_contours(spec.grey, spec.width, spec.height, level, spec.pixel_size);

  // The minimal path with the step cost d^-4 (d in pixels, >= 1 on lumen): a pixel on the
  // vessel's axis costs (R / d)^4 times less than one beside the wall, so the path keeps to the
  // axis and cuts no bend (minimal paths on a potential, Deschamps & Cohen 2001, grid_path.h).
  // The cost takes the distances' place (and the lumen flags' memory is let go): at the largest
  // image, 8192^2 px, each per-pixel double is half a gigabyte.
  DistanceMap dm = distance_to_background(lumen, spec.width, spec.height);
  std::vector<double> cost = std::move(dm.distance);
  for (std::size_t i = 0; i < cost.size(); ++i) cost[i] = lumen[i] ? std::pow(cost[i], -kCostExponent) : 0.0;
  std::vector<std::uint8_t>().swap(lumen);
  const std::vector<int> pixels = cheapest_grid_path(cost, spec.width, spec.height, start, goal);
  if (pixels.empty()) {
    std::ostringstream msg;
    msg << "/vessels/goal: the goal " << point_text(spec.goal) << " at " << pixel_text(pixel_of(spec, spec.goal))
        << " of " << spec.file << " cannot be reached from the start " << point_text(spec.start) << " at "
        << pixel_text(pixel_of(spec, spec.start)) << " through the lumen (they lie in separate parts of it)";
    throw InputError(msg.str());
  }

  // Pixel centres, with the exact start and goal at the ends; then the staircase smoothed out at
  // one point per pixel, and resampled since smoothing shortens the steps a little.
  Polyline path;
  path.reserve(pixels.size() + 1);
  path.push_back(spec.start);
  for (std::size_t k = 1; k + 1 < pixels.size(); ++k)
    path.push_back(pixel_centre(spec, pixels[k] % spec.width, pixels[k] / spec.width));
  path.push_back(spec.goal);
  path = resample(path, spec.pixel_size);
  smooth(path, kSmoothingPasses);
  trace.centreline = resample(path, spec.pixel_size);
  trace.radius.reserve(trace.centreline.size());
  std::vector<bool> beyond_border;
  for (const Vec2& p : trace.centreline) {
    const LumenRadius r = radius_at(spec, dm, p);
    trace.radius.push_back(r.radius);
    beyond_border.push_back(r.beyond_border);
  }
  // At both ends: the goal may lie at the border too.
  trace.clear_of_border = extend_radius_past_border(spec, trace.centreline, trace.radius, beyond_border);
  Polyline reversed_path(trace.centreline.rbegin(), trace.centreline.rend());
  std::vector<double> reversed_radius(trace.radius.rbegin(), trace.radius.rend());
  extend_radius_past_border(spec, reversed_path, reversed_radius, std::vector<bool>(beyond_border.rbegin(), beyond_border.rend()));
  trace.radius.assign(reversed_radius.rbegin(), reversed_radius.rend());
  return trace;
}

}  // namespace vascsim
