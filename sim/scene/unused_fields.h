// Which fields of a scene its own configuration leaves unused: the barrier's settings under the
// paper's penalty, error control's tolerances with a fixed step, a sine's frequency on a constant
// load, a route's speed in free space. One list serves both directions, so they cannot drift
// apart: the scene reader warns of each one a file gives (the run goes on as if it were not
// there; a sweep that switches a mode keeps working), and the canonical writer leaves them all
// out, so the scene a log stores reads back without a warning.
#pragma once

#include <vector>

#include "sim/scene/scene.h"

namespace vascsim {

// Every field `scene`'s configuration does not use, whether or not its file gave it, in the
// order of the scene file's sections. Depends only on fields that are used (modes, switches,
// profiles), so a scene read back from its canonical text has the same list.
std::vector<UnusedField> unused_fields(const Scene& scene);

}  // namespace vascsim
