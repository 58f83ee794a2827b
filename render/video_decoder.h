// Reading a frame back out of a video (the MP4s vascsim renders, or any file libavformat
// opens), so developers and tests can look at what the encoder actually wrote: the machine has
// no ffmpeg command line, and the renderer's own PNGs show the frames before H.264 loss.
// Used by tests/tools/mp4_frame and the render tests; the renderer itself never decodes.
#pragma once

#include <string>

#include "render/image_diff.h"

namespace vascsim::render {

// Frame `frame_index` (0-based, presentation order) of the best video stream in `path`,
// converted to 8-bit RGB (Image is RGB, no alpha) with the colour matrix and range the stream
// is tagged with (BT.709 limited range for vascsim's videos). Decodes from the start, so the cost
// grows with the index (a 720p synthetic render, sanitizer build: frame 0 in 19 ms, frame 99
// in 67 ms), which is fine for a look or a test.
// Throws InputError (a std::runtime_error) naming the file if it cannot be opened (missing,
// not a video), has no video stream, or has no frame `frame_index` (the message gives the
// number of frames); std::runtime_error naming the file if decoding fails.
Image decode_video_frame(const std::string& path, long long frame_index);

}  // namespace vascsim::render
