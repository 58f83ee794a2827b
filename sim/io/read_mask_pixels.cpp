#include "sim/io/png_file.h"
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

}  // namespace vascsim::io
