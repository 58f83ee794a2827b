// The text of a libav error code, for the messages of the video encoder and decoder.
#pragma once

#include <string>

extern "C" {
#include <libavutil/error.h>
}

namespace vascsim::render {

inline std::string av_error(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, buf, sizeof buf);
  return buf;
}

}  // namespace vascsim::render
