#!/usr/bin/env bash
# The page in Debian's headless Chromium (SwiftShader's WebGL2), as ./web.sh --build left it in
# build-web/: served with the isolation headers threads need, each lab opened by its link, frames
# counted, no shader or WebGL error, the viewport of each screenshot checked for a picture (not one
# flat colour).
# usage: web_test.sh REPO IMAGE_CHECK OUT_DIR
set -euo pipefail
repo=$1 check=$2 out=$3
site=$repo/build-web
if [ ! -f "$site/shadelab.wasm" ]; then
  echo "no page in $site: ./test.sh builds it (./web.sh --build)"
  exit 1
fi
mkdir -p "$out"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 "$repo/tools/serve_web.py" "$site" --port "$port" >"$out/serve.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 50); do grep -q "http://" "$out/serve.log" 2>/dev/null && break; sleep 0.1; done

# The viewport at the default layout of a 1280x800 page: between the side panels, under its title.
viewport=400,40,480,740
open_lab() {  # open_lab NAME LINK: the page at LINK draws 10 frames and its viewport shows a picture
  local name=$1 link=$2
  python3 "$repo/tools/web_driver.py" "http://127.0.0.1:$port/index.html#$link" --frames 10 --timeout 90 \
    --screenshot "$out/$name.png" >"$out/$name.log" 2>&1 || { cat "$out/$name.log"; echo "$name: the page failed"; exit 1; }
  if grep -qE "error:|GL_INVALID|WebGL: INVALID" "$out/$name.log"; then
    cat "$out/$name.log"; echo "$name: a shader or a WebGL call failed in the page"; exit 1
  fi
  "$check" "$out/$name.png" --crop "$viewport" --min-stddev 0.03 --min-colors 100 ||
    { cat "$out/$name.log"; echo "$name: the viewport is blank"; exit 1; }
  grep "^frames:" "$out/$name.log"
}
open_lab shading "lab=shading"
open_lab surface "lab=surface"
open_lab denoise "lab=denoise"
open_lab filtering "lab=filtering"
open_lab shadows "lab=shadows"
open_lab shadows-point-pcss "lab=shadows&shadows.light_type=point&shadows.filter=pcss"  # six cube passes
echo "web test passed"
