// Exact Euclidean distance transform of a binary image, for tracing vessel masks (vessel_mask.h):
// for every pixel, the distance from its centre to the centre of the nearest background pixel,
// and which pixel that is. The minimal-path step cost falls with this distance (so the path keeps
// to the middle of the lumen), and the lumen radius along the centreline comes from it.
// Everything outside the image counts as background, so lumen touching the border has a finite
// distance there, as the traced wall closes along the border (iso_contour.h).
#pragma once

#include <cstdint>
#include <vector>

namespace vascsim {

struct DistanceMap {
  int width = 0, height = 0;        // px
  std::vector<double> distance;     // px, per pixel (row-major, row 0 at the top); 0 on background
  // The nearest background pixel of each pixel, as column and row; -1 or width (height) when it
  // is just outside the image.
  std::vector<int> nearest_col, nearest_row;
};

// `inside`: nonzero for foreground (lumen) pixels, row-major, width * height entries.
DistanceMap distance_to_background(const std::vector<std::uint8_t>& inside, int width, int height);

}  // namespace vascsim
