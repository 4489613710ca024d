#!/usr/bin/env bash
# Build ShadeLab and run the whole test suite with ctest: unit, GL through OSMesa, CLI, grading,
# the real window under Xvfb, the page in headless Chromium (label web; emscripten's build in
# build-web/), and the fuzz targets over their kept inputs plus 20 s of fresh fuzzing each (label
# fuzz; clang's build in build-fuzz/). Any arguments go to ctest, e.g.
#   ./test.sh -L unit
#   ./test.sh --sanitize        the same suite built with AddressSanitizer + UBSan, in build-asan/
set -euo pipefail
cd "$(dirname "$0")"
sanitize=false
if [ "${1:-}" = --sanitize ]; then
  sanitize=true
  shift
fi
tools/install_deps.sh test
export LIBGL_ALWAYS_SOFTWARE=1  # the same llvmpipe rasteriser everywhere, GPU or not

if $sanitize; then
  # Mesa (llvmpipe, OSMesa, EGL) is not instrumented; tools/lsan.supp names only its libraries.
  # Set before the build too: listing the GL tests opens a context.
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1:check_initialization_order=1
  export LSAN_OPTIONS=suppressions=$PWD/tools/lsan.supp:print_suppressions=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADELAB_SANITIZE=ON -DSHADELAB_BENCH=OFF >/dev/null
  cmake --build build-asan
  # The fuzz targets are sanitized already; their tests belong to the plain build's run.
  ctest --test-dir build-asan --output-on-failure -j2 -LE fuzz "$@"
  exit
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
tools/fuzz.sh --build
./web.sh --build  # the page, for the web tests (label web)
ctest --test-dir build --output-on-failure -j2 "$@"
