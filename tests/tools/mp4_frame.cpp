// mp4_frame FILE INDEX OUT.png: writes frame INDEX (0-based, presentation order) of a video as
// PNG, to look at what the encoder wrote (there is no ffmpeg command line on the machine), e.g.
//   build/tests/mp4_frame out/maze_default/video.mp4 100 /tmp/f100.png
// OUT.png is never overwritten: an existing file is refused with exit code 2, as the vascsim
// command line refuses outputs without --force. Exit codes: 0 written; 2 bad usage or input
// (existing OUT, missing file, no video stream, no such frame); 1 decoding failed.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>

#include "render/video_decoder.h"
#include "sim/scene/input_error.h"

namespace {

// A whole non-negative decimal number, or -1: "12x" or "-3" must not read as a frame index.
long long parse_index(const char* text) {
  if (*text < '0' || *text > '9') return -1;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text, &end, 10);
  return (errno != 0 || *end != '\0') ? -1 : v;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: mp4_frame FILE.mp4 INDEX OUT.png\n");
    return 2;
  }
  const long long index = parse_index(argv[2]);
  if (index < 0) {
    std::fprintf(stderr, "mp4_frame: INDEX: expected a whole number >= 0, got '%s'\n", argv[2]);
    return 2;
  }
  try {
    // Before decoding, so a refused run costs nothing. symlink_status: a dangling link is a
    // name the user made too.
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::symlink_status(argv[3], ec))) {
      std::fprintf(stderr, "mp4_frame: %s: already exists; mp4_frame never overwrites a file (choose another name or remove it)\n",
                   argv[3]);
      return 2;
    }
    const vascsim::render::Image image = vascsim::render::decode_video_frame(argv[1], index);
    vascsim::render::write_image_png(argv[3], image);
    std::printf("%s: frame %lld, %dx%d\n", argv[3], index, image.width, image.height);
    return 0;
  } catch (const vascsim::InputError& e) {
    std::fprintf(stderr, "mp4_frame: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mp4_frame: %s\n", e.what());
    return 1;
  }
}
