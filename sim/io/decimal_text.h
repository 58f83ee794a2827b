// Numbers as people type them in a command-line option or a URL parameter: decimal digits, a
// sign, a point and an exponent, the whole text and nothing else. strtod alone also reads " 5"
// (a leading space), "0x10" (16), "inf" and "nan", which nobody means for a time or a length;
// one parser, so every option and request parameter refuses the same texts.
#pragma once

#include <optional>
#include <string>

namespace vascsim::io {

// The finite number the whole of `text` spells in decimal (at most 64 characters; not one that
// overflows a double; one that underflows reads as the nearest double, 0 or subnormal), or nothing.
std::optional<double> parse_decimal(const std::string& text);
// The integer the whole of `text` spells in decimal digits after an optional sign (no spaces),
// or nothing if it does not or is out of the range of long long.
std::optional<long long> parse_decimal_integer(const std::string& text);

}  // namespace vascsim::io
