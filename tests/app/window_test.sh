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

# The student's loop: --exercise opens the exercise's lab on its first configuration (the preset
# written beside the screenshot says which), and Check on the starter shows, for every
# configuration that lost points, the student's frame, the solution's and their difference.
student="$out/exercise_student"
rm -rf "$student" "$out/window_exercise.json" && mkdir -p "$student"
cp -r "$(dirname "$0")/../../exercises/shadows/shadow-lookup/starter/." "$student/"
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --shaders "$student" --exercise shadows/shadow-lookup --check \
  --exit-after 300 --screenshot "$out/window_exercise.png" >"$out/exercise.log" 2>&1
python3 - "$out/window_exercise.json" <<'PY' || { cat "$out/exercise.log"; exit 1; }
import json, sys
state = json.load(open(sys.argv[1]))
assert state["lab"] == "shadows", "the exercise's lab: " + state["lab"]
assert state["params"]["view"] == "visibility", "its first configuration's view: " + str(state["params"]["view"])
PY
failing=$(grep -cE "^  (FAIL|PARTIAL)" "$out/exercise.log" || true)
configs=$(grep -E "^  (FAIL|PARTIAL)" "$out/exercise.log" | sed -E 's/^  (FAIL|PARTIAL) +([^:]*):.*/\2/' | sort -u | wc -l)
shown=$(grep -c "^pictures of '" "$out/exercise.log" || true)
[ "$failing" -gt 0 ] && [ "$shown" -eq "$configs" ] ||
  { cat "$out/exercise.log"; echo "Check showed pictures for $shown of $configs failing configurations"; exit 1; }
"$check" "$out/window_exercise.png" --min-stddev 0.05 --min-colors 200
echo "exercise opened where it is done, Check with its pictures passed ($shown configurations)"

# A student's include that leaves the shader folders: the window runs on, names the rule, and
# prints nothing of the file it refused to read.
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --exit-after 4 \
  --shaders "$(dirname "$0")/../data/escape_shaders" --screenshot "$out/window_escape.png" 2>"$out/escape.log"
grep -q "shade.frag:4:11: error: #include may only name files inside the shader folders" "$out/escape.log" ||
  { cat "$out/escape.log"; echo "the window did not refuse the include"; exit 1; }
if grep -qE "PRETTY_NAME|VERSION_ID" "$out/escape.log"; then echo "the window printed a refused file"; exit 1; fi
"$check" "$out/window_escape.png" --min-stddev 0.05 --min-colors 50
echo "include escape in the window passed"

# The inspector in the window: I (--inspect) over the PCF exercise's penumbra traces the student's
# loop at that point of the view; the section shows the table and the marked line, and the view
# is drawn on.
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --shaders "$(dirname "$0")/../data/inspect_pcf" --exercise shadows/pcf \
  --inspect 260,457 --exit-after 40 --screenshot "$out/window_inspect.png" >"$out/inspect.log" 2>&1 ||
  { cat "$out/inspect.log"; echo "the window with the inspector failed"; exit 1; }
grep -q "^> line 11  lit = 25 times" "$out/inspect.log" && grep -q "(returned) = .*the solution returns" "$out/inspect.log" ||
  { cat "$out/inspect.log"; echo "the inspector did not mark the loop's line"; exit 1; }
"$check" "$out/window_inspect.png" --min-stddev 0.05 --min-colors 200
# With no exercise open, I traces the lab's own pass: the surface lab's main() at the view's pixel.
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --lab surface --inspect 260,400 --exit-after 30 \
  --screenshot "$out/window_inspect_lab.png" >"$out/inspect_lab.log" 2>&1 ||
  { cat "$out/inspect_lab.log"; echo "the window with the lab's inspector failed"; exit 1; }
grep -q "^surface/surface.frag, main():" "$out/inspect_lab.log" && grep -q "^  line [0-9]*  uv = (" "$out/inspect_lab.log" ||
  { cat "$out/inspect_lab.log"; echo "the lab's inspector did not show the pass's values"; exit 1; }
echo "inspector in the window passed"

# A short soak in the real window: random labs, parameters, broken and fixed shaders, meshes and
# Measure for 20 s; no bad frame, no GL error, GL objects back to their count on entering a lab.
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --soak 0.33 --soak-seed 5 >"$out/soak.log" 2>&1 ||
  { tail -20 "$out/soak.log"; echo "the window soak failed"; exit 1; }
grep -q "soak: 0 frames with NaN/Inf, 0 GL errors" "$out/soak.log" || { tail -20 "$out/soak.log"; exit 1; }
grep -q "soak: samples in .*; passed" "$out/soak.log" || { tail -20 "$out/soak.log"; echo "the soak's verdict is not passed"; exit 1; }
echo "soak in the window passed"

# Presentation mode on the filtering lab: the viewport fills the window (over 100,000 pixels of its
# sky), and the sky is drawn opaque (its alpha is 0, coverage for the metrics: blended, it was black).
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --lab filtering --present --exit-after 4 \
  --screenshot "$out/window_present.png" >/dev/null
