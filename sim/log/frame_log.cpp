#include "sim/log/frame_log.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "sim/scene/input_error.h"

namespace vascsim {

std::string frame_log_path(const std::string& run_path) {
  std::error_code ec;
  if (!std::filesystem::exists(run_path, ec))
    throw InputError(run_path + ": no such run directory or frame log (expected RUN_DIR/frames.vlog)");
  if (std::filesystem::is_directory(run_path, ec)) return (std::filesystem::path(run_path) / "frames.vlog").string();
  return run_path;
}
namespace {

constexpr char kMagic[8] = {'V', 'S', 'I', 'M', 'L', 'O', 'G', '\0'};

// The format is little-endian; every machine we build for is too, so values are written raw.
static_assert(sizeof(double) == 8, "frame log stores IEEE-754 binary64");

void put_u8(std::string& out, std::uint8_t v) { out.push_back(static_cast<char>(v)); }
void put_u32(std::string& out, std::uint32_t v) {
  char b[4];
  std::memcpy(b, &v, 4);
  out.append(b, 4);
}
void put_string(std::string& out, const std::string& s) {
  put_u32(out, static_cast<std::uint32_t>(s.size()));
  out += s;
}

// Reads the header fields in order from a byte buffer, failing with a message on truncation.
class ByteCursor {
 public:
  ByteCursor(const std::string& path, std::FILE* f) : path_(path), file_(f) {}
  void bytes(void* out, std::size_t n) {
    if (std::fread(out, 1, n, file_) != n)
      throw InputError(path_ + ": truncated frame log header");
    consumed_ += n;
  }
  std::uint8_t u8() { std::uint8_t v; bytes(&v, 1); return v; }
  std::uint32_t u32() { std::uint32_t v; bytes(&v, 4); return v; }
  std::string string(std::uint32_t max_len) {
    std::uint32_t n = u32();
    if (n > max_len) throw InputError(path_ + ": corrupt frame log header (string of " + std::to_string(n) + " bytes)");
    std::string s(n, '\0');
    if (n) bytes(s.data(), n);
    return s;
  }
  std::uint64_t consumed() const { return consumed_; }

 private:
  const std::string& path_;
  std::FILE* file_;
  std::uint64_t consumed_ = 0;
};

}  // namespace

int FrameLogHeader::find_channel(const std::string& name) const {
  for (std::size_t i = 0; i < channels.size(); ++i)
    if (channels[i].name == name) return static_cast<int>(i);
  return -1;
}

std::size_t FrameLogHeader::record_doubles() const {
  std::size_t n = 1;
  for (const auto& c : channels) n += c.count;
  return n;
}

std::size_t FrameLogHeader::channel_offset(int index) const {
  std::size_t offset = 1;
  for (int i = 0; i < index; ++i) offset += channels[static_cast<std::size_t>(i)].count;
  return offset;
}

std::uint64_t frame_log_header_bytes(const FrameLogHeader& header) {
  std::uint64_t bytes = sizeof kMagic + 3 * 4 + 4 + header.metadata.size();
  for (const auto& c : header.channels) bytes += 4 + c.name.size() + 4 + c.unit.size() + 1 + 4;
  return (bytes + 7) / 8 * 8;
}

FrameLogWriter::FrameLogWriter(const std::string& path, const FrameLogHeader& header)
    : path_(path), header_(header) {
  for (const auto& c : header_.channels) {
    if (c.layout == ChannelLayout::kNodeVectors && c.count != 2 * header_.node_count)
      throw std::invalid_argument("frame log channel " + c.name + ": node vectors need 2*node_count values");
    if (c.layout == ChannelLayout::kVector && c.count != 2)
      throw std::invalid_argument("frame log channel " + c.name + ": a vector has 2 values");
  }
  // Checked before the file exists: a log its readers refuse must not be written at all.
  if (header_.metadata.size() > kMaxMetadataBytes)
    throw InputError(path + ": frame log metadata of " + std::to_string(header_.metadata.size()) + " bytes exceeds the " +
                     std::to_string(kMaxMetadataBytes >> 20) + " MiB limit (a path or wall list too finely sampled?)");
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) throw InputError(path + ": cannot create frame log (" + std::strerror(errno) + ")");
  // Closed if the header cannot be written (a full disk): the destructor does not run for a
  // constructor that throws. The file is left as it is (it may be the user's device or pipe).
  try {
    std::string bytes(kMagic, sizeof kMagic);
    put_u32(bytes, kFrameLogVersion);
    put_u32(bytes, header_.node_count);
    put_u32(bytes, static_cast<std::uint32_t>(header_.channels.size()));
    for (const auto& c : header_.channels) {
      put_string(bytes, c.name);
      put_string(bytes, c.unit);
      put_u8(bytes, static_cast<std::uint8_t>(c.layout));
      put_u32(bytes, c.count);
    }
    put_string(bytes, header_.metadata);
    // Records start 8-byte aligned so a reader may map the file and view them as doubles.
    while (bytes.size() % 8 != 0) bytes.push_back('\0');
    if (bytes.size() != frame_log_header_bytes(header_)) throw std::logic_error("frame_log_header_bytes disagrees with the writer");
    if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size() || std::fflush(file_) != 0)
      throw InputError(path_ + ": cannot write frame log header (" + std::strerror(errno) + ")");
  } catch (...) {
    std::fclose(file_);
    file_ = nullptr;
    throw;
  }
  record_.resize(header_.record_doubles());
}

