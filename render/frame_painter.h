// Draws one frame of a run on a canvas: the vessel lumen and walls, the reference path, start
// and goal, the tip trail, the rod at its true radius, node markers, the clamp and supports that
// hold it, force arrows, and a panel with the HUD (time, and what the log records of tip error,
// forces and feed), the legend and a scale bar; each is a layer of the View and drawn only when
// on. Pure drawing: it reads a FrameState and the log metadata, and holds only the view, the
// arrow scales and which runs failed, fixed for a whole video.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include "render/canvas.h"
#include "render/frame_source.h"
#include "render/number_format.h"
#include "render/polygon_fill.h"
#include "render/support_symbols.h"
#include "render/view.h"

namespace vascsim::render {

// Arrow scales fixed for a whole video so arrows compare across frames, with the round
// reference value shown in the legend.
struct ForceScales {
  double actuation_px_per_newton = 0, contact_px_per_newton = 0;  // 0: channel absent or zero
  double actuation_reference = 0, contact_reference = 0;          // N, legend arrow values
  double actuation_max_px = 1e9, contact_max_px = 1e9;            // px, longer arrows are capped
  // Friction draws at the contact scale (both are the wall's reaction, so their lengths compare);
  // drag has its own.
  double drag_px_per_newton = 0, drag_reference = 0, drag_max_px = 1e9;
  DisplayUnit unit{1e3, "mN"};
};

// The typical large force of each kind over the whole run (N): what the automatic arrow scales
// are chosen from. Depends on the log only, so a server measures it once per log length.
struct ForcePeaks {
  double actuation = 0, contact = 0, drag = 0;
};
ForcePeaks measure_force_peaks(const FrameSource& source);
// The scales for `view` from `peaks`: the typical force draws a fixed fraction of the frame;
// explicit px-per-newton values in `view` win and are never capped.
ForceScales scales_for(const ForcePeaks& peaks, const View& view);

// The 95th percentile of the non-zero values (their maximum if fewer than 20): a start-up
// spike must not shrink every other arrow of a video or plot to nothing.
double typical_peak(std::vector<double> values);

// scales_for(measure_force_peaks(source), view): from the whole run (at most ~2000 frames
// sampled), not the rendered window, so a clip draws the same arrows as the full video.
ForceScales choose_force_scales(const FrameSource& source, const View& view);

// The map layers that draw something for a log with `metadata` and the channels of `header`: the
// lumen (or the bounds' backdrop) and walls of the run's vessel, its path (or the logged tip
// reference) and its start and goal, the clamp and supports where the scene holds the rod, and
// each force's arrows only if the log records that force.
// The rod, trail, node markers, HUD and legend draw for every log. The replay page greys out the
// others, so a reviewer does not look for magnetic arrows in a run only pushed from its root.
LayerSet layers_with_content(const LogMetadata& metadata, const FrameLogHeader& header);
// What a layer draws that a log may lack, as a phrase ("a magnetic force"), for saying why it
// draws nothing (`vascsim render --layers`, the replay page's greyed-out boxes); "" for the
// layers that draw for every log.
const char* layer_content_phrase(Layer layer);

// The runs in the picture that ended early: failed or stopped (their summary.json says so), or
// killed before writing one (FrameSource::ended_early()), each with the time it had reached. The
// HUD says so in red on every frame, so no picture of such a run passes for a finished one, nor a
// compared rod that stops moving for one that stopped of its own accord.
struct RunsEndedEarly {
  std::optional<EarlyEnd> run;      // the run whose map is painted
  std::optional<EarlyEnd> overlay;  // the compared run drawn over it (given only with one)
  int count() const { return static_cast<int>(run.has_value()) + static_cast<int>(overlay.has_value()); }
};

// Where the world lands on screen: world (x, y) m is drawn at pixel (ox + scale x, oy - scale y).
struct ViewTransform {
  double scale = 1;        // px per m
  double ox = 0, oy = 0;   // px
};

class FramePainter {
 public:
  // `first_frame`: the log's frame 0 (the fit camera of a log without bounds frames it; the HUD
  // has a row for each quantity it records).
  FramePainter(const LogMetadata& metadata, const View& view, const ForceScales& scales,
               const FrameState& first_frame, const RunsEndedEarly& ended_early = {});
  // `trail`: tip positions so far (m), oldest first. `overlay`: another run's state at the same
  // time, whose rod is drawn over this run's map (compare mode), or null.
  void paint(Canvas& canvas, const FrameState& frame, const std::vector<Vec2>& trail,
             const FrameState* overlay = nullptr);
  // World (m) to pixel (y down) for the camera of `frame`; tests use it to find things.
  glm::dvec2 to_pixel(const FrameState& frame, Vec2 world) const;
  ViewTransform transform(const FrameState& frame) const;
  double pixels_per_metre() const { return scale_; }
  // What the panel (or the HUD card of a narrow frame) drew on the last frame, top to bottom,
  // with the box it was laid out in (px): the HUD (in a narrow frame, its whole card), each
  // legend entry, the scale bar. Entries that do not fit a short frame are left out; tests check
  // that none overlaps another.
  struct PanelItem {
    const char* what;  // "hud", "legend" or "scale bar"
    float left, right, top, bottom;
    std::string label;  // a legend entry's text ("reference path", "Magnetic force")
  };
  const std::vector<PanelItem>& panel_items() const { return panel_items_; }
  // The HUD's rows as last painted: the label shown (shortened, or none, where the value needs
  // the room) and where it ends and its value starts (px).
  struct HudField {
    const char* label;  // "" for none
    float label_right, value_left;
    std::string value;  // as drawn: "5.00 mN"
  };
  const std::vector<HudField>& hud_fields() const { return hud_fields_; }

