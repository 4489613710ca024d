#!/usr/bin/env bash
# The page against the desktop, side by side on this machine:
#   tools/web_bench.sh [FRAMES] [CYCLE_SECONDS]        (defaults: 60 frames, 300 s)
# 1. What a visitor downloads: the .wasm, .js and worker gzipped (the site without its data), and
#    the data file (the shaders and exercises) gzipped.
# 2. Every lab's default frame at 1280x720, each in presentation mode (the viewport is the whole
#    1280x720): the page in headless Chromium (SwiftShader's WebGL2) and the desktop's window under
#    Xvfb (llvmpipe), FRAMES frames each, one lab after the other. Medians of the frame (drawing, UI,
#    the swap) and of the lab's own passes, and page / desktop for each.
# 3. The page's load to its first frame, per lab (what web_driver.py measures from navigation).
# 4. The tab's memory while it switches labs every three frames for CYCLE_SECONDS: the WebAssembly
#    heap and the browser's processes' resident memory, at the start and at the end.
# Needs ./web.sh --build and the desktop build (build/). Figures from one run: compare the ratios.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
frames=${1:-60}
cycle=${2:-300}
site=$root/build-web bin=$root/build/shadelab
[ -f "$site/shadelab.wasm" ] || { echo "web_bench: no page in $site (./web.sh --build)" >&2; exit 2; }
[ -x "$bin" ] || { echo "web_bench: no $bin (cmake --build build)" >&2; exit 2; }
out=$(mktemp -d /tmp/shadelab-web-bench.XXXXXX)
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 "$root/tools/serve_web.py" "$site" --port "$port" >"$out/serve.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 50); do grep -q "http://" "$out/serve.log" 2>/dev/null && break; sleep 0.1; done

gz() { gzip -9 -c "$1" | wc -c; }
code=0
for f in shadelab.wasm shadelab.js shadelab.worker.js; do code=$((code + $(gz "$site/$f"))); done
echo "download: .wasm + .js + worker $(awk -v b=$code 'BEGIN {printf "%.2f", b / 1048576}') MB gzipped;" \
  "data (shaders, exercises) $(awk -v b="$(gz "$site/shadelab.data")" 'BEGIN {printf "%.2f", b / 1048576}') MB gzipped"

# field LINE NAME: a number from the window's report line
median() { sed -n "s/.*median frame \([0-9.]*\) ms idle.*/\1/p" <<<"$1"; }
passes() { sed -n "s/.*the lab's passes \([0-9.]*\) ms.*/\1/p" <<<"$1"; }
echo
echo "| lab (default, 1280x720) | page frame ms | desktop frame ms | page / desktop | page passes ms | desktop passes ms | page / desktop | page load to first frame s |"
echo "|---|---|---|---|---|---|---|---|"
for lab in ${WEB_BENCH_LABS:-$("$bin" list | sed -n '/^labs:/,/^scenes/p' | sed -n 's/^\([a-z][a-z]*\)  .*/\1/p')}; do
  python3 "$root/tools/web_driver.py" "http://127.0.0.1:$port/index.html#lab=$lab&present&frames=$frames" --size 1280,720 \
    --frames 1 --timeout 600 --wait-console "frames: " --screenshot "$out/$lab.png" >"$out/$lab-page.log" 2>&1 || true
  page=$(grep -m1 "console log: frames: " "$out/$lab-page.log" || true)
  first=$(sed -n 's/^frames: .*first frame after \([0-9.]*\) s.*/\1/p' "$out/$lab-page.log" | head -1)
  desk=$(xvfb-run -a -s "-screen 0 1280x720x24" "$bin" --lab "$lab" --present --window-size 1280x720 \
    --exit-after "$frames" 2>/dev/null | grep "^frames: " || true)
  if [ -z "$page" ] || [ -z "$desk" ]; then
    echo "| $lab | (no report: see $out/$lab-page.log) | | | | | | |"
    continue
  fi
  awk -v l="$lab" -v pf="$(median "$page")" -v df="$(median "$desk")" -v pp="$(passes "$page")" -v dp="$(passes "$desk")" \
    -v fl="$first" 'BEGIN {printf "| %s | %.1f | %.1f | %.2f | %.2f | %.2f | %.2f | %s |\n", l, pf, df, pf / df, pp, dp,
                           (dp > 0 ? pp / dp : 0), fl}'
done

# The tab's memory: the wasm heap from inside, the browser's processes' resident memory from outside.
rss() { ps -C chromium -o rss= 2>/dev/null | awk '{s += $1} END {printf "%.0f", s / 1024}'; }
memory="(async () => { const sample = () => ({wasm_mb: Math.round(Module.HEAP8.length / 1048576),
  js_mb: Math.round(performance.memory.usedJSHeapSize / 1048576), frames: Module.shadelabFrames});
  const start = sample(); await new Promise((ok) => setTimeout(ok, $cycle * 1000));
  return JSON.stringify({start: start, end: sample()}); })()"
python3 "$root/tools/web_driver.py" "http://127.0.0.1:$port/index.html#lab=shading&cycle" --size 1280,720 --frames 10 \
  --timeout $((cycle + 300)) --eval "$memory" --screenshot "$out/cycle.png" >"$out/cycle.log" 2>&1 &
driver=$!
sleep 20
rss_start=$(rss)
peak=$rss_start
while kill -0 $driver 2>/dev/null; do
  now=$(rss)
  [ -n "$now" ] && [ "$now" -gt "$peak" ] && peak=$now
  last=$now
  sleep 10
done
echo
echo "switching labs every three frames for $cycle s: $(grep -o '{\\"start.*}' "$out/cycle.log" | tr -d '\\' || echo 'no sample')"
echo "the browser's resident memory: ${rss_start} MB at 20 s, ${last:-?} MB at the end, peak ${peak} MB"
echo "logs and screenshots: $out"
