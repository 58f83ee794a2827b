// The view: everything that decides which pixels a frame of a run becomes, as one plain value
// (frame size, camera, layer flags, arrow scales). `vascsim render` fills it from its options, the
// replay server from a request's parameters; both hand it to the same painter, so a view seen in
// the browser and the equivalent command line give identical pixels (MuJoCo's mjvOption plays
// this part). Layers name what is drawn, so a reviewer can hide the trail or show the drag forces
// without a new renderer.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/env/geometry.h"

namespace vascsim::render {

enum class CameraMode {
  kFit,     // the whole environment
  kFollow,  // centred on the tip
  kCentre,  // centred on View::centre
};

// What a frame can show. The order is the drawing order of the map layers.
enum class Layer : int {
  kLumen, kWalls, kPath, kStartGoal, kTrail, kRod, kNodes, kSupports,
  kMagnetic, kContact, kFriction, kDrag,
  kHud, kLegend,
  kCount
};

class LayerSet {
 public:
  // All but node markers, friction and drag arrows: the look of the review videos.
  static LayerSet defaults();
  static LayerSet none() { return LayerSet(0); }
  bool has(Layer layer) const { return bits_ & bit(layer); }
  LayerSet& set(Layer layer, bool on);
  bool operator==(const LayerSet& other) const { return bits_ == other.bits_; }
  bool operator!=(const LayerSet& other) const { return bits_ != other.bits_; }

 private:
  explicit LayerSet(std::uint32_t bits) : bits_(bits) {}
  static std::uint32_t bit(Layer layer) { return 1u << static_cast<int>(layer); }
  std::uint32_t bits_;
};

// "lumen", "walls", "path", "start_goal", "trail", "rod", "nodes", "supports", "magnetic",
// "contact", "friction", "drag", "hud", "legend".
const char* layer_name(Layer layer);
std::optional<Layer> layer_from_name(const std::string& name);
std::vector<std::string> all_layer_names();
// "a,b,c" to a set; "" is no layer. Throws InputError naming the unknown layer and the known ones
// (an empty name or one given twice, too). The parsers' messages do not name the option or URL
// parameter the text came from: the caller does.
LayerSet parse_layer_list(const std::string& list);
// The set as "a,b,c", in drawing order.
std::string format_layer_list(LayerSet layers);
// `base` without the layers in "a,b" (the --hide option).
LayerSet hide_layers(LayerSet base, const std::string& list);

// "fit", "follow", "center" (and "centre"). Throws InputError otherwise.
CameraMode parse_camera(const std::string& name);
const char* camera_name(CameraMode mode);
// "X,Y" in metres, both finite and within 1000 m of the origin, where scene
// geometry lies. Throws InputError otherwise.
Vec2 parse_centre(const std::string& text);

struct View {
  int width = 1280, height = 720;  // px
  CameraMode camera = CameraMode::kFit;
  double zoom = 1.0;               // magnification over the fitted view
  Vec2 centre = Vec2::Zero();      // m, the map's centre with CameraMode::kCentre
  LayerSet layers = LayerSet::defaults();
  // Arrow lengths: px per newton; 0 chooses them from the run's typical force.
  double actuation_px_per_newton = 0;
  double contact_px_per_newton = 0;
  double min_rod_width_px = 3.0;   // the rod is drawn at least this wide

  // The HUD or the legend is on: the frame has a panel (beside the map, or bands above and
  // below it on narrow frames).
  bool panel() const { return layers.has(Layer::kHud) || layers.has(Layer::kLegend); }
  bool side_panel() const { return panel() && width >= 1.2 * height; }
};

}  // namespace vascsim::render
