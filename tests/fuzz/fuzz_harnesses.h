// The fuzz harnesses: one entry point per reader that takes bytes from outside (a scene file, a
// frame log, a PNG, a replay request), in the shape libFuzzer calls (LLVMFuzzerTestOneInput).
// Each one feeds its bytes to the product code as a user's file or a browser's request would
// reach it and returns 0. The only outcome allowed besides success is the reader's documented
// refusal (InputError; ParamError for a request); anything else escaping (another exception, a
// failed self-check, a sanitizer report) is a crash. The same functions are built twice: into
// libFuzzer executables with clang (-DVASCSIM_FUZZ=ON, scripts/fuzz) and into the GoogleTest
// suite, which runs them over every committed corpus and regression input under ASan and UBSan
// (tests/fuzz/fuzz_corpus_test.cpp), so a crash once found stays fixed in ordinary CI.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace vascsim::fuzz {

using Harness = int (*)(const std::uint8_t* data, std::size_t size);

// Scene JSON text -> read_scene_text -> a validated Scene; its canonical JSON must read back to
// the same text (logs store it), and the scene is compiled as `vascsim run` would.
int scene_reader(const std::uint8_t* data, std::size_t size);
// PNG file bytes -> decode_png, as `vascsim diff` reads them (RGB, any size) and as a vessel
// mask is read (grey, at most kMaxMaskSide px a side).
int png_reader(const std::uint8_t* data, std::size_t size);
// Frame log file bytes -> FrameSource (header, channels, metadata, times) -> one rendered view
// with every layer on, at the log's middle time, on a small canvas. Needs the renderer.
int frame_log(const std::uint8_t* data, std::size_t size);
// A request's query string ("width=320&t=1.5&...", as after the '?'), then optionally a newline
// and a request body -> httplib's query parser -> RequestParams and parse_view with every
// parameter the replay server's handlers read; the body as a bookmark. Needs the renderer.
int replay_request(const std::uint8_t* data, std::size_t size);

// A harness found something its own checks call wrong: throws std::logic_error("fuzz: " + what),
// which no harness catches (libFuzzer reports the uncaught exception as a crash and keeps the
// input; the corpus test reports it as a failure naming the input).
[[noreturn]] void fail(const std::string& what);

}  // namespace vascsim::fuzz
