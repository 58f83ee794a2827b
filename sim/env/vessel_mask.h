// A vessel network traced from an image (the scene's `vessels.mask`, issue 12): white lumen on
// black, as a segmentation or a drawn phantom gives it. From the grey pixels alone (the scene
// reader has loaded them; nothing here touches a file) it makes what a vessel Environment needs:
// the wall as sub-pixel closed rings (iso_contour.h), and the reference path from the start to
// the goal along the middle of the lumen with the lumen radius along it (distance_transform.h,
// grid_path.h). Coordinates as in iso_contour.h: metres from the image's bottom-left corner, pixel
// (col, row) centred at ((col + 0.5) h, (height - row - 0.5) h), row 0 the top row.
#pragma once

#include <vector>

#include "sim/env/geometry.h"
#include "sim/scene/scene.h"

namespace vascsim {

struct MaskTrace {
  // m, closed rings (last point not repeated) at the grey level threshold * 255: outer boundaries
  // counter-clockwise, holes clockwise; their even-odd interior is the lumen.
  std::vector<Polyline> outline;
  // m, from spec.start to spec.goal exactly, about one point per pixel, without pixel staircase.
  Polyline centreline;
  // m, lumen radius at each centreline point; where the path starts or ends at the image's
  // border, that of the vessel running out of the image there (not the distance to the border).
  std::vector<double> radius;
  // The first centreline point one diameter past the last that has the image's border nearest,
  // where the route starts at the border (0 if it does not): before it the path may bend off the
  // vessel's axis.
  std::size_t clear_of_border = 0;
};

// Uses spec.grey, width, height, pixel_size, threshold, start, goal; spec.file only in messages.
// Throws InputError, with a message starting with a JSON path and naming spec.file and the pixel,
// if no pixel is lumen (at or above the threshold), if the start or the goal is not on a lumen
// pixel (or outside the image), or if the lumen does not connect them; also for a pixel_size or
// threshold out of range.
MaskTrace trace_vessel_mask(const VesselMaskSpec& spec);

}  // namespace vascsim
