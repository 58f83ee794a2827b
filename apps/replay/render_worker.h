// The replay server's one rendering thread. An OSMesa context is current on one thread only, so
// every frame is drawn here, whichever HTTP thread asked for it; canvases of the last few frame
// sizes are kept, since creating one (a GL context and framebuffer) costs more than a frame.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <thread>

#include "render/canvas.h"

namespace vascsim::replay {

class RenderWorker {
 public:
  RenderWorker();
  ~RenderWorker();
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  // Runs `job` with a width x height canvas on the render thread and waits for it; rethrows
  // what the job threw.
  void run(int width, int height, const std::function<void(render::Canvas&)>& job);

 private:
  struct Job;
  void loop();
  render::Canvas& canvas(int width, int height);

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job*> queue_;
  bool stopping_ = false;
  std::list<std::unique_ptr<render::Canvas>> canvases_;  // most recently used first
  std::thread thread_;
};

}  // namespace vascsim::replay
