// The frame log: everything a run produced, frame by frame, and the only thing the renderer reads.
//
// A log is one binary file (little-endian, documented in docs/frame-log.md): a header with a table
// of channels (named blocks of float64 stored in every frame) and an opaque metadata text (JSON
// written by the io layer: the scene, walls, path, rod radius), then fixed-size frame records.
// Fixed-size records make seeking to frame i O(1) and to a time O(log n) without reading the
// file, and a run killed midway leaves every completed record readable: the reader ignores a
// torn last record. The writer hands each record to the kernel as soon as it is complete.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/scene/input_error.h"

namespace vascsim {

// How a channel's values are laid out; tells a reader (and the renderer) how to interpret them.
enum class ChannelLayout : std::uint8_t {
  kScalars = 0,    // count independent scalars
  kNodeVectors = 1,  // one 2D vector per rod node: x0 y0 x1 y1 ... (count = 2 * node_count)
  kVector = 2,     // a single 2D vector (count = 2)
};

struct LogChannel {
  std::string name;  // e.g. "position", "force/contact"; see docs/frame-log.md
  std::string unit;  // SI unit, e.g. "m", "N"
  ChannelLayout layout = ChannelLayout::kScalars;
  std::uint32_t count = 0;  // float64 values per frame
};

struct FrameLogHeader {
  std::uint32_t node_count = 0;
  std::vector<LogChannel> channels;
  std::string metadata;  // JSON text, opaque to sim/

  // Index of the channel named `name`, or -1.
  int find_channel(const std::string& name) const;
  // Values per record, time included.
  std::size_t record_doubles() const;
  // Offset of channel `index` inside a record, in doubles (time is at 0).
  std::size_t channel_offset(int index) const;
};

inline constexpr std::uint32_t kFrameLogVersion = 1;
// The largest metadata a log may carry: geometry and scene for any network this tool draws,
// while a reader's JSON of it stays far below a gigabyte.
inline constexpr std::uint32_t kMaxMetadataBytes = 32u << 20;

// Bytes of a log's header as written (records start after it, 8-byte aligned): a log of n frames
// takes this plus n * record_doubles() * 8 bytes.
std::uint64_t frame_log_header_bytes(const FrameLogHeader& header);

// Streams frames to a file. Writes to `path`; the caller chooses whether that is a temporary name.
class FrameLogWriter {
 public:
  // Throws InputError if the file cannot be created.
  FrameLogWriter(const std::string& path, const FrameLogHeader& header);
  ~FrameLogWriter();
  FrameLogWriter(const FrameLogWriter&) = delete;
  FrameLogWriter& operator=(const FrameLogWriter&) = delete;

  // Appends one frame: `values` holds record_doubles() - 1 values in channel order.
  // Throws InputError on a short write (disk full) and std::invalid_argument on a size mismatch.
  void append(double time, const std::vector<double>& values);
  std::size_t frames_written() const { return frames_written_; }
  const FrameLogHeader& header() const { return header_; }
  void close();

 private:
  std::string path_;
  FrameLogHeader header_;
  std::FILE* file_ = nullptr;
  std::vector<double> record_;
  std::size_t frames_written_ = 0;
};

// The frame log of a run: RUN_DIR/frames.vlog for a directory, the path itself for a file.
// Throws InputError if neither exists.
std::string frame_log_path(const std::string& run_path);
// The run directory a path names: the path itself for a directory, the parent for its log named
// directly (DIR/frames.vlog), empty for any other file (a log copied out of its run, which no
// summary describes).
std::string run_dir_of(const std::string& run_path);

// The one rule for a frame's time (docs/frame-log.md, "Checked times"): finite, >= 0 and not
// before the previous frame's (`previous`, s; ignored for frame 0). Throws InputError naming the
// log `path` and frame i.
void check_frame_time(const std::string& path, std::size_t i, double t, double previous);
// The error for frame i of log `path` whose time t breaks that rule, saying `why`.
InputError bad_frame_time(const std::string& path, std::size_t i, double t, const char* why);

// Random access to a log's frames. Reads only the header on opening.
class FrameLogReader {
 public:
  // Throws InputError naming the file if it is missing, not a frame log, of an unknown version,
  // has a truncated header, or a channel whose value count does not match its layout (2 per node
  // for node vectors, 2 for a vector, at least 1 for scalars), so no reader of a record runs past
  // the values it was told are there.
  explicit FrameLogReader(const std::string& path);
  ~FrameLogReader();
  FrameLogReader(const FrameLogReader&) = delete;
  FrameLogReader& operator=(const FrameLogReader&) = delete;

  const FrameLogHeader& header() const { return header_; }
  const std::string& path() const { return path_; }
  // Complete frames in the file now; a growing log can be re-polled.
  std::size_t frame_count() const;
  // The path no longer names the file this reader opened: it was removed, or a new file took its
  // name (a run repeated with --force into the same directory), or the file was written over in
  // place with another header (another scene). The reader keeps its file open.
  bool replaced() const;
  // Reads frame i (time first, then channels in order) into `record`.
  void read(std::size_t i, std::vector<double>& record) const;
  double time_of(std::size_t i) const;
  // Reads `count` doubles at `offset` (in doubles, time at 0) inside frame i into `out`.
  void read_values(std::size_t i, std::size_t offset, std::size_t count, double* out) const;
  // Reads frames [first, first + count) back to back into `records` (count * record_doubles()):
  // one read for a streaming pass instead of one per frame.
  void read_frames(std::size_t first, std::size_t count, std::vector<double>& records) const;
  // The last frame whose time is <= t (0 if t precedes the first frame). Binary search: O(log n)
  // reads of one double each. Requires frame_count() > 0.
  std::size_t frame_at_time(double t) const;

 private:
  void read_header();  // into header_ and data_offset_; throws InputError

  std::string path_;
  FrameLogHeader header_;
  std::FILE* file_ = nullptr;
  std::uint64_t data_offset_ = 0;
  std::vector<char> header_bytes_;  // as read on opening, for replaced()
};

}  // namespace vascsim
