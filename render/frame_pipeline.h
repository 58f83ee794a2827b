// A bounded producer/consumer pipeline for rendered frames: the render thread fills one of a
// few fixed buffers while worker threads encode earlier ones (video: one worker, in order;
// PNG: one per core, any order). Memory stays at `slots` frames whatever the video length.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace vascsim::render {

class FramePipeline {
 public:
  using Consumer = std::function<void(std::size_t index, const std::vector<std::uint8_t>& rgba)>;
  FramePipeline(std::size_t frame_bytes, int workers, int slots, Consumer consume);
  // Joins the workers (discarding queued frames if finish() was not called).
  ~FramePipeline();
  FramePipeline(const FramePipeline&) = delete;
  FramePipeline& operator=(const FramePipeline&) = delete;

  // A free buffer to render into; blocks while all are in flight. Rethrows a worker's error.
  std::vector<std::uint8_t>& acquire();
  // Queues the buffer last acquired as frame `index`.
  void submit(std::size_t index);
  // Waits for every queued frame; rethrows the first worker error.
  void finish();

 private:
  void work();
  void stop();

  Consumer consume_;
  std::vector<std::vector<std::uint8_t>> buffers_;
  std::vector<std::size_t> free_;                      // buffer ids ready to render into
  std::deque<std::pair<std::size_t, std::size_t>> queue_;  // (frame index, buffer id)
  std::size_t current_ = 0;
  int busy_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::thread> threads_;
};

}  // namespace vascsim::render
