// Command-line parsing for the vascsim subcommands: options of the form --name VALUE or --flag,
// and positional arguments. Each subcommand declares its options, so --help lists exactly them
// and an unknown option is a usage error (exit code 2).
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace vascsim::cli {

// A command-line mistake; main prints it with the subcommand's usage hint and exits 2.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& m) : std::runtime_error(m) {}
};

// The value name of an option that takes a comma-separated list, which may be empty.
inline constexpr const char* kListValue = "a,b,...";

struct OptionSpec {
  std::string name;        // without the leading dashes
  std::string value_name;  // empty for a flag
  std::string help;
};

class Args {
 public:
  // Parses argv[first..argc). Throws UsageError for unknown options or missing values.
  Args(int argc, char** argv, int first, const std::vector<OptionSpec>& options);

  bool flag(const std::string& name) const { return values_.count(name) > 0; }
  std::optional<std::string> value(const std::string& name) const;
  double number(const std::string& name, double fallback, double min, double max) const;
  long long integer(const std::string& name, long long fallback, long long min, long long max) const;
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::map<std::string, std::string> values_;
  std::vector<std::string> positional_;
};

// The help text for a list of options, one per line, aligned.
std::string format_options(const std::vector<OptionSpec>& options);

}  // namespace vascsim::cli
