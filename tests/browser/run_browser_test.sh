#!/usr/bin/env bash
# The replay page's browser test as ctest runs it: simulates three shipped scenes into WORK_DIR
# (a run to replay, a second one to compare with, a third in another vessel to overlay), then
# drives the page in headless Chromium (tests/browser/replay_browser_test.py). Screenshots of
# every mode land in WORK_DIR/screenshots.
# usage: run_browser_test.sh VASCSIM_EXE MP4_PROBE_EXE SOURCE_DIR WORK_DIR
set -euo pipefail
vascsim=$1 probe=$2 src=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
"$vascsim" run "$src/scenes/maze_default.json" --out "$work/a" --quiet >/dev/null
"$vascsim" run "$src/scenes/maze_body_drag.json" --out "$work/b" --quiet >/dev/null
"$vascsim" run "$src/scenes/bifurcation.json" --out "$work/c" --duration 1 --quiet >/dev/null
exec python3 "$src/tests/browser/replay_browser_test.py" --vascsim "$vascsim" --run "$work/a" --run-b "$work/b" \
  --run-c "$work/c" \
  --probe "$probe" --screenshots "$work/screenshots"
