#include <cstdio>
#include <set>
#include <sstream>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "sim/io/csv_export.h"
#include "sim/io/log_metadata.h"
#include "sim/io/log_run_check.h"
#include "sim/log/frame_log.h"

namespace vascsim::cli {

namespace {

const std::vector<OptionSpec> kOptions = {
    {"csv", "DIR", "write one CSV per channel into DIR (required; created if missing)"},
    {"channels", kListValue, "only these channels (default: all; names as in docs/frame-log.md)"},
    {"from", "T0", "first time in s (default: the first frame)"},
    {"to", "T1", "last time in s (default: the last frame)"},
    {"every", "K", "keep every K-th frame of those (default 1)"},
    {"force", "", "replace CSV files that exist"},
    {"help", "", "show this help"},
};

void print_usage() {
  std::printf(
      "usage: vascsim export RUN_DIR --csv DIR [--channels a,b] [--from T0 --to T1] [--every K] [--force]\n\n"
      "Writes a run's frame log as CSV for MATLAB, Excel or R: DIR/<channel>.csv ('/' becomes '_'), long\n"
      "format with units in the header (time, node, x, y for node vectors; time, value for scalars).\n\noptions:\n%s",
      format_options(kOptions).c_str());
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

int run_export_command(int argc, char** argv) {
  Args args(argc, argv, 2, kOptions);
  if (args.flag("help")) {
    print_usage();
    return 0;
  }
  if (args.positional().size() != 1) throw UsageError("expected one RUN_DIR");
  const auto dir = args.value("csv");
  if (!dir) throw UsageError("--csv DIR is required");
  CsvExportOptions options;
  if (auto c = args.value("channels")) {
    options.channels = split(*c);
    if (options.channels.empty()) throw UsageError("--channels: expected a comma-separated list of channel names, got '" + *c + "'");
    std::set<std::string> seen;
    for (const std::string& name : options.channels)
      if (!seen.insert(name).second) throw UsageError("--channels: '" + name + "' is listed twice");
  }
  options.from = args.number("from", options.from, -1e300, 1e300);
  options.to = args.number("to", options.to, -1e300, 1e300);
  if (options.to < options.from) throw UsageError("--to must not be before --from");
  options.every = static_cast<std::size_t>(args.integer("every", 1, 1, 1000000000));
  options.overwrite = args.flag("force");
  const std::string log_path = frame_log_path(args.positional().front());
  const FrameLogReader log(log_path);
  const std::string& run = args.positional().front();
  for (const std::string& warning :
       check_log_against_run(run, log.frame_count(), read_log_metadata(log.header().metadata, log_path).scene_hash).warnings)
    std::fprintf(stderr, "vascsim export: %s\n", warning.c_str());
  const auto files = export_csv(log, *dir, options);
  std::printf("wrote %zu CSV file%s to %s\n", files.size(), files.size() == 1 ? "" : "s", dir->c_str());
  return 0;
}

}  // namespace vascsim::cli
