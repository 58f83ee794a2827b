// The lumen's wall as traced from a grey image (vessel_mask.h): the iso-contour at one grey level,
// found by marching squares with linear interpolation along the cell edges, so an anti-aliased
// edge gives the wall to a fraction of a pixel. Hand-written because no Debian library gives
// sub-pixel iso-contours without a heavy dependency (VTK's vtkContourFilter); OpenCV's
// findContours traces pixel boundaries only, which is half a pixel of staircase.
//
// Conventions: pixel (col, row), row 0 at the top, has its centre at ((col + 0.5) h, (height - row
// - 0.5) h) metres for pixel size h, so the origin is the image's bottom-left corner and y points
// up. Pixels at or above `level` are inside. Outside the image counts as grey level 0, so the
// contour of a region touching the border runs along the border and every ring closes.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/env/geometry.h"

namespace vascsim {

// Closed rings (the last point is not repeated) in metres, with the inside on their left: outer
// boundaries counter-clockwise, boundaries of holes clockwise. The two ambiguous (saddle)
// configurations of a cell are resolved by the mean of its four corners: at or above `level`
// the two inside corners are joined, else they are kept apart; the decision belongs to the cell
// alone, so rings never cross. Each ring starts at its crossing with the lowest edge index
// (deterministic). level: grey units, in (0, 255]; grey: width * height values, row-major.
std::vector<Polyline> iso_contours(const std::vector<std::uint8_t>& grey, int width, int height, double level,
                                   double pixel_size);

}  // namespace vascsim