 private:
  glm::dmat3 camera(const FrameState& frame) const;
  void paint_world(Canvas& c, const glm::dmat3& m, const FrameState& f, const std::vector<Vec2>& trail,
                   const FrameState* overlay);
  void paint_lumen(Canvas& c, const glm::dmat3& m);
  // px, the rod as the map draws it: its true radius, never thinner than min_rod_width_px.
  float rod_radius_px() const;
  void paint_rod(Canvas& c, const glm::dmat3& m, const FrameState& f, Rgba body, Rgba edge, Rgba tip);
  void paint_supports(Canvas& c) const;
  std::vector<SupportKind> supports_drawn(std::size_t nodes) const;
  void paint_support_key(Canvas& c, SupportKind kind, glm::vec2 top_left, int fs) const;
  glm::vec2 arrow_vector(const Vec2& px, double max_px) const;
  void paint_arrows(Canvas& c, const std::vector<double>& forces, double px_per_newton, double max_px, float width,
                    Rgba colour);
  void paint_panel(Canvas& c, const FrameState& f);
  // px per N of a force layer's arrows, on the map and in the legend alike; 0 where the layer is
  // off (the map draws no such arrow, so the legend explains none).
  double arrow_scale(Layer layer) const;
  // Whether the map draws the reference path and the start and goal markers: their layer is on
  // and the run has them (a free rod's has neither).
  bool path_drawn() const;
  bool start_goal_drawn() const;
  float card_bottom() const;  // px, lower edge of the HUD card of frames without a side panel
  // px, how far below the panel's or card's top the HUD's last row of text reaches
  float hud_text_bottom() const;
  float band_height() const;  // px, the legend band below the map of frames without a side panel
  void paint_band(Canvas& c) const;

  LogMetadata meta_;
  View view_;
  ForceScales scales_;
  RunsEndedEarly ended_early_;
  Box2 world_;                    // m, what the fit camera shows
  float map_x0_, map_x1_;         // px, the map's horizontal extent (the panel takes the rest)
  float map_y0_;                  // px, top of the map (below the HUD card of narrow frames)
  float map_y1_;                  // px, bottom of the map (above the legend band of narrow frames)
  bool side_panel_;
  bool title_line_ = true;        // the HUD keeps a line for the title (not on a frame too short)
  // The HUD shows what the log records (from its first frame): a rod only pushed from its root
  // has no tip error or magnetic force to show, and its feed instead.
  struct HudQuantities {
    bool tip_error = false, magnetic = false, feed = false, contact = false;
    int rows() const { return 1 + tip_error + magnetic + 2 * feed + contact; }  // time first
  } hud_quantities_;
  bool overlay_shown_ = false;    // the frame being painted shows another run's rod
  double scale_ = 1;              // px per m
  int font_px_;
  float hud_row_ = 0;             // px from one HUD row to the next (closer in a frame too short)
  std::vector<glm::vec2> scratch_;
  std::vector<PanelItem> panel_items_;
  std::vector<HudField> hud_fields_;
  bool lumen_is_box_ = false;              // meta_.lumen is one axis-aligned rectangle, lumen_box_
  Box2 lumen_box_;                         // m
  std::vector<Triangle> lumen_triangles_;  // m, meta_.lumen's interior unless lumen_is_box_
  std::vector<glm::vec2> lumen_px_;        // px, lumen_triangles_ on this frame, 3 per triangle
  std::vector<std::vector<glm::vec2>> outline_px_;  // px, meta_.lumen on this frame
};

}  // namespace vascsim::render
