"""Reads vascsim frame logs (frames.vlog, format version 1; docs/frame-log.md) into numpy arrays.

One file, numpy only. The records are memory-mapped, not read: opening a log of any size costs
its header, and an array touches only the frames you index. A run still being written can be
reopened to see its new frames; a torn last record is ignored, as the C++ reader does.

    import vascsim_log
    log = vascsim_log.open_log("out/maze_default")          # a run directory or a .vlog file
    print(log.metadata["title"], log.frame_count, [c.name for c in log.channels])
    tip = log.channel("position")[:, -1, :]                   # (frames, 2) in m
    error = log.channel("tip/error")                          # (frames,) in m
    print(vascsim_log.run_state("out/maze_default"))         # "finished", "writing", "killed", ...
"""

import json
import os
import struct

import numpy as np

MAGIC = b"VSIMLOG\0"
VERSION = 1
LAYOUTS = {0: "scalars", 1: "node_vectors", 2: "vector"}


class Channel:
    """A named block of float64 values in every frame: layout, unit (SI) and where it lies."""

    def __init__(self, name, unit, layout, count, offset):
        self.name, self.unit, self.layout, self.count, self.offset = name, unit, layout, count, offset

    def __repr__(self):
        return "Channel(%r, unit=%r, layout=%r, count=%d)" % (self.name, self.unit, self.layout, self.count)


