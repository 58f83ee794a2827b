#include "sim/io/sweep_results.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "sim/io/json_fields.h"

namespace vascsim {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

// A number as JSON writes it: the shortest text that reads back to the same double, so the
// table is exact and its bytes depend only on the value. Unknown values are empty cells.
std::string number_cell(double v) {
  if (!std::isfinite(v)) return "";
  if (v == std::floor(v) && std::fabs(v) < 9007199254740992.0) return std::to_string(static_cast<long long>(v));
  return json(v).dump();
}

// RFC 4180: a cell with a comma, a quote or a line break is quoted, its quotes doubled.
std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

ordered_json number_json(double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr); }
// A count as an integer ("steps": 19, not 19.0), as results.csv writes it.
ordered_json metric_json(double v, const SweepMetric& metric) {
  if (metric.whole && std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9007199254740992.0)
    return ordered_json(static_cast<long long>(v));
  return number_json(v);
}

}  // namespace

const std::vector<std::string>& sweep_timing_columns() {
  static const std::vector<std::string> columns = {"wall_time_s", "real_time_factor", "process_time_s", "cpu_time_s",
                                                   "host"};
  return columns;
}

std::string sweep_value_text(const std::string& value_json) {
  const json v = json::parse(value_json);
  return v.is_string() ? v.get<std::string>() : value_json;
}

bool sweep_axis_numbers(const SweepAxis& axis, std::vector<double>& numbers) {
  numbers.clear();
  for (const auto& v : axis.values) {
    const json j = json::parse(v);
    if (!j.is_number()) return false;
    numbers.push_back(j.get<double>());
  }
  return true;
}

std::string sweep_results_csv(const SweepManifest& m, const std::vector<RunOutcome>& outcomes) {
  std::vector<std::string> header = {"index", "id", "repeat"};
  for (const auto& a : m.axes) header.push_back(a.pointer);
  header.push_back("status");
  for (const auto& metric : sweep_metrics()) header.push_back(metric.column);
  header.push_back("failure");
  for (const auto& c : sweep_timing_columns()) header.push_back(c);
  std::string out;
  for (std::size_t i = 0; i < header.size(); ++i) out += (i ? "," : "") + csv_cell(header[i]);
  out += "\n";
  for (std::size_t r = 0; r < m.runs.size(); ++r) {
    const SweepManifestRun& run = m.runs[r];
    const RunOutcome& o = outcomes[r];
    std::vector<std::string> row = {std::to_string(run.index), run.id, std::to_string(run.repeat)};
    for (const auto& v : run.values) row.push_back(sweep_value_text(v));
    row.push_back(o.status);
    for (double v : o.metrics) row.push_back(number_cell(v));
    row.push_back(o.failure);
    row.push_back(o.wall_time >= 0 ? number_cell(o.wall_time) : "");
    row.push_back(o.real_time_factor >= 0 ? number_cell(o.real_time_factor) : "");
    row.push_back(o.has_status ? number_cell(o.process.wall_time) : "");
    row.push_back(o.has_status ? number_cell(o.process.cpu_time) : "");
    row.push_back(o.has_status ? o.process.host : "");
    for (std::size_t i = 0; i < row.size(); ++i) out += (i ? "," : "") + csv_cell(row[i]);
    out += "\n";
  }
  return out;
}

