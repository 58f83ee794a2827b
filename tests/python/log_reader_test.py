"""The Python frame-log reader (python/vascsim_log.py) against the C++ reader on a real run: every
channel of every frame, as `vascsim export --csv` (the C++ FrameLogReader) writes them with 17
significant digits, must equal the memory-mapped arrays exactly. Also: a run directory or file
opens, a torn last record is ignored, another format version, a wrong channel count and frame
times that are not finite or go back are refused; and run_state() says how a run stands as the C++
readers' warnings do (finished, failed, stopped, still writing, killed).
Usage: log_reader_test.py VASCSIM_EXE SOURCE_DIR WORK_DIR"""
import csv
import fcntl
import json
import os
import shutil
import struct
import subprocess
import sys
import time

import numpy as np

exe, source, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(source, "python"))
import vascsim_log  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
run = os.path.join(work, "run")
subprocess.run([exe, "run", os.path.join(source, "scenes", "bifurcation.json"), "--out", run, "--duration", "2",
                "--quiet"], check=True)
csv_dir = os.path.join(work, "csv")
os.makedirs(csv_dir)
subprocess.run([exe, "export", run, "--csv", csv_dir], check=True, stdout=subprocess.DEVNULL)

log = vascsim_log.open_log(run)
assert log.frame_count == 101, log.frame_count
assert log.metadata["title"] == "bifurcation"
assert log.metadata["lumen"], "the metadata carries the lumen outline"
failures = []
for c in log.channels:
    with open(os.path.join(csv_dir, c.name.replace("/", "_") + ".csv")) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], np.array(rows[1:], dtype=float)
    assert header[0] == "time [s]" and header[-1].endswith("[%s]" % c.unit), (c.name, header)
    values = log.channel(c.name)
    if c.layout == "node_vectors":
        expected_time = np.repeat(log.times, log.node_count)
        got = values.reshape(-1, 2)
        ok = np.array_equal(body[:, 0], expected_time) and np.array_equal(body[:, 2:4], got) and \
            np.array_equal(body[:, 1], np.tile(np.arange(log.node_count), log.frame_count))
        assert values.shape == (log.frame_count, log.node_count, 2)
    elif c.layout == "vector":
        ok = np.array_equal(body[:, 0], log.times) and np.array_equal(body[:, 1:3], values)
    else:
        ok = np.array_equal(body[:, 0], log.times) and np.array_equal(body[:, -1], np.asarray(values).reshape(-1))
    if not ok:
        failures.append(c.name)
assert not failures, "channels differ from the C++ reader: %s" % failures

# A torn last record (a run killed mid-write) is not a frame.
torn = os.path.join(work, "torn.vlog")
with open(os.path.join(run, "frames.vlog"), "rb") as f:
    data = f.read()
with open(torn, "wb") as f:
    f.write(data[:-100])
assert vascsim_log.open_log(torn).frame_count == log.frame_count - 1

# A frame whose time goes back, or is not finite, is refused by frame, as the C++ reader does.
record_bytes = 8 * log.record_doubles
for frame, value, why in ((3, 0.01, "before the previous frame's time"), (5, float("nan"), "not a finite time >= 0")):
    broken = os.path.join(work, "time_%d.vlog" % frame)
    at = log.data_offset + frame * record_bytes
    with open(broken, "wb") as f:
        f.write(data[:at] + np.float64(value).tobytes() + data[at + 8:])
    try:
        vascsim_log.open_log(broken).times
        raise AssertionError("a log whose frame %d has time %r was read" % (frame, value))
    except ValueError as e:
        assert "time_%d.vlog: frame %d has time" % (frame, frame) in str(e) and why in str(e), e
    export = subprocess.run([exe, "export", broken, "--csv", csv_dir, "--force"], capture_output=True, text=True)
    assert export.returncode == 2 and "frame %d has time" % frame in export.stderr, export

# Another version is refused by name.
other = os.path.join(work, "v2.vlog")
with open(other, "wb") as f:
    f.write(data[:8] + (2).to_bytes(4, "little") + data[12:])
try:
    vascsim_log.open_log(other)
    raise AssertionError("a version 2 log was read")
except ValueError as e:
    assert "format version 2, written by a newer vascsim; this reader reads version 1" in str(e), e
