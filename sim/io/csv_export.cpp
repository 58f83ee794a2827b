#include "sim/io/csv_export.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include "sim/io/json_fields.h"
#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

// %.17g round-trips a double; shortest output is not needed for files read by machines.
void put(std::string& out, double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  out += text;
}

std::string header_of(const LogChannel& c) {
  const std::string u = " [" + c.unit + "]";
  switch (c.layout) {
    case ChannelLayout::kNodeVectors: return "time [s],node,x" + u + ",y" + u + "\n";
    case ChannelLayout::kVector: return "time [s],x" + u + ",y" + u + "\n";
    case ChannelLayout::kScalars: return c.count == 1 ? "time [s],value" + u + "\n" : "time [s],index,value" + u + "\n";
  }
  return "\n";
}

}  // namespace

std::string csv_file_name(const std::string& channel) {
  std::string name = channel;
  std::replace(name.begin(), name.end(), '/', '_');
  return name + ".csv";
}

std::vector<std::string> export_csv(const FrameLogReader& log, const std::string& dir, const CsvExportOptions& options) {
  const auto& channels = log.header().channels;
  std::vector<std::size_t> chosen;  // indices into channels
  if (options.channels.empty()) {
    for (std::size_t i = 0; i < channels.size(); ++i) chosen.push_back(i);
  } else {
    for (const std::string& name : options.channels) {
      const auto it = std::find_if(channels.begin(), channels.end(), [&](const LogChannel& c) { return c.name == name; });
      if (it == channels.end()) {
        std::string known;
        for (const auto& c : channels) known += (known.empty() ? "" : ", ") + c.name;
        throw InputError(log.path() + ": no channel \"" + name + "\" (the log has " + known + ")");
      }
      chosen.push_back(static_cast<std::size_t>(it - channels.begin()));
    }
  }
  const bool dir_exists = std::filesystem::exists(dir);
  if (dir_exists && !std::filesystem::is_directory(dir)) throw InputError(dir + ": not a directory");
  std::vector<std::string> paths;
  std::map<std::string, std::string> channel_of_file;  // refused before any file is written
  for (std::size_t i : chosen) {
    const std::string file = csv_file_name(channels[i].name);
    const auto [it, fresh] = channel_of_file.emplace(file, channels[i].name);
    if (!fresh)
      throw InputError(log.path() + ": channels \"" + it->second + "\" and \"" + channels[i].name + "\" would both be written to " +
                       file + " ('/' becomes '_'): export them one at a time (--channels) into different directories");
    paths.push_back((std::filesystem::path(dir) / file).string());
    if (dir_exists) check_replaceable_output(paths.back(), options.overwrite, {log.path()});  // else nothing to replace
  }

  // The frames kept: by time, then every k-th. Every frame's time is checked on the way, so a
  // corrupt log fails here rather than as a table with a time out of order.
  std::vector<std::size_t> frames;
  const std::size_t n = log.frame_count();
  if (n == 0) throw InputError(log.path() + ": frame log has no complete frame");
  double previous = 0.0;
  for (std::size_t f = 0, kept = 0; f < n; ++f) {
    const double t = log.time_of(f);
    check_frame_time(log.path(), f, t, previous);
    previous = t;
    if (t < options.from || t > options.to) continue;
    if (kept++ % std::max<std::size_t>(1, options.every) == 0) frames.push_back(f);
  }
  if (frames.empty())
    throw InputError(log.path() + ": no frame in the time range [" + io::format_number(options.from) + ", " +
                     io::format_number(options.to) + "] s (the log spans " + io::format_number(log.time_of(0)) + " .. " +
                     io::format_number(previous) + " s)");

  std::vector<std::size_t> offset(channels.size(), 1);  // in doubles, after the time
  for (std::size_t i = 1; i < channels.size(); ++i) offset[i] = offset[i - 1] + channels[i - 1].count;
  std::vector<double> values;
  // Created (with its parents) only now, so that input refused above leaves nothing behind.
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot create the directory (" + ec.message() + ")");
  OutputFileSet files;  // all of them or none: a failed export leaves no half of itself
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const LogChannel& c = channels[chosen[k]];
    std::string out = header_of(c);
    values.resize(c.count);
    for (std::size_t f : frames) {
      const double t = log.time_of(f);
      log.read_values(f, offset[chosen[k]], c.count, values.data());
      const std::size_t rows = c.layout == ChannelLayout::kNodeVectors ? c.count / 2 : (c.layout == ChannelLayout::kVector ? 1 : c.count);
      for (std::size_t r = 0; r < rows; ++r) {
        put(out, t);
        if (c.layout == ChannelLayout::kNodeVectors || (c.layout == ChannelLayout::kScalars && c.count > 1))
          out += "," + std::to_string(r);
        if (c.layout == ChannelLayout::kScalars) {
          out += ",";
          put(out, values[r]);
        } else {
          out += ",";
          put(out, values[2 * r]);
          out += ",";
          put(out, values[2 * r + 1]);
        }
        out += "\n";
      }
    }
    files.add(paths[k], out);
  }
  files.commit();
  return paths;
}

}  // namespace vascsim
