#include "apps/sweep/sweep_merge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "sim/io/output_file.h"
#include "sim/io/scene_reader.h"
#include "sim/scene/input_error.h"
#ifdef VASCSIM_HAVE_RENDER
#include "render/sweep_plot.h"
#endif

namespace vascsim::sweep {

namespace {

namespace fs = std::filesystem;

// Lines of cells, each column as wide as its widest cell and two spaces apart: nothing is cut
// (cells of a fixed width cut long pointers, object values and wide figures to "...").
std::string aligned_lines(const std::vector<std::vector<std::string>>& lines) {
  std::vector<std::size_t> width;
  for (const auto& line : lines) {
    width.resize(std::max(width.size(), line.size()), 0);
    for (std::size_t c = 0; c < line.size(); ++c) width[c] = std::max(width[c], line[c].size());
  }
  std::string out;
  for (const auto& line : lines) {
    std::string text;
    for (std::size_t c = 0; c < line.size(); ++c) {
      text += line[c];
      if (c + 1 < line.size()) text += std::string(width[c] - line[c].size() + 2, ' ');
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out += text + "\n";
  }
  return out;
}

std::string figure_text(double v) {
  if (!std::isfinite(v)) return "-";
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", v);
  return s;
}

// "control_kp" for "/control/kp": a file name for the axis's figure.
std::string slug(const std::string& pointer) {
  std::string out;
  for (char c : pointer) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-';
    if (keep) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out.empty() ? "axis" : out;
}

std::vector<std::string> figure_paths(const SweepManifest& m, const fs::path& dir) {
  std::vector<std::string> paths;
  std::set<std::string> used;
  for (std::size_t k = 0; k < m.axes.size(); ++k) {
    std::string name = slug(m.axes[k].pointer);
    if (!used.insert(name).second) name += "_" + std::to_string(k);
    used.insert(name);
    paths.push_back((dir / (name + ".png")).string());
  }
  return paths;
}

#ifdef VASCSIM_HAVE_RENDER
render::SweepFigure figure_of(const SweepManifest& m, const std::vector<RunOutcome>& outcomes, std::size_t k,
                              const std::vector<std::size_t>& metrics) {
  const SweepAxis& axis = m.axes[k];
  render::SweepFigure f;
  f.xlabel = axis.pointer;
  std::vector<double> numbers;
  // Numbers spread evenly enough are drawn at their values; names, and values spanning
  // decades (a dt from 1e-5 to 1e-2), at even positions with their own labels.
  bool numeric = sweep_axis_numbers(axis, numbers);
  if (numeric && numbers.size() > 2) {
    const auto [lo, hi] = std::minmax_element(numbers.begin(), numbers.end());
    numeric = !(*lo > 0 && *hi / *lo >= 100);
  }
  for (std::size_t j = 0; j < axis.values.size(); ++j) {
    f.x.push_back(numeric ? numbers[j] : static_cast<double>(j));
    if (!numeric) f.x_labels.push_back(sweep_value_text(axis.values[j]));
  }
  const auto& all = sweep_metrics();
  for (std::size_t i : metrics) {
    render::SweepPanel p;
    p.title = all[i].label;
    p.ylabel = std::string(all[i].label) + (*all[i].unit ? std::string(" (") + all[i].unit + ")" : "");
    p.values.resize(axis.values.size());
    p.failed.assign(axis.values.size(), 0);
    p.unknown.assign(axis.values.size(), 0);
    p.unknown_label = i == kGoalTime ? "not reached" : "without a value";
    for (std::size_t r = 0; r < m.runs.size(); ++r) {
      std::size_t j = 0;
      while (j < axis.values.size() && axis.values[j] != m.runs[r].values[k]) ++j;
      if (j == axis.values.size()) continue;
      if (outcomes[r].status != "done") ++p.failed[j];
      else if (std::isfinite(outcomes[r].metrics[i])) p.values[j].push_back(outcomes[r].metrics[i] * all[i].scale);
      else ++p.unknown[j];
    }
    f.panels.push_back(std::move(p));
  }
  return f;
}
#endif

}  // namespace

SweepKind sweep_kind(const SweepDirectory& sweep, const std::vector<RunOutcome>& outcomes) {
  SweepKind kind;
  bool any_done = false;
  for (const auto& o : outcomes) {
    any_done = any_done || o.status == "done";
    if (!std::isfinite(o.metrics[kGoalReached])) continue;  // no navigation figures
    kind.navigation = true;
    // A summary that does not say (written before control_mode was) is of a steered run.
    kind.steered = kind.steered || o.control_mode != "none";
    kind.fed = kind.fed || std::isfinite(o.metrics[kFeedForceMax]);
  }
  // Before any run has figures, the scene says which columns the table will fill (a merge
  // before the runs showed the free-space ones for a maze sweep).
  if (kind.navigation || any_done || sweep.manifest.runs.empty()) return kind;
  try {
    const Scene scene = read_scene_file((fs::path(sweep.dir) / run_scene_path(sweep.manifest.runs.front().id)).string());
    kind.navigation = scene.has_environment;
    kind.steered = kind.navigation && scene.control.mode != ActuationMode::kNone;
    kind.fed = kind.navigation && scene.control.advance.enabled();
  } catch (const InputError&) {
  }
  return kind;
}

std::vector<std::size_t> headline_metrics(const SweepKind& kind) {
  if (!kind.navigation) return {kSteps, kNewtonIterations, kRejectedSteps};
  std::vector<std::size_t> metrics;
  if (kind.steered) metrics.insert(metrics.end(), {kTipErrorRms, kTipErrorMax});
  if (kind.fed) metrics.push_back(kFeedForceMax);
  metrics.insert(metrics.end(), {kGoalTime, kMaxPenetration});
  return metrics;
}

std::string summary_table(const SweepManifest& m, const std::vector<RunOutcome>& outcomes, const SweepKind& kind) {
  // An axis value longer than this (a whole vessel network, say) is named "value K" in its row
  // and given in full below the table, so the columns stay readable.
  constexpr std::size_t kLongestValueCell = 32;
  const auto& all = sweep_metrics();
  const std::vector<std::size_t> metrics = headline_metrics(kind);
  std::size_t done = 0, failed = 0, missing = 0;
  for (const auto& o : outcomes) done += o.status == "done", failed += o.status == "failed", missing += o.status == "missing";
  std::string out = "sweep " + m.name + " (" + m.scene + "): " + std::to_string(m.runs.size()) + " runs: " +
                    std::to_string(done) + " done, " + std::to_string(failed) + " failed, " + std::to_string(missing) +
                    " missing\n";
  for (const auto& axis : summarise_sweep(m, outcomes)) {
    std::vector<std::string> header = {axis.pointer, "runs", "failed", "missing"}, units = {"", "", "", ""};
    if (kind.navigation) header.push_back("goal"), units.push_back("");
    for (std::size_t i : metrics) {
      header.push_back(std::string(all[i].label) + (*all[i].unit ? std::string(" (") + all[i].unit + ")" : ""));
      units.push_back("mean [min, max]");
    }
    std::vector<std::vector<std::string>> lines = {header, units};
    std::string legend;
    for (std::size_t k = 0; k < axis.values.size(); ++k) {
      const auto& v = axis.values[k];
      std::string value = sweep_value_text(v.value);
      if (value.size() > kLongestValueCell) {
        legend += "  value " + std::to_string(k + 1) + ": " + value + "\n";
        value = "value " + std::to_string(k + 1);
      }
      std::vector<std::string> row = {value, std::to_string(v.runs), std::to_string(v.failed), std::to_string(v.missing)};
      // Goals of the completed runs, as the figures are ("0/3" for three missing runs read as
      // three runs that missed the goal).
      if (kind.navigation) row.push_back(v.done ? std::to_string(v.goal_reached) + "/" + std::to_string(v.done) : "-");
      for (std::size_t i : metrics)
        row.push_back(figure_text(v.mean[i] * all[i].scale) + " [" + figure_text(v.min[i] * all[i].scale) + ", " +
                      figure_text(v.max[i] * all[i].scale) + "]");
      lines.push_back(std::move(row));
    }
    out += "\n" + aligned_lines(lines) + legend;
  }
  return out;
}

std::vector<std::string> earlier_merge_outputs(const SweepDirectory& sweep) {
  const fs::path dir(sweep.dir);
  std::vector<std::string> outputs = {(dir / "results.csv").string(), (dir / "results.json").string()};
  for (const auto& f : figure_paths(sweep.manifest, dir / "plots")) outputs.push_back(f);
  std::vector<std::string> existing;
  for (const auto& f : outputs) {
    std::error_code ec;
    if (fs::symlink_status(f, ec).type() != fs::file_type::not_found) existing.push_back(f);
  }
  return existing;
}

MergeReport merge_sweep(const SweepDirectory& sweep, bool force, bool plots) {
  const SweepManifest& m = sweep.manifest;
  const fs::path dir(sweep.dir);
  const std::string csv = (dir / "results.csv").string(), json = (dir / "results.json").string();
  const fs::path plot_dir = dir / "plots";
  const std::vector<std::string> figures = figure_paths(m, plot_dir);
#ifdef VASCSIM_HAVE_RENDER
  const bool drawing = plots;
#else
  const bool drawing = false;
#endif
  // Every refusal before anything is written, so a refused merge changes nothing. Figures of an
  // earlier merge are replaced, or removed when this one draws none: left beside the new tables
  // they would show results that are no longer there.
  check_replaceable_output(csv, force, {});
  check_replaceable_output(json, force, {});
  if (drawing) {
    std::error_code ec;
    fs::create_directories(plot_dir, ec);
    if (ec) throw InputError(plot_dir.string() + ": cannot create directory (" + ec.message() + ")");
  }
  std::vector<std::string> stale;
  for (const auto& f : figures) {
    std::error_code ec;
    if (!drawing && fs::symlink_status(f, ec).type() == fs::file_type::not_found) continue;
    check_replaceable_output(f, force, {});
    if (!drawing) stale.push_back(f);
  }
  for (const auto& f : stale) {
    std::error_code ec;
    if (fs::remove(f, ec); ec) throw InputError(f + ": cannot remove the figure of an earlier merge (" + ec.message() + ")");
  }
  std::vector<RunOutcome> outcomes;
  outcomes.reserve(m.runs.size());
  MergeReport report;
  for (std::size_t i = 0; i < m.runs.size(); ++i) {
    outcomes.push_back(read_run_outcome(run_directory(sweep, i)));
    const std::string& s = outcomes.back().status;
    report.done += s == "done", report.failed += s == "failed", report.missing += s == "missing";
  }
  write_file_atomically(csv, sweep_results_csv(m, outcomes));
  write_file_atomically(json, sweep_results_json(m, outcomes));
  report.written = {csv, json};
  const SweepKind kind = sweep_kind(sweep, outcomes);
#ifdef VASCSIM_HAVE_RENDER
  if (drawing) {
    const std::vector<std::size_t> metrics = headline_metrics(kind);
    for (std::size_t k = 0; k < m.axes.size(); ++k) {
      render::write_sweep_figure(figure_of(m, outcomes, k, metrics), figures[k], 1600, 1100);
      report.written.push_back(figures[k]);
    }
  }
#else
  if (plots) report.note = "no plots: this build has no renderer (configure with -DVASCSIM_RENDER=ON)";
#endif
  report.table = summary_table(m, outcomes, kind);
  return report;
}

}  // namespace vascsim::sweep
