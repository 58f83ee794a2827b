#include "sim/io/sweep_spec.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "sim/io/bounded_read.h"
#include "sim/io/file_kind.h"
#include "sim/io/json_fields.h"
#include "sim/scene/input_error.h"

namespace vascsim {

using nlohmann::json;

namespace {

// Range values are rounded to 12 significant digits, so 0.1 + 2 * 0.1 is written 0.3 and not
// 0.30000000000000004 in scenes, manifests and tables.
double round12(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.12g", x);
  return std::strtod(text, nullptr);
}

// Whether one pointer is the other or lies inside it ("/control" and "/control/kp").
bool overlaps(const std::string& a, const std::string& b) {
  const auto inside = [](const std::string& outer, const std::string& inner) {
    return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 && inner[outer.size()] == '/';
  };
  return a == b || inside(a, b) || inside(b, a);
}

// A pointer's syntax: empty (the whole scene) is refused, and every token must start with '/'
// and use only the escapes ~0 and ~1.
void check_pointer(const std::string& pointer, const std::string& label, const std::string& where) {
  bool ok = !pointer.empty() && pointer[0] == '/';
  for (std::size_t i = 0; ok && i < pointer.size(); ++i)
    if (pointer[i] == '~') ok = i + 1 < pointer.size() && (pointer[i + 1] == '0' || pointer[i + 1] == '1');
  if (!ok)
    throw InputError(label + ": " + where + ": expected a JSON pointer into the scene such as \"/control/kp\", got " +
                     json(pointer).dump());
}

// {"from": a, "to": b[, "step": s | "count": n[, "scale": "linear" | "log"]]} as values.
std::vector<std::string> read_range(const json& range, const std::string& label, const std::string& where) {
  io::FieldReader in(range, label, where);
  for (const char* key : {"from", "to"})
    if (!in.has(key))
      throw InputError(label + ": " + in.pointer_of(key) + ": missing (a range needs \"from\" and \"to\", numbers)");
  const double from = in.number("from", 0, -1e300, 1e300);
  const double to = in.number("to", 0, -1e300, 1e300);
  if (to < from) in.fail("to", "a number >= \"from\" (" + io::format_number(from) + ")", range["to"]);
  if (in.has("step") && in.has("count")) in.fail("count", "either \"step\" or \"count\", not both", range["count"]);
  const std::string scale = in.choice("scale", "linear", {"linear", "log"});
  if (scale == "log" && in.has("step")) in.fail("step", "\"count\" with \"scale\": \"log\"", range["step"]);
  if (scale == "log" && !(from > 0)) in.fail("from", "a number > 0 with \"scale\": \"log\"", range["from"]);
  const long long max_count = static_cast<long long>(kMaxSweepRuns);
  std::vector<std::string> values;
  // Integer bounds and step give integers (seeds, node counts); 2^53 keeps them exact as doubles.
  const auto exact_integer = [&](const char* key) {
    return range[key].is_number_integer() && std::fabs(range[key].get<double>()) <= 9007199254740992.0;
  };
  if (in.has("count")) {
    const long long count = in.integer("count", 2, 1, max_count);
    if (count == 1 && to != from) in.fail("count", "an integer >= 2 when \"to\" differs from \"from\"", range["count"]);
    // Between integer bounds, a value that falls on an integer is one (5 to 9 in 3 values is
    // 5, 7, 9, which an integer field takes; it was 5.0, 7.0, 9.0, which it refuses).
    const bool integer_bounds = exact_integer("from") && exact_integer("to");
    for (long long i = 0; i < count; ++i) {
      const double f = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
      const double x = round12(i == count - 1 ? to : scale == "log" ? from * std::pow(to / from, f) : from + f * (to - from));
      values.push_back(integer_bounds && x == std::round(x) ? json(static_cast<long long>(x)).dump() : json(x).dump());
    }
    in.finish();
    return values;
  }
  const bool integers = exact_integer("from") && exact_integer("to") && (!in.has("step") || exact_integer("step"));
  const double step = in.positive("step", 1.0);
  // A step that does not divide the span stops at the last value <= "to" (the tolerance keeps
  // 0.1 .. 0.3 step 0.1 at three values despite rounding).
  const double span = (to - from) / step;
  if (!(span < static_cast<double>(max_count)))
    in.fail(in.has("step") ? "step" : "to", "at most " + std::to_string(max_count) + " values in the range",
            in.has("step") ? range["step"] : range["to"]);
  const long long count = static_cast<long long>(std::floor(span + 1e-9)) + 1;
  // As for "count": between integer bounds a value on an integer is one, whatever the step is
  // written as (1 to 3 step 1.0 gave 1.0, 2.0, 3.0, which /maze/seed refuses).
  const bool integer_bounds = exact_integer("from") && exact_integer("to");
  for (long long i = 0; i < count; ++i) {
    if (integers) {
      values.push_back(json(range["from"].get<long long>() + i * range.value("step", json(1)).get<long long>()).dump());
    } else {
      const double x = round12(from + static_cast<double>(i) * step);
      values.push_back(integer_bounds && x == std::round(x) ? json(static_cast<long long>(x)).dump() : json(x).dump());
    }
  }
  in.finish();
  return values;
}

// An axis's values: a non-empty list of JSON values, or a range object.
std::vector<std::string> read_values(const json& v, const std::string& label, const std::string& where) {
  if (v.is_object()) return read_range(v, label, where);
  if (!v.is_array() || v.empty())
    throw InputError(label + ": " + where +
                     ": expected a non-empty list of values or a range {\"from\": a, \"to\": b}, got " + io::describe(v));
  if (v.size() > kMaxSweepRuns)
    throw InputError(label + ": " + where + ": more than " + std::to_string(kMaxSweepRuns) + " values");
  std::vector<std::string> values;
  for (const auto& item : v) values.push_back(item.dump());
  return values;
}

// A value given twice on one axis of a product sweep (2 and 2.0 are one value): each of its runs
// would be made twice, and the per-value summary would count them under two rows. Refused,
// naming both places; "repeats" runs a setting more than once. Sorted, not compared pairwise: an
// axis may hold 100000 values.
void check_distinct_values(const SweepAxis& axis, const json& given, const std::string& label) {
  std::vector<json> values;
  values.reserve(axis.values.size());
  for (const auto& v : axis.values) values.push_back(json::parse(v));
  std::vector<std::size_t> order(values.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t first = order[k - 1], again = order[k];
    if (!(values[first] == values[again])) continue;
    const std::string where = "/axes/" + io::escape_pointer_token(axis.pointer);
    const bool listed = given.is_array();
    throw InputError(label + ": " + where + (listed ? "/" + std::to_string(again) : "") + ": the value " +
                     values[again].dump() + " is given twice" +
                     (listed ? " (also at " + where + "/" + std::to_string(first) + ")" : " (the range rounds two steps to it)") +
                     ": each run would be made twice; use \"repeats\" to run a setting more than once");
  }
}

// The keys of a JSON object in the order the file writes them (nlohmann::json sorts them; the
// order of the axes is the user's: the first varies slowest, columns appear in that order).
std::vector<std::string> keys_in_file_order(const std::string& text, const std::string& key) {
  const nlohmann::ordered_json root = nlohmann::ordered_json::parse(text);
  std::vector<std::string> keys;
  for (auto it = root[key].begin(); it != root[key].end(); ++it) keys.push_back(it.key());
  return keys;
}

}  // namespace

SweepSpec read_sweep_text(const std::string& text, const std::string& label) {
  const json root = io::parse_json_strictly(text, label);
  io::FieldReader in(root, label, "");
  SweepSpec spec;
  spec.file = label;
  if (!in.has("format")) throw InputError(label + ": /format: missing (expected \"vascsim-sweep/1\")");
  io::check_format(root, "vascsim-sweep/1", label);
  in.text("format", "");
  spec.name = in.text("name", std::filesystem::path(label).stem().string());
  if (spec.name.empty() || spec.name.size() > 64 || spec.name.find_first_of("/\\\n\r\t\"'$`") != std::string::npos)
    in.fail("name", "a name of 1 to 64 characters without slashes, quotes or '$'", root["name"]);
  in.text("description", "");
  spec.scene = in.text("scene", "");
  if (spec.scene.empty()) {
    if (!in.has("scene")) throw InputError(label + ": /scene: missing (the base scene file, relative to the sweep file)");
    in.fail("scene", "the base scene file, relative to the sweep file", root["scene"]);
  }
  const std::filesystem::path scene(spec.scene);
  spec.scene_path = scene.is_absolute() ? spec.scene : (std::filesystem::path(label).parent_path() / scene).string();

  spec.combine = in.choice("combine", "product", {"product", "zip"}) == "zip" ? SweepCombine::kZip : SweepCombine::kProduct;
  spec.repeats = static_cast<int>(in.integer("repeats", 1, 1, 10000));

  const json* axes = in.raw("axes");
  if (!axes || !axes->is_object() || axes->empty())
    in.fail("axes", std::string(axes && axes->is_object() ? "at least one axis: " : "") +
                        "an object of JSON pointers into the scene, each with its values: {\"/control/kp\": [2, 4, 8]}",
            axes ? *axes : json(nullptr));
  for (const std::string& key : keys_in_file_order(text, "axes")) {
    const std::string where = "/axes/" + io::escape_pointer_token(key);
    check_pointer(key, label, where);
    for (const auto& axis : spec.axes)
      if (overlaps(axis.pointer, key))
        throw InputError(label + ": " + where + ": " + key + " overlaps the axis " + axis.pointer +
                         "; a run's value would depend on which is applied last (name each field once)");
    spec.axes.push_back({key, read_values((*axes)[key], label, where)});
    if (spec.combine == SweepCombine::kProduct) check_distinct_values(spec.axes.back(), (*axes)[key], label);
  }
  if (const json* fixed = in.raw("overrides")) {
    if (!fixed->is_object()) in.fail("overrides", "an object of JSON pointers into the scene and their values", *fixed);
    for (const std::string& key : keys_in_file_order(text, "overrides")) {
      const std::string where = "/overrides/" + io::escape_pointer_token(key);
      check_pointer(key, label, where);
      for (const auto& axis : spec.axes) {
        if (axis.pointer == key)
          throw InputError(label + ": " + where + ": " + key + " is also an axis; an override is fixed for every run");
        if (overlaps(axis.pointer, key))
          throw InputError(label + ": " + where + ": " + key + " overlaps the axis " + axis.pointer +
                           "; an override inside an axis's value, or around it, would change what the axis sets");
      }
      for (const auto& [other, value] : spec.overrides)
        if (overlaps(other, key))
          throw InputError(label + ": " + where + ": " + key + " overlaps the override " + other +
                           "; the result would depend on which is applied last");
      spec.overrides.emplace_back(key, (*fixed)[key].dump());
    }
  }
  in.finish();

  // The size is checked here, before anything is expanded.
  if (spec.combine == SweepCombine::kZip)
    for (const auto& axis : spec.axes)
      if (axis.values.size() != spec.axes.front().values.size())
        throw InputError(label + ": /axes/" + io::escape_pointer_token(axis.pointer) + ": expected " +
                         std::to_string(spec.axes.front().values.size()) + " values (as many as " +
                         spec.axes.front().pointer + ", with \"combine\": \"zip\"), got " +
                         std::to_string(axis.values.size()));
  double runs = spec.repeats;
  if (spec.combine == SweepCombine::kZip) runs *= static_cast<double>(spec.axes.front().values.size());
  else
    for (const auto& axis : spec.axes) runs *= static_cast<double>(axis.values.size());
  if (runs > static_cast<double>(kMaxSweepRuns))
    throw InputError(label + (spec.repeats > 1 ? ": /axes and /repeats: " : ": /axes: ") + "the sweep has " +
                     io::format_number(runs) + " runs" +
                     (spec.repeats > 1 ? " (" + io::format_number(runs / spec.repeats) + " settings, each " +
                                             std::to_string(spec.repeats) + " times)"
                                       : "") +
                     ", more than the limit of " + std::to_string(kMaxSweepRuns));
  return spec;
}

std::string read_sweep_file_text(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(path + ": not a regular file (a sweep is read from a JSON file)");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open sweep file (" + std::strerror(errno) + ")");
  const std::string text = io::read_at_most(file, kMaxSweepFileBytes);
  if (file.bad()) throw InputError(path + ": cannot read sweep file");
  if (text.size() > kMaxSweepFileBytes)
    throw InputError(path + ": larger than " + std::to_string(kMaxSweepFileBytes >> 20) + " MiB, the limit for a sweep file");
  return text;
}

SweepSpec read_sweep_file(const std::string& path) { return read_sweep_text(read_sweep_file_text(path), path); }

std::size_t sweep_run_count(const SweepSpec& spec) {
  std::size_t n = static_cast<std::size_t>(spec.repeats);
  if (spec.combine == SweepCombine::kZip) return n * spec.axes.front().values.size();
  for (const auto& axis : spec.axes) n *= axis.values.size();
  return n;
}

}  // namespace vascsim
