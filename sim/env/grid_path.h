// The cheapest path between two pixels of an image, for a vessel mask's reference centreline
// (vessel_mask.h): Dijkstra's algorithm on the 8-neighbour pixel graph with a per-pixel cost, as
// in minimal-path centreline extraction (Deschamps & Cohen, "Fast extraction of minimal paths in
// 3D images and applications to virtual endoscopy", Medical Image Analysis 5 (2001) 281-299): with
// a cost that falls with the distance from the wall, the cheapest path keeps to the middle.
#pragma once

#include <vector>

namespace vascsim {

// cost: per pixel (row-major, width * height), > 0 and finite where the path may go, anything else
// (infinity, 0) a wall. A step between neighbours costs its length (1 or sqrt 2 pixels) times the
// mean of the two pixels' costs. A diagonal step is taken only if both pixels beside it are
// passable, so the path never cuts a wall's corner. Ties go to the lower pixel index, so the result
// depends on nothing but the input. Returns the pixel indices from start to goal, or an empty
// vector if the goal cannot be reached (or start or goal is a wall).
std::vector<int> cheapest_grid_path(const std::vector<double>& cost, int width, int height, int start, int goal);

}  // namespace vascsim
