#include "sim/env/vessel_environment.h"

#include "sim/scene/input_error.h"

namespace vascsim {

Environment build_vessel_environment(const VesselsSpec&, double) {
  throw InputError("/vessels: vessel networks are being written (issue 12)");
}

}  // namespace vascsim