# A channel whose value count does not match its layout (the first channel, position: 2 per
# node) is refused by name, by this reader and by the C++ one behind `vascsim export`.
name_length = int.from_bytes(data[20:24], "little")
unit_at = 24 + name_length
count_at = unit_at + 4 + int.from_bytes(data[unit_at:unit_at + 4], "little") + 1
assert int.from_bytes(data[count_at:count_at + 4], "little") == 2 * log.node_count
bad_count = os.path.join(work, "bad_count.vlog")
with open(bad_count, "wb") as f:
    f.write(data[:count_at] + (2 * log.node_count - 1).to_bytes(4, "little") + data[count_at + 4:])
try:
    vascsim_log.open_log(bad_count)
    raise AssertionError("a log with a wrong channel count was read")
except ValueError as e:
    assert "bad_count.vlog: channel 'position' holds %d values per frame, expected %d" % (
        2 * log.node_count - 1, 2 * log.node_count) in str(e), e
export = subprocess.run([exe, "export", bad_count, "--csv", csv_dir, "--force"], capture_output=True, text=True)
assert export.returncode == 2 and "bad_count.vlog: channel 'position' holds" in export.stderr, export

# How a run stands (run_state), each state beside the C++ readers' warning for the same directory;
# a lock this test holds must read as a run writing to both, so both ask about the same lock.
assert vascsim_log.run_state(run) == "finished"
assert vascsim_log.run_state(os.path.join(run, "frames.vlog")) == "finished"
assert vascsim_log.run_state(torn) == "unknown", "a log copied out of its run has no run"
state = os.path.join(work, "state")
shutil.copytree(run, state)
summary_path = os.path.join(state, "summary.json")
with open(summary_path) as f:
    finished = json.load(f)


def cxx_warning():
    export = subprocess.run([exe, "export", state, "--csv", csv_dir, "--force"], capture_output=True, text=True)
    assert export.returncode == 0, export
    return export.stderr


for changes, expected, warned in (({"ok": False, "failure": "Newton did not converge"}, "failed", "the run failed"),
                                  ({"ok": False, "failure": "stopped by SIGTERM", "stopped_by": "SIGTERM"}, "stopped",
                                   "the run was stopped before its end")):
    with open(summary_path, "w") as f:
        json.dump(dict(finished, **changes), f)
    assert vascsim_log.run_state(state) == expected, (changes, vascsim_log.run_state(state))
    assert warned in cxx_warning()
os.remove(summary_path)
assert vascsim_log.run_state(state) == "unknown"
assert "no run is writing it (the directory was copied without it" in cxx_warning()
claim = os.path.join(state, vascsim_log.CLAIM_FILE)
open(claim, "w").close()
assert vascsim_log.run_state(state) == "killed"
assert "its run was killed before its end" in cxx_warning()
fd = os.open(claim, os.O_RDWR)
fcntl.fcntl(fd, fcntl.F_OFD_SETLK, struct.pack("hhqqi4x", fcntl.F_WRLCK, os.SEEK_SET, 0, 0, 0))
assert vascsim_log.run_state(state) == "writing"
assert "a run is still writing it" in cxx_warning()
os.close(fd)
# A real run: writing while it runs (fixed 10 us steps: it outlasts the test), killed by kill -9.
long_scene = os.path.join(work, "long.json")
with open(long_scene, "w") as f:
    json.dump({"maze": None, "rod": {"nodes": 40}, "solver": {"dt": 1e-5}, "run": {"duration": 1000, "output_interval": 0.01}}, f)
live = os.path.join(work, "live")
proc = subprocess.Popen([exe, "run", long_scene, "--out", live, "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
try:
    deadline = time.time() + 30
    while time.time() < deadline and not os.path.exists(os.path.join(live, "frames.vlog")):
        time.sleep(0.02)
    assert vascsim_log.run_state(live) == "writing", vascsim_log.run_state(live)
finally:
    proc.kill()
    proc.wait()
assert vascsim_log.run_state(live) == "killed", vascsim_log.run_state(live)
try:
    vascsim_log.run_state(os.path.join(work, "no_such_run"))
    raise AssertionError("a path that does not exist has a state")
except FileNotFoundError as e:
    assert "no_such_run: no such run directory or frame log" in str(e), e

print("python reader agrees with the C++ reader on %d channels x %d frames" % (len(log.channels), log.frame_count))
