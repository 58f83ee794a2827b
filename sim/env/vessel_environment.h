// A vessel network's Environment (environment.h), built from a scene's `vessels` section: the
// graph's tubes and sacs (vessel_lumen.h, vessel_graph.h) or the traced mask (vessel_mask.h), with
// an introducer tube behind the start as the inlet, so the rod starts straight and inside the lumen.
#pragma once

#include "sim/env/environment.h"
#include "sim/scene/scene.h"

namespace vascsim {

// rod_length (m): how far behind the start the introducer reaches. Throws InputError with a
// message starting with a JSON path (e.g. "/vessels/route/2: ...").
Environment build_vessel_environment(const VesselsSpec& spec, double rod_length);

}  // namespace vascsim
