#include "sim/io/decimal_text.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace vascsim::io {

std::optional<double> parse_decimal(const std::string& text) {
  if (text.empty() || text.size() > 64 || text.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(x)) return std::nullopt;
  // Underflow reads as the nearest double (0 or subnormal), as a scene file's JSON number does;
  // a range check refuses it where the value must be positive. Overflow stays refused.
  if (errno == ERANGE && std::abs(x) > std::numeric_limits<double>::min()) return std::nullopt;
  return x;
}

std::optional<long long> parse_decimal_integer(const std::string& text) {
  const std::size_t digits = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if (text.size() == digits || text.size() > 20 || text.find_first_not_of("0123456789", digits) != std::string::npos)
    return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const long long x = std::strtoll(text.c_str(), &end, 10);
  if (end != text.c_str() + text.size() || errno != 0) return std::nullopt;
  return x;
}

}  // namespace vascsim::io