FrameLogWriter::~FrameLogWriter() {
  if (file_) std::fclose(file_);
}

void FrameLogWriter::append(double time, const std::vector<double>& values) {
  if (values.size() + 1 != record_.size())
    throw std::invalid_argument("frame log append: expected " + std::to_string(record_.size() - 1) +
                                " values, got " + std::to_string(values.size()));
  if (!file_) throw std::logic_error("frame log append after close");
  record_[0] = time;
  std::copy(values.begin(), values.end(), record_.begin() + 1);
  const std::size_t n = record_.size() * sizeof(double);
  // Flushing each record means a killed run keeps every frame it completed.
  if (std::fwrite(record_.data(), 1, n, file_) != n || std::fflush(file_) != 0)
    throw InputError(path_ + ": cannot write frame " + std::to_string(frames_written_) + " (" +
                     std::strerror(errno) + ")");
  ++frames_written_;
}

void FrameLogWriter::close() {
  if (!file_) return;
  const bool ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok) throw InputError(path_ + ": cannot close frame log (" + std::strerror(errno) + ")");
}

std::string run_dir_of(const std::string& run_path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(run_path, ec)) return run_path;
  const fs::path log(run_path);
  if (log.filename() != "frames.vlog") return "";
  return log.has_parent_path() ? log.parent_path().string() : ".";
}

InputError bad_frame_time(const std::string& path, std::size_t i, double t, const char* why) {
  char time[32];
  std::snprintf(time, sizeof time, "%.17g", t);  // all digits: the fault may be in the last ones
  return InputError(path + ": frame " + std::to_string(i) + " has time " + time + " s, " + why +
                    " (times must be finite, >= 0 and non-decreasing)");
}

void check_frame_time(const std::string& path, std::size_t i, double t, double previous) {
  if (!std::isfinite(t) || t < 0) throw bad_frame_time(path, i, t, "not a finite time >= 0");
  if (i > 0 && t < previous) throw bad_frame_time(path, i, t, "before the previous frame's time");
}

FrameLogReader::FrameLogReader(const std::string& path) : path_(path) {
  // Checked before opening: fopen on a FIFO blocks until a writer comes, which hung `export` and
  // `render` on a pipe named frames.vlog, and a directory only failed later as a "truncated" log.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) throw InputError(path + ": is a directory, not a frame log");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(path + ": not a regular file (a frame log is read from a file, not a device or a pipe)");
  file_ = std::fopen(path.c_str(), "rb");
  if (!file_) throw InputError(path + ": cannot open frame log (" + std::strerror(errno) + ")");
  // A refused file is closed here: the destructor does not run for a constructor that throws.
  try {
    read_header();
  } catch (...) {
    std::fclose(file_);
    file_ = nullptr;
    throw;
  }
}

void FrameLogReader::read_header() {
  const std::string& path = path_;
  ByteCursor in(path_, file_);
  char magic[8];
  in.bytes(magic, 8);
  if (std::memcmp(magic, kMagic, 8) != 0) throw InputError(path + ": not a vascsim frame log");
  const std::uint32_t version = in.u32();
  // A newer format (3D rods, say) comes with a newer version number: say so, not "corrupt".
  if (version != kFrameLogVersion)
    throw InputError(path + ": frame log format version " + std::to_string(version) +
                     (version > kFrameLogVersion ? ", written by a newer vascsim" : "") + "; this build reads version " +
                     std::to_string(kFrameLogVersion) + (version > kFrameLogVersion ? " (update vascsim to read it)" : ""));
  header_.node_count = in.u32();
  const std::uint32_t channel_count = in.u32();
  if (channel_count > 4096) throw InputError(path + ": corrupt frame log header (channel count)");
  for (std::uint32_t i = 0; i < channel_count; ++i) {
    LogChannel c;
    c.name = in.string(1024);
    c.unit = in.string(1024);
    const std::uint8_t layout = in.u8();
    if (layout > 2) throw InputError(path + ": corrupt frame log header (channel layout)");
    c.layout = static_cast<ChannelLayout>(layout);
    c.count = in.u32();
    // 64 bits: twice a corrupt node count near 2^32 must not wrap to a small count that matches.
    const std::uint64_t expected = c.layout == ChannelLayout::kNodeVectors ? 2ull * header_.node_count
                                   : c.layout == ChannelLayout::kVector    ? 2ull
                                                                           : std::max<std::uint64_t>(c.count, 1);
    if (c.count != expected)
      throw InputError(path + ": channel '" + c.name.substr(0, 64) + "' holds " + std::to_string(c.count) +
                       " values per frame, expected " + std::to_string(expected) +
                       (c.layout == ChannelLayout::kNodeVectors ? " (2 per node)" : ""));
    header_.channels.push_back(c);
  }
  const std::uint32_t metadata_bytes = in.u32();
  if (metadata_bytes > kMaxMetadataBytes)
    throw InputError(path + ": frame log metadata of " + std::to_string(metadata_bytes) + " bytes exceeds the " +
                     std::to_string(kMaxMetadataBytes >> 20) + " MiB limit");
  header_.metadata.assign(metadata_bytes, '\0');
  if (metadata_bytes) in.bytes(header_.metadata.data(), metadata_bytes);
  data_offset_ = (in.consumed() + 7) / 8 * 8;
  header_bytes_.resize(in.consumed());
  if (::pread(fileno(file_), header_bytes_.data(), header_bytes_.size(), 0) != static_cast<ssize_t>(header_bytes_.size()))
    throw InputError(path + ": cannot read the frame log header");
}

