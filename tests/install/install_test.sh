#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then the embedding example (examples/embed/) built
# against the installed package with find_package(vascsim 0.2) and run: its log must be the
# bytes `vascsim run` (installed) writes for the same scene, and its still the PNG bytes
# `vascsim render --still` writes. Also: the package's version rule, the installed header set
# (closed under its own includes, none of the private ones), the soname of shared libraries.
#   install_test.sh BUILD_DIR SOURCE_DIR WORK_DIR CXX_COMPILER SANITIZE RENDER SHARED
set -euo pipefail
build=$1 source=$2 work=$3 cxx=$4 sanitize=$5 render=$6 shared=$7
fail() { echo "install_test: FAIL: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
for f in bin/vascsim lib/cmake/vascsim/vascsimConfig.cmake lib/cmake/vascsim/vascsimConfigVersion.cmake \
         include/vascsim/sim/run/run.h include/vascsim/sim/io/scene_reader.h include/vascsim/sim/log/frame_log.h \
         share/vascsim/scenes/maze_default.json share/vascsim/assets/vessel_phantom.png share/vascsim/docs/install.md \
         share/vascsim/python/vascsim_log.py share/vascsim/examples/embed/embed.cpp share/man/man1/vascsim.1 \
         share/bash-completion/completions/vascsim; do
  [[ -e $prefix/$f ]] || fail "$f not installed"
done
if [[ $render == ON ]]; then
  [[ -e $prefix/include/vascsim/render/render_run.h ]] || fail "render headers not installed"
  [[ -x $prefix/libexec/vascsim/vascsim-render ]] || fail "libexec/vascsim/vascsim-render (the program that draws) not installed"
fi

# Headers: every quoted include of an installed header is installed too, and the private ones
# (JSON parsing, the command line, the replay server) are not.
cd "$prefix/include/vascsim"
while read -r header included; do
  [[ -f $included ]] || fail "$header includes $included, which is not installed"
done < <(grep -rHo '^#include "[^"]*"' . | sed 's|^\./||; s|:#include "| |; s|"$||')
for private in sim/io/json_fields.h apps sim/io/scene_sections.h; do
  [[ ! -e $private ]] || fail "$private is installed but is not part of the API"
done
! grep -rq nlohmann . || fail "an installed header includes nlohmann-json, a private dependency"
cd - > /dev/null

if [[ $shared == ON ]]; then
  soname=$(readelf -d "$prefix/lib/libvascsim_sim.so" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
  [[ $soname == libvascsim_sim.so.0.2 ]] || fail "soname of libvascsim_sim.so is '$soname', expected libvascsim_sim.so.0.2"
  [[ -f $prefix/lib/libvascsim_sim.so.0.2.0 ]] || fail "libvascsim_sim.so.0.2.0 not installed"
fi

flags=()
if [[ $sanitize == ON ]]; then
  flags=(-DCMAKE_CXX_FLAGS="-fsanitize=address,undefined" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined")
fi
# The version rule: 0.2 is found, 0.3 and 0.1 are not (0.x minors may break the API).
for wanted in 0.3 0.1; do
  mkdir -p "$work/version-$wanted"
  printf 'cmake_minimum_required(VERSION 3.20)\nproject(v LANGUAGES CXX)\nfind_package(vascsim %s REQUIRED)\n' "$wanted" \
    > "$work/version-$wanted/CMakeLists.txt"
  if cmake -S "$work/version-$wanted" -B "$work/version-$wanted/build" -DCMAKE_PREFIX_PATH="$prefix" \
       > "$work/version-$wanted/log" 2>&1; then
    fail "find_package(vascsim $wanted) accepted version 0.2.0"
  fi
  grep -q "0.2.0" "$work/version-$wanted/log" || fail "find_package(vascsim $wanted) failed without naming the version found"
done

cmake -S "$source/examples/embed" -B "$work/embed" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_BUILD_TYPE=Release "${flags[@]}" > "$work/embed-configure.log" || { cat "$work/embed-configure.log"; fail "configure"; }
cmake --build "$work/embed" -j2 > "$work/embed-build.log" 2>&1 || { cat "$work/embed-build.log"; fail "build"; }

scene=$prefix/share/vascsim/scenes/bifurcation.json
"$work/embed/embed" "$scene" "$work/embedded" 0.5 | tee "$work/embed.out"
"$prefix/bin/vascsim" run "$scene" --duration 0.5 --out "$work/cli" --quiet > /dev/null
cmp "$work/embedded/frames.vlog" "$work/cli/frames.vlog" || fail "the embedded run's log differs from vascsim run's"
if [[ $render == ON ]]; then
  t=$(sed -n 's/^tip at t = \([0-9.]*\) s.*/\1/p' "$work/embed.out")
  "$prefix/bin/vascsim" render "$work/cli" --still "$t" --png "$work/cli/still.png" > /dev/null
  cmp "$work/embedded/still.png" "$work/cli/still.png" || fail "the embedded still differs from vascsim render --still"
fi
echo "install_test: ok"
