// Review videos through libavcodec/libavformat/libswscale: H.264 (libx264) in MP4, yuv420p,
// every packet one frame long so the container's duration is frames/fps, the index (moov)
// at the front so browsers stream it, and bit-exact muxing with a fixed encoder thread count
// so the same frames give the same bytes. Without libx264 it falls back to VP9 in WebM (never
// MPEG-4 part 2, which Chromium refuses) and says so. The file appears under its final name
// only when finish() succeeds.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace vascsim::render {

struct VideoSettings {
  int width = 1280, height = 720;  // px, both even (yuv420p)
  int fps = 30;                    // frames per second of video
  int crf = 20;                    // x264 constant rate factor: lower is better and larger
};

class VideoEncoder {
 public:
  // Opens `path` + ".partial" for writing. If H.264 is unavailable, the output becomes
  // `path` with its extension replaced by .webm (see path()). Throws InputError if the file
  // cannot be created, std::runtime_error if no encoder works.
  VideoEncoder(const std::string& path, const VideoSettings& settings);
  // Removes the partial file unless finish() succeeded.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  const std::string& path() const;   // the final file name
  const std::string& codec() const;  // "h264" or "vp9"
  const std::string& note() const;   // non-empty when the encoder fell back
  // One frame: width*height*4 bytes of top-down RGBA.
  void add_frame(const std::uint8_t* rgba);
  // Drains the encoder, writes the index and renames the file to path().
  void finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// What a video file holds, read back with libavformat (tests and the render report use it).
struct VideoInfo {
  std::string container;     // e.g. "mov,mp4,m4a,3gp,3g2,mj2"
  std::string codec;         // e.g. "h264"
  std::string pixel_format;  // e.g. "yuv420p"
  int width = 0, height = 0;
  long frames = 0;           // video packets counted
  double duration = 0;       // s, the video stream's duration
  double fps = 0;            // average frame rate
};
// Throws InputError if the file cannot be opened or has no video stream.
VideoInfo probe_video(const std::string& path);

}  // namespace vascsim::render
