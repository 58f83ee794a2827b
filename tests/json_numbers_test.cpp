// first_inexact_number (sim/io/json_fields.h): the numbers of a file that the JSON library would
// write back changed, found before vascsim rewrites a file another tool also writes
// (bookmarks.json). The reference is IEEE 754 binary64 as RFC 8259 section 6 describes it:
// integers up to 2^53 and decimals of up to 15 significant digits come back as written; an
// integer beyond 64 bits, or more digits than a double's 17, do not.
#include <gtest/gtest.h>

#include <string>

#include "sim/io/json_fields.h"

namespace vascsim::io {
namespace {

TEST(JsonNumbers, NumbersADoubleOrA64BitIntegerHoldsAreExact) {
  EXPECT_EQ(first_inexact_number("{}"), "");
  EXPECT_EQ(first_inexact_number(R"({"a": [1, 2.5, 0.1, 1e-5, 100.0, 1E2, -0.0, 0.0120e3, 0.30000000000000004,
                                        18446744073709551615, -9223372036854775808, 1.7976931348623157e308]})"),
            "");
  EXPECT_EQ(first_inexact_number("not json"), "");
}

TEST(JsonNumbers, NamesTheFirstNumberThatWouldComeBackChanged) {
  EXPECT_EQ(first_inexact_number(R"({"a": {"b": [0, 123456789012345678901234, 3.14159265358979323846]}})"),
            "/a/b/1: 123456789012345678901234");
  EXPECT_EQ(first_inexact_number(R"({"x/y": [{"pi": 3.14159265358979323846}]})"), "/x~1y/0/pi: 3.14159265358979323846");
  // 2^64 is a double exactly, but written back as 1.8446744073709552e+19: another integer.
  EXPECT_EQ(first_inexact_number("[18446744073709551616]"), "/0: 18446744073709551616");
  EXPECT_EQ(first_inexact_number("-12345678901234567890"), "/: -12345678901234567890");
}

}  // namespace
}  // namespace vascsim::io