std::vector<SweepAxisSummary> summarise_sweep(const SweepManifest& m, const std::vector<RunOutcome>& outcomes) {
  const std::size_t nm = sweep_metrics().size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<SweepAxisSummary> axes;
  for (std::size_t k = 0; k < m.axes.size(); ++k) {
    SweepAxisSummary axis;
    axis.pointer = m.axes[k].pointer;
    // One row per distinct value, as JSON compares them (2 and 2.0 are one), in the axis's order:
    // a zipped axis may repeat a value, each time beside another value of the other axes.
    std::map<json, std::size_t> row_of;
    for (const auto& value : m.axes[k].values) {
      if (!row_of.emplace(json::parse(value), axis.values.size()).second) continue;
      SweepValueSummary s;
      s.value = value;
      s.mean.assign(nm, 0.0), s.min.assign(nm, nan), s.max.assign(nm, nan), s.count.assign(nm, 0);
      axis.values.push_back(std::move(s));
    }
    for (std::size_t r = 0; r < m.runs.size(); ++r) {
      const auto row = row_of.find(json::parse(m.runs[r].values[k]));
      if (row == row_of.end()) continue;  // a hand-edited manifest: a value its axis does not list
      SweepValueSummary& s = axis.values[row->second];
      const RunOutcome& o = outcomes[r];
      ++s.runs;
      if (o.status == "failed") ++s.failed;
      if (o.status == "missing") ++s.missing;
      if (o.status != "done") continue;
      ++s.done;
      if (o.metrics[kGoalReached] == 1.0) ++s.goal_reached;
      for (std::size_t i = 0; i < nm; ++i) {
        const double v = o.metrics[i];
        if (!std::isfinite(v)) continue;
        s.mean[i] += v;
        s.min[i] = s.count[i] ? std::min(s.min[i], v) : v;
        s.max[i] = s.count[i] ? std::max(s.max[i], v) : v;
        ++s.count[i];
      }
    }
    for (SweepValueSummary& s : axis.values)
      for (std::size_t i = 0; i < nm; ++i) s.mean[i] = s.count[i] ? s.mean[i] / static_cast<double>(s.count[i]) : nan;
    axes.push_back(std::move(axis));
  }
  return axes;
}

std::string sweep_results_json(const SweepManifest& m, const std::vector<RunOutcome>& outcomes) {
  const auto& metrics = sweep_metrics();
  ordered_json j;
  j["format"] = "vascsim-sweep-results/1";
  j["name"] = m.name;
  j["scene"] = m.scene;
  j["axes"] = ordered_json::array();
  for (const auto& a : m.axes) j["axes"].push_back(a.pointer);
  std::size_t done = 0, failed = 0, missing = 0;
  ordered_json runs = ordered_json::array();
  for (std::size_t r = 0; r < m.runs.size(); ++r) {
    const RunOutcome& o = outcomes[r];
    done += o.status == "done", failed += o.status == "failed", missing += o.status == "missing";
    ordered_json row;
    row["index"] = m.runs[r].index;
    row["id"] = m.runs[r].id;
    row["repeat"] = m.runs[r].repeat;
    row["overrides"] = ordered_json::object();
    for (std::size_t k = 0; k < m.axes.size(); ++k) row["overrides"][m.axes[k].pointer] = ordered_json::parse(m.runs[r].values[k]);
    row["status"] = o.status;
    row["failure"] = o.failure.empty() ? ordered_json(nullptr) : ordered_json(o.failure);
    for (std::size_t i = 0; i < metrics.size(); ++i) row[metrics[i].column] = metric_json(o.metrics[i], metrics[i]);
    row["timing"] = {{"wall_time_s", o.wall_time >= 0 ? ordered_json(o.wall_time) : ordered_json(nullptr)},
                     {"real_time_factor", o.real_time_factor >= 0 ? ordered_json(o.real_time_factor) : ordered_json(nullptr)},
                     {"process_time_s", o.has_status ? ordered_json(o.process.wall_time) : ordered_json(nullptr)},
                     {"cpu_time_s", o.has_status ? ordered_json(o.process.cpu_time) : ordered_json(nullptr)},
                     {"host", o.has_status ? ordered_json(o.process.host) : ordered_json(nullptr)}};
    runs.push_back(row);
  }
  j["counts"] = {{"runs", m.runs.size()}, {"done", done}, {"failed", failed}, {"missing", missing}};
  ordered_json summary = ordered_json::array();
  for (const auto& axis : summarise_sweep(m, outcomes)) {
    ordered_json a;
    a["pointer"] = axis.pointer;
    a["values"] = ordered_json::array();
    for (const auto& v : axis.values) {
      ordered_json s;
      s["value"] = ordered_json::parse(v.value);
      s["runs"] = v.runs, s["done"] = v.done, s["failed"] = v.failed, s["missing"] = v.missing;
      s["goal_reached"] = v.goal_reached;
      for (std::size_t i = 0; i < metrics.size(); ++i)
        s[metrics[i].column] = {{"mean", number_json(v.mean[i])}, {"min", metric_json(v.min[i], metrics[i])},
                                {"max", metric_json(v.max[i], metrics[i])}, {"count", v.count[i]}};
      a["values"].push_back(s);
    }
    summary.push_back(a);
  }
  j["per_axis"] = summary;
  j["runs"] = runs;
  return j.dump(2, ' ', false, decltype(j)::error_handler_t::replace) + "\n";  // file names, child stderr: maybe not UTF-8
}

}  // namespace vascsim
