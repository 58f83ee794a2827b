#include "apps/replay/request_params.h"

#include <algorithm>
#include <cstdio>

#include "sim/io/decimal_text.h"
#include "sim/scene/input_error.h"

namespace vascsim::replay {

namespace {

// A parameter value quoted in an error message, cut short: the message must not echo a huge or
// hostile input back. Control characters are shown as \xNN (a NUL, t=1%00, ended the message).
std::string quoted(const std::string& value) {
  std::string shown;
  for (const char c : value.substr(0, 40)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7F) {
      shown += c;
    } else {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
      shown += escaped;
    }
  }
  return "'" + shown + (value.size() > 40 ? "..." : "") + "'";
}

}  // namespace

std::optional<std::string> RequestParams::text(const std::string& name) const {
  const auto it = query_.find(name);
  if (it == query_.end()) return std::nullopt;
  // Which of two values was meant is a guess; a page or script that builds the URL can say. The
  // same value twice (written differently: a and %61) is no question.
  const auto [first, last] = query_.equal_range(name);
  if (std::any_of(first, last, [&](const auto& other) { return other.second != it->second; }))
    throw ParamError(name, "given more than once with different values");
  if (it->second.size() > 4096) throw ParamError(name, "longer than 4096 characters");
  return it->second;
}

std::optional<double> RequestParams::optional_number(const std::string& name, double min, double max) const {
  const auto value = text(name);
  if (!value) return std::nullopt;
  const std::optional<double> parsed = io::parse_decimal(*value);
  if (!parsed) throw ParamError(name, "expected a finite number, got " + quoted(*value));
  const double x = *parsed;
  if (x < min || x > max) {
    char range[64];
    std::snprintf(range, sizeof range, "[%g, %g]", min, max);  // not to_string's "[0.001000, 1000.000000]"
    throw ParamError(name, "expected a number in " + std::string(range) + ", got " + quoted(*value));
  }
  return x;
}

double RequestParams::number(const std::string& name, double fallback, double min, double max) const {
  return optional_number(name, min, max).value_or(fallback);
}

long long RequestParams::integer(const std::string& name, long long fallback, long long min, long long max) const {
  const auto value = text(name);
  if (!value) return fallback;
  const std::optional<long long> parsed = io::parse_decimal_integer(*value);
  if (!parsed) throw ParamError(name, "expected an integer, got " + quoted(*value));
  const long long x = *parsed;
  if (x < min || x > max)
    throw ParamError(name, "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                               quoted(*value));
  return x;
}

std::string RequestParams::choice(const std::string& name, const std::string& fallback,
                                  const std::vector<std::string>& choices) const {
  const auto value = text(name);
  if (!value) return fallback;
  for (const auto& c : choices)
    if (*value == c) return c;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  throw ParamError(name, "expected one of " + list + ", got " + quoted(*value));
}

render::View parse_view(const RequestParams& p) {
  render::View v;
  v.width = static_cast<int>(p.integer("width", v.width, 16, kMaxFrameSide));
  v.height = static_cast<int>(p.integer("height", v.height, 16, kMaxFrameSide));
  v.zoom = p.number("zoom", 1.0, 1e-3, 1e3);
  try {
    if (const auto centre = p.text("center")) {
      v.centre = render::parse_centre(*centre);
      v.camera = render::CameraMode::kCentre;
    }
  } catch (const InputError& e) {
    throw ParamError("center", e.what());
  }
  const std::string camera = p.choice("camera", render::camera_name(v.camera), {"fit", "follow", "center"});
  v.camera = render::parse_camera(camera);
  if (v.camera == render::CameraMode::kCentre && !p.text("center"))
    throw ParamError("center", "camera=center needs center=X,Y (metres)");
  if (v.camera != render::CameraMode::kCentre && p.text("center"))
    throw ParamError("center", "center=X,Y goes with camera=center (or no camera), not camera=" + camera);
  try {
    if (const auto layers = p.text("layers")) v.layers = render::parse_layer_list(*layers);
  } catch (const InputError& e) {
    throw ParamError("layers", e.what());
  }
  return v;
}

}  // namespace vascsim::replay
