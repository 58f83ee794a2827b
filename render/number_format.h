// Numbers for people: "nice" round values for scale bars, legends and plot ticks, and SI values
// printed in the unit a clinician reads them in (mm, mN, µN, s).
#pragma once

#include <string>
#include <vector>

namespace vascsim::render {

// The largest value of the form {1, 2, 5} x 10^k that is <= x (x > 0).
double nice_floor(double x);
// Tick positions covering [lo, hi] with about `target` intervals, on a 1-2-5 step; just {lo, hi}
// for a range no double can step through (wider than the double range, or narrower than the
// precision of its values).
std::vector<double> nice_ticks(double lo, double hi, int target);
// Formats a tick value so consecutive ticks (step apart) read distinctly and without noise.
std::string format_tick(double value, double step);

// A display unit: value_in_unit = value_SI * factor.
struct DisplayUnit {
  double factor;
  const char* name;
};
// mN for forces in [1e-3, 1) N, µN below, N above.
DisplayUnit force_unit(double typical_newtons);
// mm below 1 m, else m.
DisplayUnit length_unit(double typical_metres);
// "1.23 mN": `digits` decimals in the unit.
std::string format_value(double value_si, DisplayUnit unit, int digits);
// A round value (nice_floor's) with the decimals its one significant digit needs in the unit:
// "20 mm", "0.5 mN", "0.02 mN" (a legend's reference force far below the unit chose "0.0 mN");
// below 1e-4 of the unit an exponent, "5e-11 mN".
std::string format_round_value(double value_si, DisplayUnit unit);

}  // namespace vascsim::render
