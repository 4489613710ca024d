#!/usr/bin/env bash
# ShadeLab in the browser: the same sources built by Debian's emscripten into build-web/.
#   ./web.sh              build, then serve on http://127.0.0.1:8080/ (with the headers threads need)
#   ./web.sh --port N     the same on port N
#   ./web.sh --out DIR    build, then write the static site to DIR for any web host (no server started)
#   ./web.sh --build      build only
#   ./web.sh --exercises DIR   (with any of the above) a course folder in the site, listed before the
#                         built-in exercises; without it, none
# Installs what is missing from Debian's packages (tools/install_deps.sh web) and fetches the sources
# Debian ships compiled for the desktop only (Dear ImGui; LZ4, which FLANN calls) through Debian's
# source packages into build-web/src, never into the repository.
set -euo pipefail
caller=$PWD  # where relative paths given on the command line start
cd "$(dirname "$0")"
mode=serve port=8080 out="" course=""
while [ $# -gt 0 ]; do
  case "$1" in
    --out) mode=out; out=${2:?--out needs a folder}; shift ;;
    --port) port=${2:?--port needs a number}; shift ;;
    --build) mode=build ;;
    --exercises) course=$(cd "$caller" && realpath -m "${2:?--exercises needs a course folder}"); shift
      [ -d "$course" ] || { echo "web.sh: --exercises: '$course' is not a folder" >&2; exit 2; } ;;
    -h|--help) sed -n "2,10p" "$0"; exit 0 ;;
    *) echo "web.sh: unknown argument '$1' (valid: --out DIR, --port N, --build, --exercises DIR)" >&2; exit 2 ;;
  esac
  shift
done

tools/install_deps.sh web
build=build-web
src=$build/src
fetch_source() {  # fetch_source PACKAGE FOLDER FILE: Debian's source of PACKAGE in $src/FOLDER, unless FILE is there
  [ -f "$src/$2/$3" ] && return 0
  if [ ! -f "$src/apt/sources.list" ]; then
    # A private apt configuration with a deb-src line for the machine's own mirror: /etc is untouched.
    mkdir -p "$src/apt/lists/partial"
    mirror=$(awk '/^URIs:/ {print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null || true)
    [ -n "$mirror" ] || mirror=$(awk '/^deb / {print $2; exit}' /etc/apt/sources.list 2>/dev/null || true)
    echo "deb-src ${mirror:-http://deb.debian.org/debian} bookworm main" >"$src/apt/sources.list"
  fi
  local apt_opts=(-o "Dir::Etc::SourceList=$PWD/$src/apt/sources.list" -o Dir::Etc::SourceParts=/dev/null
                  -o "Dir::State::Lists=$PWD/$src/apt/lists" -o Debug::NoDropPrivs=1)
  [ -n "$(ls -A "$src/apt/lists" 2>/dev/null | grep -v partial)" ] || apt-get -qq "${apt_opts[@]}" update
  (cd "$src" && apt-get -qq "${apt_opts[@]}" source "$1" >/dev/null 2>&1)
  rm -rf "${src:?}/$2" && mv "$src/$1"-[0-9]* "$src/$2"
}
fetch_source imgui imgui imgui.cpp
fetch_source lz4 lz4 lib/lz4.c
imgui=$src/imgui
# Debian's emscripten runs its JavaScript tools with whichever node is first on PATH; Debian's
# node modules (acorn) live where only Debian's own node looks by default.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}

[ -f "$build/build.ninja" ] || emcmake cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DIMGUI_SOURCE_DIR="$PWD/$imgui" -DLZ4_SOURCE_DIR="$PWD/$src/lz4" >/dev/null
cmake -S . -B "$build" -DSHADELAB_COURSE="$course" >/dev/null  # the course this build carries, or none
cmake --build "$build"
site=(index.html isolation.js course.js exercise.js shadelab.js shadelab.wasm shadelab.data shadelab.worker.js)

case $mode in
  build) echo "web.sh: built $build/index.html" ;;
  out)
    mkdir -p "$out"
    for f in "${site[@]}"; do cp "$build/$f" "$out/"; done
    echo "web.sh: the site is in $out (${site[*]}). Its threads need these headers:"
    echo "  Cross-Origin-Opener-Policy: same-origin, Cross-Origin-Embedder-Policy: require-corp"
    echo "A host that cannot send them (GitHub Pages, most course sites) needs nothing more: over https the"
    echo "page registers isolation.js, a service worker that adds them, and reloads itself once."
    ;;
  serve) exec python3 tools/serve_web.py "$build" --port "$port" ;;
esac
