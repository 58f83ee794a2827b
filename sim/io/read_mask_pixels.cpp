#include <string>

#include "sim/io/png_file.h"
#include "sim/io/provenance.h"
#include "sim/io/scene_sections.h"
#include "sim/scene/input_error.h"

namespace vascsim::io {

std::vector<std::uint8_t> load_mask_pixels(VesselMaskSpec& spec, const std::string& scene_file, const std::string& pointer) {
  try {
    GreyImage image = load_grey_png(spec.resolved);
    spec.width = image.width;
    spec.height = image.height;
    std::vector<std::uint8_t> grey = std::move(image.grey);
    spec.pixel_hash = mask_pixel_hash(spec.width, spec.height, grey);
    return grey;
  } catch (const InputError& e) {
    // The PNG reader names the image; the scene file and its path say which field named it.
    throw InputError(scene_file + ": " + pointer + ": " + e.what());
  }
}

std::string mask_pixel_hash(int width, int height, const std::vector<std::uint8_t>& grey) {
  std::string bytes = std::to_string(width) + "x" + std::to_string(height) + ":";
  bytes.append(grey.begin(), grey.end());
  return scene_hash(bytes);
}

}  // namespace vascsim::io