FrameLogReader::~FrameLogReader() {
  if (file_) std::fclose(file_);
}

std::size_t FrameLogReader::frame_count() const {
  if (std::fseek(file_, 0, SEEK_END) != 0) return 0;
  const long end = std::ftell(file_);
  if (end < 0 || static_cast<std::uint64_t>(end) < data_offset_) return 0;
  const std::uint64_t record_bytes = header_.record_doubles() * sizeof(double);
  return static_cast<std::size_t>((static_cast<std::uint64_t>(end) - data_offset_) / record_bytes);
}

bool FrameLogReader::replaced() const {
  struct stat open_file {}, named {};
  if (::fstat(fileno(file_), &open_file) != 0) return false;
  if (::stat(path_.c_str(), &named) != 0) return true;  // removed, and not (yet) written again
  if (open_file.st_ino != named.st_ino || open_file.st_dev != named.st_dev) return true;
  // The same file written over in place (cp onto it) with another run: its header (the scene and
  // channels) differs. A run of the same scene and seed writes the same bytes, so is no change.
  std::vector<char> now(header_bytes_.size());
  return ::pread(fileno(file_), now.data(), now.size(), 0) != static_cast<ssize_t>(now.size()) || now != header_bytes_;
}

void FrameLogReader::read(std::size_t i, std::vector<double>& record) const {
  const std::size_t n = header_.record_doubles();
  record.resize(n);
  const std::uint64_t offset = data_offset_ + static_cast<std::uint64_t>(i) * n * sizeof(double);
  if (std::fseek(file_, static_cast<long>(offset), SEEK_SET) != 0 ||
      std::fread(record.data(), sizeof(double), n, file_) != n)
    throw InputError(path_ + ": cannot read frame " + std::to_string(i) + " (log has " +
                     std::to_string(frame_count()) + " complete frames)");
}

double FrameLogReader::time_of(std::size_t i) const {
  double t = 0.0;
  read_values(i, 0, 1, &t);
  return t;
}

void FrameLogReader::read_values(std::size_t i, std::size_t offset, std::size_t count, double* out) const {
  const std::size_t n = header_.record_doubles();
  if (offset + count > n) throw std::invalid_argument("FrameLogReader::read_values: values beyond the record");
  const std::uint64_t at = data_offset_ + (static_cast<std::uint64_t>(i) * n + offset) * sizeof(double);
  if (std::fseek(file_, static_cast<long>(at), SEEK_SET) != 0 || std::fread(out, sizeof(double), count, file_) != count)
    throw InputError(path_ + ": cannot read frame " + std::to_string(i) + " (log has " +
                     std::to_string(frame_count()) + " complete frames)");
}

void FrameLogReader::read_frames(std::size_t first, std::size_t count, std::vector<double>& records) const {
  const std::size_t n = header_.record_doubles();
  records.resize(count * n);
  if (count == 0) return;
  const std::uint64_t at = data_offset_ + static_cast<std::uint64_t>(first) * n * sizeof(double);
  if (std::fseek(file_, static_cast<long>(at), SEEK_SET) != 0 ||
      std::fread(records.data(), sizeof(double), count * n, file_) != count * n)
    throw InputError(path_ + ": cannot read frames " + std::to_string(first) + ".." +
                     std::to_string(first + count - 1) + " (log has " + std::to_string(frame_count()) +
                     " complete frames)");
}

std::size_t FrameLogReader::frame_at_time(double t) const {
  std::size_t lo = 0, hi = frame_count();
  if (hi == 0) throw InputError(path_ + ": frame log has no frames");
  // Invariant: answer in [lo, hi); times are non-decreasing.
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (time_of(mid) <= t) lo = mid; else hi = mid;
  }
  return lo;
}

}  // namespace vascsim
