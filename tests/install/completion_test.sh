#!/usr/bin/env bash
# The bash completion (apps/vascsim/vascsim.bash-completion) against the built program: commands,
# options of a command and of a benchmark, an option's listed choices, files for values.
#   completion_test.sh COMPLETION_FILE VASCSIM WORK_DIR
set -uo pipefail
completion=$1 exe=$2 work=$3
rm -rf "$work" && mkdir -p "$work/scenes" && touch "$work/scenes/a.json" "$work/scenes/b.json"
cd "$work"
# shellcheck disable=SC1090
source "$completion"
failed=0
# complete WORDS... : the candidates for the last word
complete_words() {
  COMP_WORDS=("$exe" "$@")
  COMP_CWORD=$#
  COMPREPLY=()
  _vascsim
  printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' ' | sed 's/ $//'
}
expect() {  # expect "CANDIDATES" WORDS...
  local wanted=$1; shift
  local got; got=$(complete_words "$@")
  if [[ $got != "$wanted" ]]; then
    echo "FAIL: vascsim $* <TAB>: expected '$wanted', got '$got'"
    failed=1
  fi
}
expect "render replay run" r
expect "sweep" help sw
expect "--max-log-size" run --max
expect "--mp4" render RUN --mp
expect "center fit follow" render RUN --camera ""
expect "analytic" render RUN --aa an
expect "speed sweep" bench s
expect "--max-nodes" bench speed --max-n
expect "scenes/a.json scenes/b.json" run scenes/
expect "scenes/a.json" run scenes/b.json --out x --force scenes/a
[[ $failed == 0 ]] && echo "completion_test: ok"
exit $failed
