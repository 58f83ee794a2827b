#include "render/frame_pipeline.h"

namespace vascsim::render {

FramePipeline::FramePipeline(std::size_t frame_bytes, int workers, int slots, Consumer consume)
    : consume_(std::move(consume)), buffers_(static_cast<std::size_t>(slots), std::vector<std::uint8_t>(frame_bytes)) {
  for (std::size_t i = 0; i < buffers_.size(); ++i) free_.push_back(i);
  for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { work(); });
}

FramePipeline::~FramePipeline() { stop(); }

void FramePipeline::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  changed_.notify_all();
  for (auto& t : threads_)
    if (t.joinable()) t.join();
}

std::vector<std::uint8_t>& FramePipeline::acquire() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return !free_.empty() || error_; });
  if (error_) std::rethrow_exception(error_);
  current_ = free_.back();
  free_.pop_back();
  return buffers_[current_];
}

void FramePipeline::submit(std::size_t index) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.emplace_back(index, current_);
  }
  changed_.notify_all();
}

void FramePipeline::finish() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return (queue_.empty() && busy_ == 0) || error_; });
  }
  stop();
  if (error_) std::rethrow_exception(error_);
}

void FramePipeline::work() {
  for (;;) {
    std::pair<std::size_t, std::size_t> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;
      job = queue_.front();
      queue_.pop_front();
      ++busy_;
    }
    try {
      consume_(job.first, buffers_[job.second]);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
      queue_.clear();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      --busy_;
      free_.push_back(job.second);
    }
    changed_.notify_all();
  }
}

}  // namespace vascsim::render
