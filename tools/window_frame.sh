#!/usr/bin/env bash
# The window's frame beside the lab's headless frame and the chapter's method, at one size: the
# shadows lab on LearnOpenGL's scene (800x600) as the scene opens, with its own defaults (four 512^2
# cascades, 3x3 PCF), and at the chapter's settings (one 1024^2 map fitted to the view, 3x3 PCF).
#   tools/window_frame.sh [BUILD_DIR] [FRAMES]        (defaults: build 300)
# 1. Headless: BM_LearnOpenGLFrame/1/0 and /1/1 of build/bench/shadelab_bench (the lab's frame and
#    the chapter's method written plainly, interleaved, wall clock with glFinish).
# 2. The window under Xvfb, 800x600, in presentation mode (the viewport fills the window, so it is
#    800x600 too) and in the normal layout (side panels, a smaller viewport), each drawing FRAMES
#    frames; it prints the median time between frames (drawing, UI and the buffer swap).
# Medians of one run each, one after the other on the same machine: compare ratios, not runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
frames=${2:-300}
bin=$build/shadelab
bench=$build/bench/shadelab_bench
[ -x "$bin" ] && [ -x "$bench" ] || { echo "window_frame: no $bin or $bench; build first" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "window_frame: xvfb-run is not installed (./test.sh installs it)" >&2; exit 2; }

# window LAYOUT_ARGS...: the median frame the window reports when it exits
window() {
  xvfb-run -a -s "-screen 0 800x600x24" "$bin" --lab shadows --scene learnopengl --window-size 800x600 \
    --exit-after "$frames" "$@" 2>/dev/null | sed -n 's/.*median frame \([0-9.]*\) ms idle.*/\1/p'
}
echo "| frame, 800x600 window | median ms | / headless lab | / chapter's method | misclassified |"
echo "|---|---|---|---|---|"
for config in "the scene's defaults|0|" \
  "the chapter's settings|1|--set shadows.fit=view --set shadows.map_size=1024 --set shadows.filter=pcf --set shadows.pcf_size=3"; do
  IFS='|' read -r name arg sets <<<"$config"
  headless=$(LIBGL_ALWAYS_SOFTWARE=1 "$bench" --benchmark_filter="BM_LearnOpenGLFrame/1/$arg/" 2>/dev/null | grep BM_)
  lab_ms=$(grep -o 'lab_ms=[0-9.]*' <<<"$headless" | cut -d= -f2)
  chapter_ms=$(grep -o 'chapter_ms=[0-9.]*' <<<"$headless" | cut -d= -f2)
  missed=$(grep -o 'misclassified_pct=[0-9.]*' <<<"$headless" | cut -d= -f2)
  # shellcheck disable=SC2086 # the settings are words
  present_ms=$(window $sets --present)
  # shellcheck disable=SC2086
  layout_ms=$(window $sets)
  row() {
    awk -v n="$1" -v m="$2" -v l="$lab_ms" -v c="$chapter_ms" -v p="$3" \
      'BEGIN {printf "| %s | %.1f | %.2f | %.2f | %s |\n", n, m, m / l, m / c, p}'
  }
  row "chapter's method, headless" "$chapter_ms" "0.085 % (its box: tutorials/shadows.md, section 10)"
  row "the lab, $name, headless" "$lab_ms" "$missed %"
  row "the window, $name, presentation mode (800x600 viewport)" "$present_ms" ""
  row "the window, $name, side panels" "$layout_ms" ""
done
