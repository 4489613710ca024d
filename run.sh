#!/usr/bin/env bash
# Build ShadeLab (Release, into build/) and open the app on its default lab and scene.
# With no display it says so and renders the default lab headless into out/ instead.
# Any arguments are passed to the app, e.g. ./run.sh --lab shading --shaders my_shaders/
set -euo pipefail
cd "$(dirname "$0")"
tools/install_deps.sh build
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target shadelab
exec build/shadelab "$@"