"$check" "$out/window_present.png" --color 140,173,209 --min-pixels 100000
echo "presentation mode passed"

# Measure in the window: with auto-measure on, the error against the truth appears.
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --lab shading --auto-measure --exit-after 40 \
  --screenshot "$out/window_measure.png" >"$out/measure.log"
grep -q "measured shading (defaults), truth: Phong at 256 segments: rmse=0\.0[0-9]* surface_rmse=" "$out/measure.log" ||
  { cat "$out/measure.log"; echo "Measure showed no error number"; exit 1; }
echo "measure in the window passed"

# A long job (a PCSS truth, 64 shadow rays per pixel, traced in the background): frames keep
# coming while it runs, and its progress bar (ImGui's 230,179,0 fill) is on screen.
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --lab shadows --set shadows.filter=pcss --measure \
  --exit-after 30 --screenshot "$out/window_job.png" >"$out/job.log"
busy=$(sed -n 's/.*, \([0-9]*\) while jobs ran;.*/\1/p' "$out/job.log")
[ "${busy:-0}" -ge 15 ] || { cat "$out/job.log"; echo "frames stopped while the job ran"; exit 1; }
"$check" "$out/window_job.png" --color 230,179,0 --min-pixels 200
echo "long job in the window passed"

# A person's session: drag in the viewport to orbit, press F12, then reproduce the screenshot
# headless from the JSON saved beside it. Needs xdotool (./test.sh installs it).
if command -v xdotool >/dev/null; then
  rm -rf "$out/session"
  cat > "$out/session.sh" <<SESSION
export SHADELAB_OUT="$out/session"
"$shadelab" --exit-after 100000 &
pid=\$!
for i in \$(seq 1 100); do wid=\$(xdotool search --name ShadeLab 2>/dev/null | head -1); [ -n "\$wid" ] && break; sleep 0.2; done
sleep 1.5
xdotool mousemove --window \$wid 640 400; sleep 0.3; xdotool mousedown 1; sleep 0.3
for x in 660 680 700 720 740; do xdotool mousemove --window \$wid \$x 400; sleep 0.15; done
xdotool mouseup 1; sleep 0.3
xdotool key --window \$wid F12
for i in \$(seq 1 50); do ls "$out/session/screenshots/"*.json >/dev/null 2>&1 && break; sleep 0.2; done
sleep 0.3
kill \$pid
SESSION
  xvfb-run -a -s "-screen 0 1280x800x24" bash "$out/session.sh" || true
  json=$(ls "$out"/session/screenshots/*.json)
  grep -q '"camera": "yaw=20,' "$json" && { echo "dragging in the viewport did not orbit the camera"; exit 1; }
  "$shadelab" render --preset "$json" --frames 1 --out "$out/session/again.png"
  "$shadelab" compare "${json%.json}.png" "$out/session/again.png" | tee "$out/session/compare.txt"
  grep -q "^rmse 0.00[0-4]" "$out/session/compare.txt" || { echo "the screenshot did not reproduce headless"; exit 1; }
  echo "screenshot reproduced headless"
else
  echo "xdotool not installed: skipped the drag / F12 / reproduce part"
fi

# When nothing moves the window stops drawing (an idle window costs next to nothing), yet a shader
# file saved meanwhile is rebuilt at once: start on a good copy of the shading lab's shader, let
# it settle, read its CPU time, then save a broken version and look for the error.
student="$out/idle_student"
rm -rf "$student" && mkdir -p "$student/shading"
cp "$(dirname "$0")/../../shaders/shading/shade.frag" "$student/shading/shade.frag"
xvfb-run -a -s "-screen 0 1280x800x24" "$shadelab" --lab shading --shaders "$student" >"$out/idle.log" 2>&1 &
runner=$!
pid=""
for _ in $(seq 50); do
  pid=$(pgrep -n -f "^$shadelab --lab shading --shaders $student" || true)
  [ -n "$pid" ] && break
  sleep 0.2
done
[ -n "$pid" ] || { cat "$out/idle.log"; echo "the idle window did not start"; exit 1; }
sleep 8
ticks() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
a=$(ticks); sleep 4; b=$(ticks)
cpu=$(( (b - a) * 100 / $(getconf CLK_TCK) / 4 ))
cp "$(dirname "$0")/../data/broken_shaders/shading/shade.frag" "$student/shading/shade.frag"
for _ in $(seq 40); do grep -q "shade.frag:6:[0-9]*: error:" "$out/idle.log" && break; sleep 0.25; done
kill "$pid" 2>/dev/null || true
wait "$runner" 2>/dev/null || true
# A window drawing every frame burns well over 100 % here; an idle one wakes four times a second.
[ "$cpu" -lt 25 ] || { echo "the idle window used $cpu % of a core; it should have stopped drawing"; exit 1; }
grep -q "shade.frag:6:[0-9]*: error:" "$out/idle.log" ||
  { cat "$out/idle.log"; echo "a shader saved while the window was idle was not rebuilt"; exit 1; }
echo "idle window passed ($cpu % of a core; the saved shader rebuilt)"
