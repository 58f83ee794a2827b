#include "apps/replay/export_jobs.h"

#include <cstdio>
#include <filesystem>

#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"

namespace vascsim::replay {

namespace fs = std::filesystem;

ExportJobs::~ExportJobs() {
  cancel_ = true;
  for (auto& [id, job] : jobs_)
    if (job->thread.joinable()) job->thread.join();
}

std::string ExportJobs::reserve_name(const std::string& out_dir) {
  // Choosing a free number and claiming it is one step for every server on this run: the claim
  // is this process's temporary name for the file, made now (the encoder writes into it later),
  // which another server sees as "in use" until this one ends.
  const DirectoryLock lock(out_dir);
  for (int n = 1; n < 100000; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "export-%03d.mp4", n);
    const std::string path = (fs::path(out_dir) / name).string();
    std::error_code ec;
    // Not a name another server on this run is still writing (its temporary name is in use).
    if (reserved_.count(path) || fs::exists(path, ec) || temporary_in_use(path)) continue;
    std::FILE* claim = std::fopen(temporary_sibling(path).c_str(), "wb");
    if (!claim) throw InputError(out_dir + ": cannot create an export there (not writable?)");
    std::fclose(claim);
    reserved_.insert(path);
    return path;
  }
  throw InputError(out_dir + ": no free export-NNN.mp4 name");
}

int ExportJobs::start(const std::string& run_path, const std::string& out_dir, render::RenderOptions options) {
  std::lock_guard<std::mutex> lock(mutex_);
  int running = 0;
  for (const auto& [id, job] : jobs_) running += !job->finished;
  if (running >= 2) throw ExportsBusy("two exports are already running; wait for one to finish");
  options.mp4_path = reserve_name(out_dir);
  options.png_dir.clear();
  options.plots_dir.clear();
  options.force = false;
  const int id = next_id_++;
  auto job = std::make_unique<Job>();
  Job* j = job.get();
  options.progress = [this, j](std::size_t done, std::size_t total) {
    j->done = done;
    j->total = total;
    return !cancel_;
  };
  j->thread = std::thread([j, run_path, options] {
    try {
      const render::RenderReport report = render::render_run(run_path, options);
      j->path = report.video_path;
    } catch (const std::exception& e) {
      j->error = e.what();
      std::remove(temporary_sibling(options.mp4_path).c_str());  // the claim, if the encoder never took it
    }
    j->finished = true;
  });
  jobs_.emplace(id, std::move(job));
  return id;
}

std::optional<nlohmann::json> ExportJobs::status(int id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  const Job& j = *it->second;
  const bool finished = j.finished;
  nlohmann::json s = {{"id", id}, {"frames_done", j.done.load()}, {"frames_total", j.total.load()}};
  s["state"] = !finished ? "running" : j.error.empty() ? "done" : "failed";
  s["file"] = finished && j.error.empty() ? nlohmann::json(fs::path(j.path).filename().string()) : nlohmann::json(nullptr);
  s["error"] = finished && !j.error.empty() ? nlohmann::json(j.error) : nlohmann::json(nullptr);
  return s;
}

std::optional<std::string> ExportJobs::file(int id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || !it->second->finished || !it->second->error.empty()) return std::nullopt;
  return it->second->path;
}

}  // namespace vascsim::replay
