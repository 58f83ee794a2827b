// The colours that mean the same thing in videos, frames and plots (a force arrow is the same
// purple or orange everywhere, so a reader learns them once). Colours that only one of them uses
// stay in its own file.
#pragma once

#include "render/canvas.h"

namespace vascsim::render::palette {

constexpr Rgba kInk = hex(0x212529);        // text, axes
constexpr Rgba kActuation = hex(0xAE3EC9);  // magnetic (actuation) force arrows and curves
constexpr Rgba kContact = hex(0xE8590C);    // wall contact force arrows and curves
constexpr Rgba kFailure = hex(0xC92A2A);    // a run failed or was stopped: the HUD row, the plots' note; sweep failed counts

}  // namespace vascsim::render::palette
