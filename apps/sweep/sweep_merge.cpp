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

std::string cell(const std::string& text, std::size_t width) {
  std::string t = text.size() > width - 1 ? text.substr(0, width - 4) + "..." : text;
  t.resize(width, ' ');
  return t;
}

std::string trim_right(std::string s) {
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
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

bool sweep_navigates(const SweepDirectory& sweep, const std::vector<RunOutcome>& outcomes) {
  bool any_done = false;
  for (const auto& o : outcomes) {
    if (std::isfinite(o.metrics[kTipErrorRms])) return true;
    any_done = any_done || o.status == "done";
  }
  // Before any run has figures, the scene says which columns the table will fill (a merge
  // before the runs showed the free-space ones for a maze sweep).
  if (any_done || sweep.manifest.runs.empty()) return false;
  try {
    return read_scene_file((fs::path(sweep.dir) / run_scene_path(sweep.manifest.runs.front().id)).string()).has_environment;
  } catch (const InputError&) {
    return false;
  }
}

std::vector<std::size_t> headline_metrics(bool navigation) {
  if (navigation) return {kTipErrorRms, kTipErrorMax, kGoalTime, kMaxPenetration};
  return {kSteps, kNewtonIterations, kRejectedSteps};
}

std::string summary_table(const SweepManifest& m, const std::vector<RunOutcome>& outcomes, bool navigation) {
  const auto& all = sweep_metrics();
  const std::vector<std::size_t> metrics = headline_metrics(navigation);
  std::size_t done = 0, failed = 0, missing = 0;
  for (const auto& o : outcomes) done += o.status == "done", failed += o.status == "failed", missing += o.status == "missing";
  std::string out = "sweep " + m.name + " (" + m.scene + "): " + std::to_string(m.runs.size()) + " runs: " +
                    std::to_string(done) + " done, " + std::to_string(failed) + " failed, " + std::to_string(missing) +
                    " missing\n";
  for (const auto& axis : summarise_sweep(m, outcomes)) {
    std::string header = "\n" + cell(axis.pointer, 18) + cell("runs", 6) + cell("failed", 8) + cell("missing", 9) +
                         (navigation ? cell("goal", 7) : "");
    for (std::size_t i : metrics)
      header += cell(std::string(all[i].label) + (*all[i].unit ? std::string(" (") + all[i].unit + ")" : ""), 26);
    std::string units = std::string(18 + 6 + 8 + 9, ' ') + (navigation ? cell("", 7) : "");
    for (std::size_t n = 0; n < metrics.size(); ++n) units += cell("mean [min, max]", 26);
    out += trim_right(header) + "\n" + trim_right(units) + "\n";
    for (const auto& v : axis.values) {
      std::string row = cell(sweep_value_text(v.value), 18) + cell(std::to_string(v.runs), 6) +
                        cell(std::to_string(v.failed), 8) + cell(std::to_string(v.missing), 9);
      if (navigation) row += cell(std::to_string(v.goal_reached) + "/" + std::to_string(v.runs), 7);
      for (std::size_t i : metrics)
        row += cell(figure_text(v.mean[i] * all[i].scale) + " [" + figure_text(v.min[i] * all[i].scale) + ", " +
                        figure_text(v.max[i] * all[i].scale) + "]",
                    26);
      out += trim_right(row) + "\n";
    }
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
  const bool navigation = sweep_navigates(sweep, outcomes);
#ifdef VASCSIM_HAVE_RENDER
  if (drawing) {
    const std::vector<std::size_t> metrics = headline_metrics(navigation);
    for (std::size_t k = 0; k < m.axes.size(); ++k) {
      render::write_sweep_figure(figure_of(m, outcomes, k, metrics), figures[k], 1600, 1100);
      report.written.push_back(figures[k]);
    }
  }
#else
  if (plots) report.note = "no plots: this build has no renderer (configure with -DVASCSIM_RENDER=ON)";
#endif
  report.table = summary_table(m, outcomes, navigation);
  return report;
}

}  // namespace vascsim::sweep
