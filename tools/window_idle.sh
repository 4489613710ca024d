#!/usr/bin/env bash
# What a window costs when nothing moves: CPU time per second of wall time, per lab, beside the
# same window drawing every frame (--exit-after keeps it drawing, as the tests do).
#   tools/window_idle.sh [BUILD_DIR] [SECONDS]        (defaults: build 10)
# Each window is started under Xvfb, left 8 s to start and settle, then its process's user+system
# CPU time is read over SECONDS. 100 % is one core. CPU time, not wall time: a loaded machine
# slows the window but barely changes what it burns.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
seconds=${2:-10}
bin=$build/shadelab
[ -x "$bin" ] || { echo "window_idle: no $bin; build first" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "window_idle: xvfb-run is not installed (./test.sh installs it)" >&2; exit 2; }
tick=$(getconf CLK_TCK)

cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }

# measure LABEL ARGS...: the window's CPU % over $seconds after 8 s
measure() {
  local label=$1
  shift
  xvfb-run -a -s "-screen 0 1280x800x24" "$bin" "$@" >/dev/null 2>&1 &
  local runner=$! pid="" a b
  for _ in $(seq 50); do
    pid=$(pgrep -n -f "^$bin $*" || true)
    [ -n "$pid" ] && break
    sleep 0.2
  done
  [ -n "$pid" ] || { echo "window_idle: $label did not start" >&2; kill "$runner" 2>/dev/null; return 1; }
  sleep 8
  a=$(cpu_ticks "$pid")
  sleep "$seconds"
  b=$(cpu_ticks "$pid")
  kill "$pid" 2>/dev/null || true
  wait "$runner" 2>/dev/null || true
  printf '| %s | %s |\n' "$label" "$(awk -v d=$((b - a)) -v t="$tick" -v s="$seconds" 'BEGIN {printf "%.1f %%", 100 * d / t / s}')"
}

echo "| window | CPU, % of one core |"
echo "|---|---|"
for lab in shading shadows surface denoise filtering; do
  measure "$lab, idle" --lab "$lab"
done
measure "shadows, drawing every frame" --lab shadows --exit-after 100000000
