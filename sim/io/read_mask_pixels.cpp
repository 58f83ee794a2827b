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
    return std::move(image.grey);
  } catch (const InputError& e) {
    // The PNG reader names the image; the scene file and its path say which field named it.
    throw InputError(scene_file + ": " + pointer + ": " + e.what());
  }
}

std::string mask_pixel_hash(const VesselMaskSpec& spec) {
  std::string bytes = std::to_string(spec.width) + "x" + std::to_string(spec.height) + ":";
  bytes.append(spec.grey.begin(), spec.grey.end());
  return scene_hash(bytes);
}

}  // namespace vascsim::io
