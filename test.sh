#!/usr/bin/env bash
# Build ShadeLab and run the test suite with ctest: unit, GL through OSMesa, CLI, grading, the real
# window under Xvfb (label app), the page in headless Chromium (label web; emscripten's build in
# build-web/), and the fuzz targets over their kept inputs plus 20 s of fresh fuzzing each (label
# fuzz; clang's build in build-fuzz/). Any arguments go to ctest. Only the trees the chosen labels
# need are built: no -L runs (and builds) everything, as CI does.
#   ./test.sh -L unit           the native tree only
#   ./test.sh -L 'grade|web'    the native tree and the page
#   ./test.sh --sanitize        the suite built with AddressSanitizer + UBSan, in build-asan/ (the
#                               fuzz and page labels left out: their trees are clang's and emscripten's)
# At the end: how long each tree took to build and each label's test time.
set -euo pipefail
cd "$(dirname "$0")"
sanitize=false
if [ "${1:-}" = --sanitize ]; then
  sanitize=true
  shift
fi

# The labels asked for: -L/--label-regex picks, -LE/--label-exclude leaves out (ctest's regexes).
include='' exclude=''
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  case "${args[i]}" in
    -L | --label-regex) include=${args[i + 1]:-} ;;
    -LE | --label-exclude) exclude=${args[i + 1]:-} ;;
  esac
done
# Whether tests labelled $1 run: picked (or nothing picked) and not left out.
runs_label() {
  if [ -n "$include" ] && ! [[ $1 =~ $include ]]; then return 1; fi
  if [ -n "$exclude" ] && [[ $1 =~ $exclude ]]; then return 1; fi
  return 0
}

tools/install_deps.sh test
export LIBGL_ALWAYS_SOFTWARE=1  # the same llvmpipe rasteriser everywhere, GPU or not

times=()
timed() {  # timed NAME COMMAND...: runs it and keeps its wall time for the summary
  local name=$1 start=$SECONDS rc=0
  shift
  "$@" || rc=$?
  times+=("$name $((SECONDS - start)) s")
  return $rc
}
summary() {  # after ctest's own "Label Time Summary" (each label's summed test time)
  local joined
  joined=$(printf '%s, ' "${times[@]}")
  echo "wall time: ${joined%, }"
}

if $sanitize; then
  # Mesa (llvmpipe, OSMesa, EGL) is not instrumented; tools/lsan.supp names only its libraries.
  # Set before the build too: listing the GL tests opens a context.
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1:check_initialization_order=1
  export LSAN_OPTIONS=suppressions=$PWD/tools/lsan.supp:print_suppressions=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # -O1 and -g1 (line tables): what the sanitizers' reports need, at a fraction of -O2 -g's build.
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DSHADELAB_SANITIZE=ON -DSHADELAB_BENCH=OFF >/dev/null
  timed "build-asan" cmake --build build-asan
  # The fuzz targets are sanitized already, in clang's tree; the page is emscripten's code, not
  # this build's: both belong to the plain run.
  status=0
  timed "tests" ctest --test-dir build-asan --output-on-failure -j2 -LE 'fuzz|web' "$@" || status=$?
  summary
  exit $status
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
timed "build" cmake --build build
if runs_label fuzz; then timed "build-fuzz" tools/fuzz.sh --build; fi
if runs_label web; then timed "build-web" ./web.sh --build; fi
status=0
timed "tests" ctest --test-dir build --output-on-failure -j2 "$@" || status=$?
summary
exit $status
