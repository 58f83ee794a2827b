// MP4 exports started from the replay page: each renders a time range of one run with the
// page's view, on its own thread (with its own GL context), into the run's directory as
// export-NNN.mp4: a new number each time, never an existing file, written under a temporary
// name and renamed when complete (render_run's rules). Progress is polled by the page; a
// shutdown cancels running exports and leaves no partial file.
#pragma once

#include <atomic>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "render/render_run.h"
#include "sim/scene/input_error.h"

namespace vascsim::replay {

// Two exports are already running: the request is fine, the server is busy (HTTP 429).
class ExportsBusy : public InputError {
 public:
  using InputError::InputError;
};

class ExportJobs {
 public:
  ExportJobs() = default;
  ~ExportJobs();  // cancels and joins running exports
  ExportJobs(const ExportJobs&) = delete;
  ExportJobs& operator=(const ExportJobs&) = delete;

  // Starts rendering `run_path` with `options` (its mp4_path is chosen here) into `out_dir`.
  // Returns the job id. Throws InputError if two exports are already running.
  int start(const std::string& run_path, const std::string& out_dir, render::RenderOptions options);
  // {"state": "running"|"done"|"failed", "frames_done", "frames_total", "file", "error"}, or
  // nullopt for an unknown id.
  std::optional<nlohmann::json> status(int id) const;
  // The finished file of job `id`, or nullopt if it is not done.
  std::optional<std::string> file(int id) const;

 private:
  struct Job {
    std::atomic<std::size_t> done{0}, total{0};
    std::atomic<bool> finished{false};
    std::string path, error;  // set before `finished`
    std::thread thread;
  };
  std::string reserve_name(const std::string& out_dir);

  mutable std::mutex mutex_;
  std::map<int, std::unique_ptr<Job>> jobs_;
  std::set<std::string> reserved_;
  std::atomic<bool> cancel_{false};
  int next_id_ = 1;
};

}  // namespace vascsim::replay
