#!/usr/bin/env bash
# The real window under Xvfb: runs frames while switching through every lab, saves a screenshot
# of the whole window (UI included) and checks it is not blank.
# usage: window_test.sh SHADELAB IMAGE_CHECK OUT_DIR
set -euo pipefail
shadelab=$1 check=$2 out=$3
if ! command -v xvfb-run >/dev/null; then
  echo "xvfb-run not installed: skipping the window test (./test.sh installs it)"
  exit 77
fi
mkdir -p "$out"
rm -f "$out/window.png"
export SHADELAB_OUT="$out"
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --exit-after 12 --cycle-labs --screenshot "$out/window.png"
"$check" "$out/window.png" --min-stddev 0.05 --min-colors 200
# A second run with a broken student shader: the window must still run and show something.
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --exit-after 6 \
  --shaders "$(dirname "$0")/../data/broken_shaders" --screenshot "$out/window_broken.png" 2>"$out/broken.log"
grep -q "shade.frag:6:[0-9]*: error:" "$out/broken.log"
"$check" "$out/window_broken.png" --min-stddev 0.05 --min-colors 50
echo "window test passed"
