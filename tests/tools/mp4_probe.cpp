// mp4_probe FILE: prints what libavformat reads from a video as one JSON line (codec, frames,
// width, height, duration in s), for tests outside C++ (the replay page's browser test checks
// the MP4 it exported with it).
#include <cstdio>
#include <exception>

#include "render/video_encoder.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: mp4_probe FILE\n");
    return 2;
  }
  try {
    const vascsim::render::VideoInfo v = vascsim::render::probe_video(argv[1]);
    std::printf("{\"codec\": \"%s\", \"pixel_format\": \"%s\", \"frames\": %lld, \"width\": %d, \"height\": %d, "
                "\"duration\": %.6f}\n",
                v.codec.c_str(), v.pixel_format.c_str(), static_cast<long long>(v.frames), v.width, v.height,
                v.duration);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mp4_probe: %s\n", e.what());
    return 1;
  }
}