class FrameLog:
    """A frame log: node_count, channels, metadata (the JSON dict), times and channel arrays."""

    def __init__(self, path):
        self.path = path
        with open(path, "rb") as f:
            head = f.read(20)
            if len(head) < 20 or head[:8] != MAGIC:
                raise ValueError("%s: not a vascsim frame log (no VSIMLOG magic)" % path)
            version, self.node_count, count = struct.unpack("<III", head[8:20])
            if version != VERSION:
                newer = version > VERSION
                raise ValueError("%s: frame log format version %d%s; this reader reads version %d%s"
                                 % (path, version, ", written by a newer vascsim" if newer else "", VERSION,
                                    " (update vascsim_log.py to read it)" if newer else ""))
            if count > 4096:
                raise ValueError("%s: %d channels claimed (at most 4096)" % (path, count))
            self.channels, offset = [], 1  # the time is value 0 of a record
            for _ in range(count):
                name, unit = self._text(f), self._text(f)
                layout_code, values = struct.unpack("<BI", self._exact(f, 5))
                if layout_code not in LAYOUTS:
                    raise ValueError("%s: channel %r has unknown layout %d" % (path, name, layout_code))
                expected = {0: max(values, 1), 1: 2 * self.node_count, 2: 2}[layout_code]
                if values != expected:
                    raise ValueError("%s: channel %r holds %d values per frame, expected %d"
                                     % (path, name, values, expected))
                self.channels.append(Channel(name, unit, LAYOUTS[layout_code], values, offset))
                offset += values
            (length,) = struct.unpack("<I", self._exact(f, 4))
            if length > 32 << 20:
                raise ValueError("%s: metadata of %d bytes claimed (at most 32 MB)" % (path, length))
            try:
                text = self._exact(f, length).decode("utf-8")
                self.metadata = json.loads(text) if text else {}
            except (UnicodeDecodeError, json.JSONDecodeError) as e:
                raise ValueError("%s: corrupt metadata (%s)" % (path, e)) from e
            self.data_offset = (f.tell() + 7) // 8 * 8
        self.record_doubles = offset
        self._records = None
        self._times_checked = 0
        self.refresh()

    def _exact(self, f, n):
        data = f.read(n)
        if len(data) != n:
            raise ValueError("%s: truncated header" % self.path)
        return data

    def _text(self, f):
        (n,) = struct.unpack("<I", self._exact(f, 4))
        if n > 1024:
            raise ValueError("%s: a channel name or unit of %d bytes (at most 1024)" % (self.path, n))
        try:
            return self._exact(f, n).decode("utf-8")
        except UnicodeDecodeError as e:
            raise ValueError("%s: a channel name or unit that is not UTF-8 (%s)" % (self.path, e)) from e

    def refresh(self):
        """Maps the complete records in the file now (a growing log gains frames)."""
        size = os.path.getsize(self.path)
        self.frame_count = max(0, (size - self.data_offset) // (8 * self.record_doubles))
        if self.frame_count == 0:
            self._records = np.zeros((0, self.record_doubles))
        else:
            self._records = np.memmap(self.path, dtype="<f8", mode="r", offset=self.data_offset,
                                      shape=(self.frame_count, self.record_doubles))

    @property
    def times(self):
        """Frame times in s, shape (frames,). Raises ValueError, naming the frame, where a time is
        not finite, negative or before the previous frame's, as the C++ reader refuses them (a
        corrupt log would otherwise plot and interpolate silently wrong)."""
        t = self._records[:, 0]
        # Each frame is checked once (a growing log's new frames on the next call), so that
        # indexing times in a loop stays cheap.
        start = max(0, self._times_checked - 1)
        if self.frame_count > self._times_checked:
            part = t[start:]
            bad = ~(np.isfinite(part) & (part >= 0))
            bad[1:] |= ~(part[1:] >= part[:-1])
            if bad.any():
                i = start + int(np.argmax(bad))
                why = "not a finite time >= 0" if not (np.isfinite(t[i]) and t[i] >= 0) else "before the previous frame's time"
                raise ValueError("%s: frame %d has time %r s, %s (times must be finite, >= 0 and non-decreasing)"
                                 % (self.path, i, float(t[i]), why))
            self._times_checked = self.frame_count
        return t

    def channel_info(self, name):
        for c in self.channels:
            if c.name == name:
                return c
        raise KeyError("%s: no channel %r (the log has %s)" % (self.path, name, ", ".join(c.name for c in self.channels)))

    def channel(self, name):
        """The channel's values for every frame: (frames, nodes, 2) for node vectors, (frames, 2) for
        a vector, (frames,) for one scalar, (frames, count) for several. A view of the map."""
        c = self.channel_info(name)
        block = self._records[:, c.offset:c.offset + c.count]
        if c.layout == "node_vectors":
            return block.reshape(self.frame_count, c.count // 2, 2)
        if c.layout == "scalars" and c.count == 1:
            return block[:, 0]
        return block


def open_log(path):
    """Opens a run directory (its frames.vlog) or a frame log file."""
    if os.path.isdir(path):
        path = os.path.join(path, "frames.vlog")
    return FrameLog(path)


# The claim `vascsim run` holds on its directory while it writes (sim/io/output_file.h): an open
# file description lock on this hidden file, left behind unheld by a run killed with kill -9.
CLAIM_FILE = ".vascsim-run.lock"
# struct flock on Linux (x86-64, arm64): l_type, l_whence, l_start, l_len, l_pid, padding.
_FLOCK = "hhqqi4x"


def _claim_holder(run_dir):
    """"run" (a run holds the claim), "none" (no claim file), "abandoned" (no one holds it) or
    "unknown" (the lock cannot be asked about), asking without taking it, as the C++ readers do."""
    try:
        import fcntl  # here, not above: the rest of this module also reads logs copied to Windows
    except ImportError:
        return "unknown"
    try:
        fd = os.open(os.path.join(run_dir, CLAIM_FILE), os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
    except FileNotFoundError:
        return "none"
    except OSError:
        return "unknown"
    try:
        probe = struct.pack(_FLOCK, fcntl.F_WRLCK, os.SEEK_SET, 0, 0, 0)
        l_type = struct.unpack(_FLOCK, fcntl.fcntl(fd, fcntl.F_OFD_GETLK, probe))[0]
    except (OSError, AttributeError):  # no OFD locks here (not Linux, Python before 3.9)
        return "unknown"
    finally:
        os.close(fd)
    return "abandoned" if l_type == fcntl.F_UNLCK else "run"


def run_state(path):
    """How the run of a run directory (or of its frames.vlog) stands, as `vascsim render`, `export`
    and `replay` tell it (docs/frame-log.md, "Finished or not"):
      "finished"  summary.json says it reached its end (/ok true);
      "failed"    summary.json says the simulation failed (/ok false; /failure says how);
      "stopped"   summary.json says a signal stopped it (/stopped_by: Ctrl-C, kill, a time limit);
      "writing"   no summary yet: a `vascsim run` is still writing it, so its log will grow;
      "killed"    no summary, and the run left its claim with no run holding it (kill -9, a crash,
                  out of memory): its log ends with the last frame it wrote;
      "unknown"   no summary and no claim (a directory copied without it), a summary that cannot
                  be read, or a file system that cannot say.
    A log named directly under another name than frames.vlog has no run: "unknown"."""
    if not os.path.exists(path):
        raise FileNotFoundError("%s: no such run directory or frame log" % path)
    if os.path.isdir(path):
        run_dir = path
    elif os.path.basename(path) == "frames.vlog":
        run_dir = os.path.dirname(path) or "."
    else:
        return "unknown"
    summary_path = os.path.join(run_dir, "summary.json")
    if os.path.exists(summary_path):
        try:
            with open(summary_path, "rb") as f:
                summary = json.loads(f.read().decode("utf-8"))
        except (OSError, ValueError):
            return "unknown"
        if not isinstance(summary, dict) or not isinstance(summary.get("ok"), bool):
            return "unknown"
        if summary["ok"]:
            return "finished"
        stopped_by = summary.get("stopped_by")
        return "stopped" if isinstance(stopped_by, str) and stopped_by else "failed"
    return {"run": "writing", "abandoned": "killed"}.get(_claim_holder(run_dir), "unknown")
