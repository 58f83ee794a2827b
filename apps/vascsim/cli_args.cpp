#include "apps/vascsim/cli_args.h"

#include <cstdio>

#include "sim/io/decimal_text.h"

namespace vascsim::cli {

Args::Args(int argc, char** argv, int first, const std::vector<OptionSpec>& options) {
  for (int i = first; i < argc; ++i) {
    std::string a = argv[i];
    if (a.size() < 3 || a.compare(0, 2, "--") != 0) {
      if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option '" + a + "'");
      positional_.push_back(a);
      continue;
    }
    std::string name = a.substr(2), inline_value;
    const bool has_inline = name.find('=') != std::string::npos;
    if (has_inline) {
      inline_value = name.substr(name.find('=') + 1);
      name = name.substr(0, name.find('='));
    }
    const OptionSpec* spec = nullptr;
    for (const auto& o : options)
      if (o.name == name) spec = &o;
    if (!spec) throw UsageError("unknown option '--" + name + "'");
    if (spec->value_name.empty()) {
      if (has_inline) throw UsageError("option '--" + name + "' takes no value");
      values_[name] = "";
    } else if (values_.count(name)) {
      // Which of two values was meant is a guess; a script that builds a command line can say.
      throw UsageError("option '--" + name + "' given twice");
    } else if (has_inline) {
      values_[name] = inline_value;
    } else {
      if (i + 1 >= argc) throw UsageError("option '--" + name + "' needs a value " + spec->value_name);
      // `--out --duration 0.5` (a value left out): the next option is not taken as the value.
      const std::string next = argv[i + 1];
      for (const auto& o : options)
        if (next == "--" + o.name || next.rfind("--" + o.name + "=", 0) == 0)
          throw UsageError("option '--" + name + "' needs a value " + spec->value_name + ", got the option '" + next + "'");
      values_[name] = argv[++i];
    }
    // An empty list is a list (--layers '' draws no layer); an empty path or number is a
    // script's unset variable, which gave messages such as ": not a directory".
    if (!spec->value_name.empty() && values_[name].empty() && spec->value_name != kListValue)
      throw UsageError("option '--" + name + "' needs a value " + spec->value_name + ", got an empty one");
  }
}

std::optional<std::string> Args::value(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

double Args::number(const std::string& name, double fallback, double min, double max) const {
  auto v = value(name);
  if (!v) return fallback;
  const std::optional<double> x = io::parse_decimal(*v);
  if (!x || *x < min || *x > max) {
    char range[64];
    std::snprintf(range, sizeof range, "[%g, %g]", min, max);
    throw UsageError("--" + name + ": expected a number in " + range + ", got '" + *v + "'");
  }
  return *x;
}

long long Args::integer(const std::string& name, long long fallback, long long min, long long max) const {
  auto v = value(name);
  if (!v) return fallback;
  const std::optional<long long> x = io::parse_decimal_integer(*v);
  if (!x || *x < min || *x > max)
    throw UsageError("--" + name + ": expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                     "], got '" + *v + "'");
  return *x;
}

std::string format_options(const std::vector<OptionSpec>& options) {
  std::string out;
  for (const auto& o : options) {
    std::string left = "  --" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
    if (left.size() < 26) left.resize(26, ' ');
    else left += "\n" + std::string(26, ' ');
    out += left + o.help + "\n";
  }
  return out;
}

}  // namespace vascsim::cli
