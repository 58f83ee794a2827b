#!/usr/bin/env bash
# The generated man page (apps/vascsim/make_manpage.cmake): groff reads it without a warning,
# and the page shows every command's section with each option its --help lists, copyable (an
# ASCII "--", not a typographic dash).
#   manpage_test.sh MANPAGE VASCSIM
set -euo pipefail
page=$1 exe=$2
fail() { echo "manpage_test: FAIL: $*" >&2; exit 1; }
warnings=$(groff -man -Tascii -ww -z "$page" 2>&1)
[[ -z $warnings ]] || fail "groff warns: $warnings"
text=$(groff -man -Tascii "$page" 2>/dev/null | col -b)
commands=$("$exe" --help | sed -n '/^commands:/,$ s/^  \([a-z][a-z0-9-]*\) .*/\1/p')
[[ -n $commands ]] || fail "no commands in vascsim --help"
for command in $commands; do
  grep -q "^   vascsim $command\$" <<< "$text" || fail "no section for vascsim $command"
  for option in $("$exe" help "$command" | sed -n 's/^  \(--[a-z][a-z0-9-]*\).*/\1/p'); do
    grep -q -- "$option" <<< "$text" || fail "option $option of vascsim $command is missing"
  done
done
# A line with | and -- as the help has it (the renderer's; a build without it has no render command).
if grep -qx render <<< "$commands"; then
  grep -q -- "--camera fit|follow|center" <<< "$text" || fail "render's --camera line is not shown as written"
fi
echo "manpage_test: ok"
