// The warnings of a finished run as a user reads them, made from its summary.json: what
// `vascsim run` prints on stderr and what the replay page marks on its timeline, worded once.
// Round-off stops and steps kept at a floor over the tolerance are counted in summary.json but
// not listed: both are accepted by design (docs/solver.md, docs/accuracy.md). Not part of the
// installed API (it would expose nlohmann-json, a private dependency).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace vascsim {

struct RunWarning {
  std::string key;          // its name under summary.json /warnings
  std::string what;         // what happened, as a clause
  int count = 0;            // steps, frames or load increments it happened in
  double first_time = 0.0;  // s (a static solve's: the load factor)

  // "WHAT N times, first at t = T s"
  std::string line() const;
};

// The listed warnings whose count is above 0, in a fixed order. Entries missing or of another
// shape (a hand-edited summary, another version's) are left out.
std::vector<RunWarning> listed_warnings(const nlohmann::json& summary);

}  // namespace vascsim
