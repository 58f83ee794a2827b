#include "render/number_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vascsim::render {

double nice_floor(double x) {
  if (!(x > 0) || !std::isfinite(x)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  const double m = x / p;
  // The 1e-9 slack keeps exact decades (x = 10^k computed with rounding error) on themselves.
  return (m >= 5 - 1e-9 ? 5 : m >= 2 - 1e-9 ? 2 : 1) * p;
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo)) {
    ticks.push_back(lo);
    return ticks;
  }
  const double step = nice_floor((hi - lo) / std::max(target, 1));
  const double first = std::ceil(lo / step - 1e-9) * step;
  // A range too wide for a double (hi - lo overflows) or too narrow for its values' precision
  // (t + step == t) would never end the loop below: the axis gets its two ends.
  if (!std::isfinite(hi - lo) || !std::isfinite(first) || first + step == first) return {lo, hi};
  const std::size_t most = 10 * static_cast<std::size_t>(std::max(target, 1)) + 2;
  for (double t = first; t <= hi + 1e-9 * step && ticks.size() < most; t += step)
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

std::string format_tick(double value, double step) {
  char buf[400];
  if (std::abs(value) >= 1e7 || step < 1e-6) {
    // Far from 1 (a plot of a diverging run's forces at 1e300 N): a mantissa with the digits the
    // step leaves distinct, not 301 digits or a dozen leading zeros.
    const double magnitude = std::max(std::abs(value), step);
    const int digits = static_cast<int>(std::ceil(std::log10(magnitude) + 1e-9) - std::floor(std::log10(step) + 1e-9));
    std::snprintf(buf, sizeof buf, "%.*g", std::clamp(digits, 1, 17), value);
    return buf;
  }
  const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

DisplayUnit force_unit(double typical) {
  if (typical >= 1.0) return {1.0, "N"};
  if (typical >= 1e-3 || typical <= 0) return {1e3, "mN"};
  return {1e6, "\xC2\xB5N"};
}

DisplayUnit length_unit(double typical) {
  if (typical >= 1.0) return {1.0, "m"};
  return {1e3, "mm"};
}

std::string format_value(double value_si, DisplayUnit unit, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f %s", digits, value_si * unit.factor, unit.name);
  return buf;
}

std::string format_round_value(double value_si, DisplayUnit unit) {
  const double shown = std::abs(value_si * unit.factor);
  const int decimals = shown >= 1 || !(shown > 0) ? 0 : static_cast<int>(std::ceil(-std::log10(shown) - 1e-9));
  if (decimals <= 4) return format_value(value_si, unit, decimals);
  // Far below the unit (a user's arrow scale of 1e15 px/N gives a 5e-14 N reference): a
  // mantissa and exponent, not a dozen zeros to count ("0.00000000005 mN").
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.0e %s", value_si * unit.factor, unit.name);
  return buf;
}

}  // namespace vascsim::render
