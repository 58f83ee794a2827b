#include "sim/io/scene_sections.h"
#include "sim/scene/input_error.h"

namespace vascsim::io {

std::vector<std::uint8_t> load_mask_pixels(VesselMaskSpec&, const std::string& pointer) {
  throw InputError(pointer + ": image masks are being merged (issue 12)");
}

}  // namespace vascsim::io
