#!/usr/bin/env bash
# `cpack -G DEB` from the build's install rules: the packages' dependencies (dpkg-shlibdeps'
# shared libraries and the font) are installed on this machine, dpkg accepts both packages
# (--dry-run: every dependency satisfied, nothing installed), and the extracted tree runs
# `vascsim run` and `vascsim render` on a shipped scene from usr/share/vascsim/scenes.
#   deb_package_test.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
fail() { echo "deb_package_test: FAIL: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"

# cpack builds the whole tree before it packages it. On a tree whose sources changed since the
# last build (ctest run without building first) that rebuild, not the packaging, would fill the
# test's time limit: say so at once instead. A source newer than every program and library the
# build made has not been built.
newest=$(find "$build/sim" "$build/render" "$build/apps" -type f \( -name '*.a' -o -name '*.so*' -o -perm -u+x \) \
           -printf '%T@ %p\n' 2>/dev/null | sort -n | tail -1 | cut -d' ' -f2-)
[[ -n $newest ]] || fail "$build has no programs or libraries; build first (cmake --build $build)"
changed=$(find "$source/sim" "$source/render" "$source/apps" "$source/CMakeLists.txt" -newer "$newest" \
            \( -name '*.cpp' -o -name '*.h' -o -name 'CMakeLists.txt' \) -print -quit)
[[ -z $changed ]] || fail "$changed changed after the last build ($newest); build first (cmake --build $build)"

cpack --config "$build/CPackConfig.cmake" -B "$work" > "$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; fail "cpack"; }
version=$(sed -n 's/^set(CPACK_PACKAGE_VERSION "\(.*\)")/\1/p' "$build/CPackConfig.cmake")
runtime=$(ls "$work"/vascsim_"$version"_*.deb) dev=$(ls "$work"/vascsim-dev_"$version"_*.deb)

depends=$(dpkg-deb -f "$runtime" Depends)
echo "vascsim Depends: $depends"
for needed in libosmesa6 libavcodec libavformat libswscale libc6 libstdc++6 fonts-dejavu-core; do
  [[ $depends == *"$needed"* ]] || fail "the runtime package does not depend on $needed"
done
# Every dependency (the first of alternatives) is installed here at the version asked for.
IFS=',' read -ra items <<< "$depends,$(dpkg-deb -f "$dev" Depends)"
for item in "${items[@]}"; do
  item=${item%%|*}
  name=$(awk '{print $1}' <<< "$item")
  [[ $name == vascsim ]] && continue
  dpkg-query -W -f='${Status}' "$name" 2>/dev/null | grep -q "install ok installed" || fail "dependency $name is not installed"
done
dpkg --dry-run -i "$runtime" "$dev" > "$work/dry-run.log" 2>&1 || { cat "$work/dry-run.log"; fail "dpkg refuses the packages"; }

root=$work/root
dpkg-deb -x "$runtime" "$root"
dpkg-deb -x "$dev" "$root"
for f in usr/bin/vascsim usr/libexec/vascsim/vascsim-render usr/share/vascsim/scenes/bifurcation.json usr/share/man/man1/vascsim.1 \
         usr/share/bash-completion/completions/vascsim usr/lib/cmake/vascsim/vascsimConfig.cmake \
         usr/include/vascsim/sim/run/run.h; do
  [[ -e $root/$f ]] || fail "$f is not in the packages"
done
# An extracted tree has no /usr/lib of its own on the loader's path: shared builds find their
# libraries through the RUNPATH ($ORIGIN/../lib); static builds need none.
exe=$root/usr/bin/vascsim
"$exe" --version
"$exe" run "$root/usr/share/vascsim/scenes/bifurcation.json" --duration 0.5 --out "$work/run" --quiet
"$exe" render "$work/run" --mp4 "$work/run/video.mp4" --quiet | tee "$work/render.out"
grep -q "(16 frames," "$work/render.out" || fail "expected a 16-frame video of 0.5 s at 30 fps"
[[ -s $work/run/video.mp4 ]] || fail "no video"
echo "deb_package_test: ok"
