#include <stdexcept>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/scene/input_error.h"
#include "tests/fuzz/fuzz_harnesses.h"

namespace vascsim::fuzz {

namespace {

// Where two texts first differ: that line of each, numbered.
std::string first_difference(const std::string& a, const std::string& b) {
  std::size_t at = 0, line = 1;
  for (; at < a.size() && at < b.size() && a[at] == b[at]; ++at) line += a[at] == '\n';
  const auto line_at = [at](const std::string& s) {
    const std::size_t begin = s.rfind('\n', at == 0 ? 0 : at - 1), end = s.find('\n', at);
    return s.substr(begin == std::string::npos ? 0 : begin + 1, end == std::string::npos ? std::string::npos : end - begin - 1);
  };
  return "line " + std::to_string(line) + ": '" + line_at(a) + "' became '" + line_at(b) + "'";
}

}  // namespace

void fail(const std::string& what) { throw std::logic_error("fuzz: " + what); }

int scene_reader(const std::uint8_t* data, std::size_t size) {
  // Named as a file in scenes/, so a mutated vessel-mask scene finds the shipped mask image
  // through its relative path, as a real scene does.
  static const std::string label = std::string(VASCSIM_SOURCE_DIR) + "/scenes/fuzz_input.json";
  const std::string text(reinterpret_cast<const char*>(data), size);
  Scene scene;
  try {
    scene = read_scene_text(text, label);
  } catch (const InputError&) {
    return 0;  // the documented refusal
  }
  // Every log and summary stores the canonical text, and replays and reruns read it back: a
  // scene the reader accepts must survive that round trip unchanged.
  const std::string canonical = scene_to_json(scene);
  try {
    const std::string again = scene_to_json(read_scene_text(canonical, label));
    if (again != canonical)
      fail("the canonical JSON of an accepted scene reads back differently, " + first_difference(canonical, again));
  } catch (const InputError& e) {
    fail(std::string("the canonical JSON of an accepted scene is refused: ") + e.what() + "\n" + canonical);
  }
  try {
    compile(scene);
  } catch (const InputError&) {
    // compile's refusal of what cannot run (node indices out of range, a maze the rod cannot fit)
  }
  return 0;
}

}  // namespace vascsim::fuzz
