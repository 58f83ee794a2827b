// Draws one video frame of a run on a canvas: the vessel lumen and walls, the reference path,
// start and goal, the tip trail, the rod at its true radius, force arrows, and a side panel with
// the HUD (time, tip error, forces), the legend and a scale bar. Pure drawing: it reads a
// FrameState and the log metadata, and holds only the view settings fixed for a whole video.
#pragma once

#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include "render/canvas.h"
#include "render/frame_source.h"
#include "render/number_format.h"

namespace vascsim::render {

enum class CameraMode { kFit, kFollow };

struct ViewOptions {
  int width = 1280, height = 720;  // px
  CameraMode camera = CameraMode::kFit;
  double zoom = 1.0;               // magnification over the fitted view (follow: around the tip)
  // Arrow lengths: px per newton; 0 chooses them from the largest force in the rendered range.
  double actuation_px_per_newton = 0;
  double contact_px_per_newton = 0;
  double min_rod_width_px = 3.0;   // the rod is drawn at least this wide
  bool panel = true;               // HUD, legend and scale bar
};

// Arrow scales fixed for a whole video so arrows compare across frames, with the round
// reference value shown in the legend.
struct ForceScales {
  double actuation_px_per_newton = 0, contact_px_per_newton = 0;  // 0: channel absent or zero
  double actuation_reference = 0, contact_reference = 0;          // N, legend arrow values
  double actuation_max_px = 1e9, contact_max_px = 1e9;            // px, longer arrows are capped
  DisplayUnit unit{1e3, "mN"};
};

// The 95th percentile of the non-zero values (their maximum if fewer than 20): a start-up
// spike must not shrink every other arrow of a video or plot to nothing.
double typical_peak(std::vector<double> values);

// Chooses ForceScales from the whole run (at most ~2000 frames sampled), not the rendered
// window, so a clip draws the same arrows as the full video: the 95th percentile of the force
// draws a fixed fraction of the frame. Explicit px-per-newton values in `view` win and are
// never capped.
ForceScales choose_force_scales(const FrameSource& source, const ViewOptions& view);

class FramePainter {
 public:
  FramePainter(const LogMetadata& metadata, const ViewOptions& view, const ForceScales& scales,
               const FrameState& first_frame);
  // `trail`: tip positions so far (m), oldest first.
  void paint(Canvas& canvas, const FrameState& frame, const std::vector<Vec2>& trail);
  // World (m) to pixel (y down) for the camera of `frame`; tests use it to find things.
  glm::dvec2 to_pixel(const FrameState& frame, Vec2 world) const;
  double pixels_per_metre() const { return scale_; }

 private:
  glm::dmat3 camera(const FrameState& frame) const;
  void paint_world(Canvas& c, const glm::dmat3& m, const FrameState& f, const std::vector<Vec2>& trail);
  void paint_panel(Canvas& c, const FrameState& f);
  float card_bottom() const;  // px, lower edge of the HUD card of frames without a side panel
  float band_height() const;  // px, the legend band below the map of frames without a side panel
  void paint_band(Canvas& c) const;

  LogMetadata meta_;
  ViewOptions view_;
  ForceScales scales_;
  Box2 world_;                    // m, what the fit camera shows
  float map_x0_, map_x1_;         // px, the map's horizontal extent (the panel takes the rest)
  float map_y0_;                  // px, top of the map (below the HUD card of narrow frames)
  float map_y1_;                  // px, bottom of the map (above the legend band of narrow frames)
  bool side_panel_;
  double scale_ = 1;              // px per m
  int font_px_;
  std::vector<glm::vec2> scratch_;
};

}  // namespace vascsim::render
