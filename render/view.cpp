#include "render/view.h"

#include <cmath>

#include "sim/io/decimal_text.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

namespace {

constexpr const char* kLayerNames[] = {"lumen",   "walls",    "path",    "start_goal", "trail",
                                       "rod",     "nodes",    "supports", "magnetic",   "contact",
                                       "friction", "drag",    "hud",      "legend"};
static_assert(sizeof(kLayerNames) / sizeof(kLayerNames[0]) == static_cast<std::size_t>(Layer::kCount));

std::string known_layers() {
  std::string s;
  for (const char* n : kLayerNames) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

// Every item, empty ones too: "1,2," is three items (getline would drop the last).
std::vector<std::string> split_commas(const std::string& list) {
  std::vector<std::string> items;
  for (std::size_t begin = 0;;) {
    const std::size_t comma = list.find(',', begin);
    items.push_back(list.substr(begin, comma - begin));
    if (comma == std::string::npos) return items;
    begin = comma + 1;
  }
}

}  // namespace

LayerSet LayerSet::defaults() {
  LayerSet s(0);
  for (int i = 0; i < static_cast<int>(Layer::kCount); ++i) s.set(static_cast<Layer>(i), true);
  return s.set(Layer::kNodes, false).set(Layer::kFriction, false).set(Layer::kDrag, false);
}

LayerSet& LayerSet::set(Layer layer, bool on) {
  bits_ = on ? bits_ | bit(layer) : bits_ & ~bit(layer);
  return *this;
}

const char* layer_name(Layer layer) { return kLayerNames[static_cast<int>(layer)]; }

std::optional<Layer> layer_from_name(const std::string& name) {
  for (int i = 0; i < static_cast<int>(Layer::kCount); ++i)
    if (name == kLayerNames[i]) return static_cast<Layer>(i);
  return std::nullopt;
}

std::vector<std::string> all_layer_names() { return {std::begin(kLayerNames), std::end(kLayerNames)}; }

LayerSet parse_layer_list(const std::string& list) {
  LayerSet s = LayerSet::none();
  if (list.empty()) return s;
  for (const std::string& name : split_commas(list)) {
    // A layer twice or an empty name ("rod,,walls", "rod,") is a list edited by hand or built by
    // a script gone wrong: said, like an unknown name, rather than guessed at.
    if (name.empty())
      throw InputError("an empty layer name in '" + list.substr(0, 64) + "' (expected a comma-separated list of " +
                       known_layers() + ")");
    const auto layer = layer_from_name(name);
    if (!layer)
      throw InputError("unknown layer '" + name.substr(0, 64) + "' (expected a comma-separated list of " +
                       known_layers() + ")");
    if (s.has(*layer)) throw InputError("layer '" + name + "' is listed twice in '" + list.substr(0, 64) + "'");
    s.set(*layer, true);
  }
  return s;
}

std::string format_layer_list(LayerSet layers) {
  std::string s;
  for (int i = 0; i < static_cast<int>(Layer::kCount); ++i)
    if (layers.has(static_cast<Layer>(i))) s += (s.empty() ? "" : ",") + std::string(kLayerNames[i]);
  return s;
}

LayerSet hide_layers(LayerSet base, const std::string& list) {
  const LayerSet hidden = parse_layer_list(list);
  for (int i = 0; i < static_cast<int>(Layer::kCount); ++i)
    if (hidden.has(static_cast<Layer>(i))) base.set(static_cast<Layer>(i), false);
  return base;
}

CameraMode parse_camera(const std::string& name) {
  if (name == "fit") return CameraMode::kFit;
  if (name == "follow") return CameraMode::kFollow;
  if (name == "center" || name == "centre") return CameraMode::kCentre;
  throw InputError("expected fit, follow or center, got '" + name.substr(0, 64) + "'");
}

const char* camera_name(CameraMode mode) {
  switch (mode) {
    case CameraMode::kFit: return "fit";
    case CameraMode::kFollow: return "follow";
    case CameraMode::kCentre: return "center";
  }
  return "fit";
}

Vec2 parse_centre(const std::string& text) {
  const auto parts = split_commas(text);
  auto number = [](const std::string& s, double& out) {
    const std::optional<double> x = io::parse_decimal(s);
    if (x) out = *x;
    return x.has_value();
  };
  Vec2 c;
  if (parts.size() != 2 || !number(parts[0], c.x()) || !number(parts[1], c.y()))
    throw InputError("expected X,Y in metres (two finite numbers), got '" + text.substr(0, 64) + "'");
  // Past the scenes' bounds a view shows nothing; at 1e308 its transform overflowed to NaN.
  constexpr double kMaxCentre = 1e3;  // m: scene geometry lies within 1000 m (sim/io/scene_sections.h)
  if (std::abs(c.x()) > kMaxCentre || std::abs(c.y()) > kMaxCentre)
    throw InputError("expected X,Y in metres within 1000 m of the origin (where scenes lie), got '" + text.substr(0, 64) + "'");
  return c;
}

}  // namespace vascsim::render
