#!/usr/bin/env bash
# Build ShadeLab and run the whole test suite (unit, GL through OSMesa, CLI, and the real window
# under Xvfb) with ctest. Any arguments go to ctest, e.g. ./test.sh -L unit
set -euo pipefail
cd "$(dirname "$0")"
tools/install_deps.sh test
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
export LIBGL_ALWAYS_SOFTWARE=1  # the same llvmpipe rasteriser everywhere, GPU or not
ctest --test-dir build --output-on-failure -j2 "$@"
