#!/usr/bin/env bash
# install_test.sh SOURCE_DIR BUILD_DIR
#
# Installs the build into a temporary prefix and uses it as a user would, with the build tree
# (and the source tree) gone: inside a private mount namespace both are covered by empty
# directories, so anything that still reads them fails. There, from another directory:
# glpt doctor, glpt run (a GL program under Xvfb, frames as PNG), glpt replay of a committed
# trace, glpt diff against the committed golden, the man pages, the bash completion, and a
# project of its own that does find_package(glpt) and glpt_add_golden_test.
# Needs root (or user namespaces) for unshare; exits 77 (skipped) without.
set -euo pipefail
src=$(cd "$1" && pwd) build=$(cd "$2" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/glpt-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in bin/glpt bin/glpt-replay lib/glpt/libGL.so.1 lib/glpt/libEGL.so.1 \
         share/man/man1/glpt.1 share/man/man1/glpt-run.1 share/man/man1/glpt-replay.1 \
         share/man/man1/glpt-doctor.1 share/bash-completion/completions/glpt \
         lib/cmake/glpt/glptConfig.cmake lib/cmake/glpt/GlptGolden.cmake; do
  [ -e "$prefix/$f" ] || { echo "install_test: $f was not installed" >&2; exit 1; }
done
# Nothing installed may point into the build tree (an RPATH, a shader path). Debug information
# names the compile directory by design (RelWithDebInfo, Debug): it is read by debuggers only,
# so ELF files are checked with their debug sections stripped. Sanitizer builds also keep the
# name of every instrumented source file outside the debug sections (ASan's global descriptors,
# UBSan's source locations): for the sources generated into the build tree those name it too,
# and like debug information they are only printed in reports, so names of source files
# (*.c, *.cpp, *.h, ...) are not counted.
names_build_tree() {
  local f=$1 copy=$work/stripped
  if [ "$(head -c4 "$f" | od -An -c | tr -d ' ')" = '177ELF' ]; then
    objcopy --strip-debug "$f" "$copy"
    local named
    named=$(strings -a "$copy" | grep -F -- "$build" | grep -Ev '\.(c|cc|cpp|cxx|h|hh|hpp|inc)$' || true)
    [ -n "$named" ]
  else
    grep -q -- "$build" "$f"
  fi
}
leaks=()
while IFS= read -r -d '' f; do
  names_build_tree "$f" && leaks+=("${f#"$prefix"/}")
done < <(find "$prefix" -type f -print0)
if [ ${#leaks[@]} -gt 0 ]; then
  echo "install_test: installed files name the build tree $build:" >&2
  printf '  %s\n' "${leaks[@]}" >&2
  exit 1
fi

# What the checks need from the trees, copied out before they disappear.
mkdir -p "$work/data"
cp "$src/tests/replay/data/gearsdet.trace" "$src/tests/golden/images/golden.gearsdet.raster/frame_000000.png" \
   "$src/tests/e2e/with_xvfb.sh" "$build/tests/programs/statetour" "$work/data/"
cp -r "$src/tests/install/consumer" "$work/consumer"

if ! unshare --mount true 2>/dev/null; then
  echo "install_test: cannot make a mount namespace (needs root): skipped" >&2
  exit 77
fi
export PREFIX=$prefix WORK=$work SRC=$src BUILD=$build
unshare --mount --propagation private bash -euo pipefail ${GLPT_INSTALL_TEST_TRACE:+-x} -c '
  mount -t tmpfs none "$BUILD"
  mount -t tmpfs none "$SRC"
  if [ -e "$BUILD/replay/glpt" ] || [ -e "$SRC/CMakeLists.txt" ]; then
    echo "install_test: the trees are still visible" >&2; exit 1
  fi
  cd "$WORK"
  export PATH=$PREFIX/bin:$PATH
  unset GLPT_VK_NO_RAY_QUERY GLPT_VK_DEVICE GLPT_OUTPUT
  export GLPT_QUIET=1

  glpt doctor >doctor.txt || { cat doctor.txt >&2; echo "install_test: glpt doctor failed" >&2; exit 1; }
  grep -q "^ok    glpt.s libGL.so.1   $PREFIX/lib/glpt/libGL.so.1" doctor.txt ||
    { cat doctor.txt >&2; echo "install_test: doctor did not find the installed library" >&2; exit 1; }

  glpt replay data/gearsdet.trace --quiet --mode raster --frames 0 --out replayed >replay.log 2>&1 ||
    { cat replay.log >&2; echo "install_test: glpt replay failed" >&2; exit 1; }
  glpt diff data/frame_000000.png replayed/frame_000000.png --threshold 0.01 >diff.txt ||
    { cat diff.txt >&2; echo "install_test: glpt diff failed" >&2; exit 1; }

  GLPT_OUTPUT=$WORK/run data/with_xvfb.sh glpt run --mode raster -- data/statetour --frames 2 \
    >run.log 2>&1 || { cat run.log >&2; echo "install_test: glpt run failed" >&2; exit 1; }
  [ -s run/frame_000000.png ] || { cat run.log >&2; echo "install_test: glpt run wrote no frame" >&2; exit 1; }

  MANPATH=$PREFIX/share/man man -w glpt-doctor | grep -q "$PREFIX" ||
    { echo "install_test: man glpt-doctor not found" >&2; exit 1; }

  # The completion, as bash-completion loads it, completing "glpt do" and "glpt run --sp".
  if [ -f /usr/share/bash-completion/bash_completion ]; then
    out=$(bash -c ". /usr/share/bash-completion/bash_completion
      . $PREFIX/share/bash-completion/completions/glpt
      COMP_WORDS=(glpt do); COMP_CWORD=1; COMP_LINE=\"glpt do\"; COMP_POINT=\${#COMP_LINE}
      _glpt glpt do glpt; echo \"\${COMPREPLY[*]}\"
      COMP_WORDS=(glpt run --sp); COMP_CWORD=2; COMP_LINE=\"glpt run --sp\"; COMP_POINT=\${#COMP_LINE}
      _glpt glpt --sp run; echo \"\${COMPREPLY[*]}\"")
    [ "$out" = "$(printf "doctor\n--spp")" ] ||
      { echo "install_test: completion gave [$out]" >&2; exit 1; }
  fi

  cmake -S consumer -B consumer-build -DCMAKE_PREFIX_PATH="$PREFIX" \
        -DCONSUMER_TRACE="$WORK/data/gearsdet.trace" -DGLPT_GOLDEN_DIR="$WORK/goldens" >cmake.log ||
    { cat cmake.log >&2; echo "install_test: find_package(glpt) failed" >&2; exit 1; }
  GLPT_UPDATE_GOLDENS=1 ctest --test-dir consumer-build --output-on-failure >ctest.log ||
    { cat ctest.log >&2; exit 1; }
  ctest --test-dir consumer-build --output-on-failure >ctest.log || { cat ctest.log >&2; exit 1; }
  # and it can fail: a different golden
  cp run/frame_000000.png goldens/consumer.gears/frame_000000.png
  if ctest --test-dir consumer-build >ctest.log 2>&1; then
    echo "install_test: a wrong golden passed" >&2; exit 1
  fi
'
echo "install_test: installed glpt works without its build and source trees"
