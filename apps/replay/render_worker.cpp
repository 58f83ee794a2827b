#include "apps/replay/render_worker.h"

#include <exception>

namespace vascsim::replay {

namespace {
constexpr std::size_t kCanvasesKept = 3;
}

struct RenderWorker::Job {
  int width, height;
  const std::function<void(render::Canvas&)>* work;
  bool done = false;
  std::exception_ptr error;
};

RenderWorker::RenderWorker() : thread_([this] { loop(); }) {}

RenderWorker::~RenderWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void RenderWorker::run(int width, int height, const std::function<void(render::Canvas&)>& work) {
  Job job{width, height, &work, false, nullptr};
  std::unique_lock<std::mutex> lock(mutex_);
  if (stopping_) throw std::runtime_error("the renderer is shutting down");
  queue_.push_back(&job);
  changed_.notify_all();
  changed_.wait(lock, [&] { return job.done; });
  if (job.error) std::rethrow_exception(job.error);
}

render::Canvas& RenderWorker::canvas(int width, int height) {
  for (auto it = canvases_.begin(); it != canvases_.end(); ++it)
    if ((*it)->width() == width && (*it)->height() == height) {
      canvases_.splice(canvases_.begin(), canvases_, it);
      return *canvases_.front();
    }
  if (canvases_.size() >= kCanvasesKept) canvases_.pop_back();
  canvases_.push_front(std::make_unique<render::Canvas>(width, height));
  return *canvases_.front();
}

void RenderWorker::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) break;
    Job* job = queue_.front();
    queue_.pop_front();
    lock.unlock();
    try {
      (*job->work)(canvas(job->width, job->height));
    } catch (...) {
      job->error = std::current_exception();
    }
    lock.lock();
    job->done = true;
    changed_.notify_all();
  }
  canvases_.clear();  // their GL contexts belong to this thread
}

}  // namespace vascsim::replay
