// Inputs the JSON library would take silently or fail on badly are errors naming the file and
// the JSON path: a key given twice (it kept the last), a NUL byte (it stopped reading there),
// node indices beyond the integer range (2^64 - 1 pinned the tip, -2^63 node 0), nesting 10^5
// deep (the error message recursed until the stack overflowed), numbers beyond the double range
// (an "internal error", exit 3). The same for a frame log's metadata.
#include <gtest/gtest.h>

#include <string>

#include "sim/io/json_fields.h"
#include "sim/io/log_metadata.h"
#include "sim/io/scene_reader.h"
#include "sim/scene/input_error.h"
#include "tests/cli_test_support.h"

namespace vascsim {
namespace {

std::string error_of(const std::string& text) {
  try {
    read_scene_text(text, "scene.json");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text.substr(0, 80);
  return "";
}

// Well-formed UTF-8 (no check of overlong forms: the question is only whether a cut split a
// character).
bool valid_utf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const std::size_t length = lead < 0x80 ? 1 : (lead >> 5) == 6 ? 2 : (lead >> 4) == 14 ? 3 : (lead >> 3) == 30 ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (std::size_t k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return false;
    i += length;
  }
  return true;
}

void expect_error(const std::string& text, const std::string& needle) {
  const std::string message = error_of(text);
  EXPECT_NE(message.find("scene.json"), std::string::npos) << message;
  EXPECT_NE(message.find(needle), std::string::npos) << "expected '" << needle << "' in: " << message;
  EXPECT_LT(message.size(), 600u) << "the message must not quote a huge input";
}

TEST(SceneStrictness, DuplicateKeysNulBytesAndOutOfRangeIntegersAreErrors) {
  expect_error(R"({"maze": null, "rod": {"nodes": 3, "nodes": 41}})", "/rod/nodes: the key appears twice");
  expect_error(R"({"maze": null, "name": "a", "name": "b"})", "/name: the key appears twice");
  expect_error(R"({"maze": null, "boundary": {"prescribed": [{"node": 1, "node": 2}]}})",
               "/boundary/prescribed/0/node: the key appears twice");
  expect_error(std::string("{\"maze\": null}\0{\"rod\": {\"nodes\": 3}}", 33), "NUL byte at offset 14");
  expect_error(R"({"maze": null, "boundary": {"pinned": [18446744073709551615]}})", "/boundary/pinned/0");
  expect_error(R"({"maze": null, "boundary": {"pinned": [-9223372036854775808]}})", "/boundary/pinned/0");
  expect_error(R"({"maze": null, "rod": {"length": 1e309}})", "double range");
  // Legal values still read.
  EXPECT_EQ(read_scene_text(R"({"maze": null, "boundary": {"pinned": [3, -1]}})", "ok.json").boundary.pinned.size(), 2u);
}

TEST(SceneStrictness, AnUnknownKeyErrorListsEveryValidKeyThere) {
  // Keys the reader only asks about (has) once went missing from the list: "vessels" at the top,
  // "advance" in /control, "points" in /control/advance.
  EXPECT_NE(error_of(R"({"vesels": {}})").find(", vessels)"), std::string::npos) << error_of(R"({"vesels": {}})");
  const std::string control = error_of(R"({"control": {"advanse": {}}})");
  EXPECT_NE(control.find("/control/advanse: unknown key (known keys here: actuated_nodes, advance,"), std::string::npos) << control;
  const std::string advance = error_of(R"({"control": {"advance": {"pionts": [[0, 0]]}}})");
  EXPECT_NE(advance.find("points"), std::string::npos) << advance;
}

TEST(SceneStrictness, DeepNestingIsRefusedWithoutRecursion) {
  const int levels = 100000;
  const std::string deep = std::string(levels, '[') + std::string(levels, ']');
  expect_error("{\"maze\": null, \"rod\": " + deep + "}", "nested deeper than 64 levels");
  const std::string deep_objects = [&] {
    std::string s;
    for (int i = 0; i < levels; ++i) s += "{\"a\":";
    s += "1";
    s += std::string(levels, '}');
    return s;
  }();
  expect_error(deep_objects, "nested deeper than 64 levels");
  try {
    read_log_metadata("{\"title\": " + deep + "}", "run/frames.vlog");
    ADD_FAILURE() << "deep metadata accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run/frames.vlog"), std::string::npos) << e.what();
  }
}

// Found by the scene fuzz harness (tests/fuzz/regressions/scene/long_string_cut_inside_a_character.json):
// a long string quoted in a message was cut inside a two-byte character, and dumping the cut
// text threw nlohmann's type_error (terminate). Messages quote whole characters only.
TEST(SceneStrictness, ALongNonAsciiValueIsQuotedShortenedAtACharacterBoundary) {
  std::string cyrillic;
  for (int i = 0; i < 40; ++i) cyrillic += "\xd1\x9c";  // U+045C, two bytes: 80 bytes in all
  for (const std::size_t shift : {0, 1}) {
    const std::string value = std::string(shift, 'a') + cyrillic;
    const std::string message = error_of("{\"maze\": null, \"rod\": \"" + value + "\"}");
    EXPECT_NE(message.find("/rod"), std::string::npos) << message;
    EXPECT_NE(message.find("..."), std::string::npos) << "the value is shortened: " << message;
    EXPECT_TRUE(valid_utf8(message)) << "the message is not valid UTF-8: " << message;
  }
  EXPECT_EQ(io::utf8_prefix("a\xd1\x9c", 2), "a");
  EXPECT_EQ(io::utf8_prefix("a\xd1\x9c", 3), "a\xd1\x9c");
  EXPECT_EQ(io::utf8_prefix("ab", 5), "ab");
}

TEST(SceneStrictness, TheCommandLineExitsTwoNamingTheFile) {
  const std::string dir = test::fresh_temp_dir("strict");
  test::write_text(dir + "/huge.json", R"({"maze": null, "rod": {"length": 1e309}})");
  const auto r = test::run_vascsim("run " + dir + "/huge.json --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/huge.json"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace vascsim
