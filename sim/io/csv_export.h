// A frame log as CSV files for tools that do not read binary formats (MATLAB, Excel, R): one file
// per channel in long format, with a header naming the units. The C++ frame-log reader is the
// source; `vascsim export` is the command (docs/frame-log.md).
#pragma once

#include <string>
#include <vector>

#include "sim/log/frame_log.h"

namespace vascsim {

struct CsvExportOptions {
  std::vector<std::string> channels;  // names; empty: every channel
  double from = -1e300, to = 1e300;   // s, frames with from <= t <= to
  std::size_t every = 1;              // keep every k-th frame of those, starting with the first
  bool overwrite = false;             // replace existing CSV files
};

// The file name a channel is written to: its name with '/' as '_', then ".csv"
// ("force/contact" -> "force_contact.csv").
std::string csv_file_name(const std::string& channel);

// Writes DIR/<channel>.csv for the chosen channels of `log` (DIR and its parents created if missing):
//   node vectors: "time [s],node,x [unit],y [unit]", one row per frame and node;
//   a vector:     "time [s],x [unit],y [unit]";
//   scalars:      "time [s],value [unit]" (one value) or "time [s],index,value [unit]".
// Values print with 17 significant digits, so they read back to the same doubles. The files
// appear complete under their final names all together, or none of them. Throws InputError
// naming the channel (not in the log) or the file (exists without overwrite, cannot be written)
// before writing anything where it can. Returns the files written.
std::vector<std::string> export_csv(const FrameLogReader& log, const std::string& dir, const CsvExportOptions& options);

}  // namespace vascsim
