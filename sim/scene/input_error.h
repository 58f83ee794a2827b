// Errors a user can fix: a bad scene value, a missing or truncated file, an unwritable output.
// The library throws these with a complete message ("FILE: /json/path: expected X, got Y"); the
// command line catches them, prints the message and exits with code 2. The library never exits.
#pragma once

#include <stdexcept>
#include <string>

namespace vascsim {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace vascsim
