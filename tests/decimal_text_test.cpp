// The one parser of numbers typed in options and URL parameters (sim/io/decimal_text.h): what a
// person writes for a time or a length reads as that number; what strtod would also read (a
// leading space, hexadecimal, inf, nan, a trailing unit) and what overflows is refused; what
// underflows reads as the nearest double. Expected values are the decimal literals themselves
// (as the compiler reads them).
#include <gtest/gtest.h>

#include "sim/io/decimal_text.h"

namespace vascsim::io {
namespace {

TEST(DecimalText, ReadsDecimalNumbersWhole) {
  const std::pair<const char*, double> read[] = {{"0", 0.0}, {"-0", -0.0}, {"2.5", 2.5}, {"+3", 3.0}, {".5", 0.5},
                                                 {"1e-3", 1e-3}, {"-1.25E+2", -125.0}, {"1e308", 1e308},
                                                 // Underflow rounds, as strtod (and a JSON number) does.
                                                 {"1e-400", 0.0}, {"-1e-400", -0.0}, {"4.9e-324", 4.9e-324}};
  for (const auto& [text, value] : read) {
    const auto x = parse_decimal(text);
    ASSERT_TRUE(x) << text;
    EXPECT_EQ(*x, value) << text;
  }
  for (const char* refused : {"", " 5", "5 ", "0x10", "0X1p3", "inf", "nan", "-inf", "1e400", "-1e400", "5s", "1,5",
                              "--5", "e", ".", "1e", "١"})
    EXPECT_FALSE(parse_decimal(refused)) << "'" << refused << "'";
  EXPECT_FALSE(parse_decimal(std::string(65, '1'))) << "longer than 64 characters";
}

TEST(DecimalText, ReadsIntegersWhole) {
  EXPECT_EQ(parse_decimal_integer("0"), 0);
  EXPECT_EQ(parse_decimal_integer("-12"), -12);
  EXPECT_EQ(parse_decimal_integer("+5"), 5);
  EXPECT_EQ(parse_decimal_integer("9223372036854775807"), 9223372036854775807LL);
  for (const char* refused : {"", "-", "+", "+-5", " 5", "5 ", "0x10", "1e3", "1.0", "9223372036854775808", "--1", "1-"})
    EXPECT_FALSE(parse_decimal_integer(refused)) << "'" << refused << "'";
}

}  // namespace
}  // namespace vascsim::io
