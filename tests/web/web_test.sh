#!/usr/bin/env bash
# The page in Debian's headless Chromium (SwiftShader's WebGL2), as ./web.sh --build left it in
# build-web/: served with the isolation headers threads need, each lab opened by its link, frames
# counted, no shader or WebGL error, the viewport of each screenshot checked for a picture (not one
# flat colour).
# Then what a user does there: Measure gives a number, F12's frame and preset are rendered again by
# the desktop build and agree with it, and a dropped shader with a typo is named at its file:line.
# usage: web_test.sh REPO IMAGE_CHECK OUT_DIR SHADELAB
set -euo pipefail
repo=$1 check=$2 out=$3 shadelab=$4
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
open_lab shading-flat "lab=shading&shading.mode=flat"  # unwelded faces: no geometry shader in WebGL2
open_lab surface "lab=surface"
open_lab surface-tessellation "lab=surface&surface.technique=tessellation"  # cut on the CPU: no tessellation stages
open_lab denoise "lab=denoise"
open_lab filtering "lab=filtering"
open_lab shadows "lab=shadows"
open_lab shadows-point-pcss "lab=shadows&shadows.light_type=point&shadows.filter=pcss"  # six cube passes
# The depth-range fit: the camera's depth reduced on the GPU and read back (gl::TexelRead reads at once here).
open_lab shadows-depth-range "lab=shadows&shadows.fit=depth-range"
echo "every lab draws in the page"

drive() {  # drive NAME LINK ARGS...: the page at LINK (of the site on $drive_port), driven by tools/web_driver.py ARGS
  local name=$1 link=$2
  shift 2
  python3 "$repo/tools/web_driver.py" "http://127.0.0.1:${drive_port:-$port}/index.html#$link" --frames 5 --timeout 180 \
    --screenshot "$out/$name.png" "$@" >"$out/$name.log" 2>&1 || { cat "$out/$name.log"; echo "$name: failed"; exit 1; }
}

# The pixel readout under the cursor (a one-texel read back): the page keeps drawing while it is shown.
hover="(() => { for (const [x, y] of [[600, 400], [620, 410], [640, 420]])
  Module.canvas.dispatchEvent(new MouseEvent('mousemove', {clientX: x, clientY: y, bubbles: true})); return 'hovered'; })()"
drive probe "lab=shading" --frames 10 --eval "$hover"
echo "the pixel readout works in the page"

# Measure from the link: the shading lab's error against its truth (an image) is a number.
drive measure "lab=shading&measure" --wait-console "measured shading"
grep -qE "measured shading \(defaults\), truth: .*rmse=[0-9]" "$out/measure.log" ||
  { cat "$out/measure.log"; echo "Measure gave no number in the page"; exit 1; }
grep -o "measured shading.*" "$out/measure.log"
# The shadows lab's truth in the page is the GPU tracer (no Embree there): both truths come back.
drive measure-shadows "lab=shadows&measure" --wait-console "measured shadows"
grep -qE "measured shadows .*truth: ray-traced on the GPU: .*visibility_rmse_hard=[0-9].*visibility_rmse_area=[0-9]" \
  "$out/measure-shadows.log" || { cat "$out/measure-shadows.log"; echo "the shadows truth gave no number in the page"; exit 1; }
grep -o "measured shadows.*" "$out/measure-shadows.log"

# F12 in the page saves (and offers as downloads) the frame and its preset; the desktop renders the
# preset again, and the two frames agree: the same sources, shaders and numbers on both.
f12="(() => { const e = new KeyboardEvent('keydown', {key: 'F12', code: 'F12', bubbles: true});
  Object.defineProperty(e, 'keyCode', {get: () => 123}); window.dispatchEvent(e);
  const u = new KeyboardEvent('keyup', {key: 'F12', code: 'F12', bubbles: true});
  Object.defineProperty(u, 'keyCode', {get: () => 123}); window.dispatchEvent(u); return 'F12'; })()"
drive screenshot "lab=shading" --frames 10 --eval "$f12" --wait-console "saved " \
  --fetch "Module.shadelabSaved[0]=$out/page-frame.png" --fetch "Module.shadelabSaved[1]=$out/page-frame.json"
LIBGL_ALWAYS_SOFTWARE=1 "$shadelab" render --preset "$out/page-frame.json" --out "$out/native-frame.png" >/dev/null
rmse=$("$shadelab" compare "$out/page-frame.png" "$out/native-frame.png" | sed -n 's/^rmse \([0-9.]*\).*/\1/p')
echo "the page's frame against the desktop's (SwiftShader against llvmpipe): rmse $rmse"
python3 -c "import sys; sys.exit(0 if float('$rmse') <= 0.01 else 1)" ||
  { echo "the page's frame and the desktop's differ by more than 0.01 RMSE"; exit 1; }

# A student's shader dropped on the page, with a typo: its file and line are named (WebGL's
# compiler gives no column).
frag=$(python3 -c 'import json, sys; print(json.dumps(open(sys.argv[1]).read()))' "$repo/tests/data/broken_shaders/shading/shade.frag")
drop="(() => { const dt = new DataTransfer(); dt.items.add(new File([$frag], 'shade.frag', {type: 'text/plain'}));
  Module.canvas.dispatchEvent(new DragEvent('drop', {dataTransfer: dt, bubbles: true, cancelable: true})); return 'dropped'; })()"
drive drop "lab=shading" --frames 10 --eval "$drop" --wait-console "shade.frag:6:"
grep -qE "shade\.frag:6:([0-9]+:)? error:" "$out/drop.log" || { cat "$out/drop.log"; echo "the dropped shader's error was not named"; exit 1; }
grep -m1 -oE "[^ ]*shade\.frag:6:([0-9]+:)? error:.*" "$out/drop.log"

# The page's student folder: a file saved there (as the in-page editor saves) rebuilds the programs
# that read it, and it is still there after a reload (the browser's storage).
save="(async () => { Module.FS.mkdirTree('/student/shading'); Module.FS.writeFile('/student/shading/shade.frag', $frag);
  await new Promise((ok, fail) => Module.FS.syncfs(false, (e) => e ? fail(e) : ok())); return 'saved'; })()"
drive student "lab=shading" --frames 10 --eval "$save" --wait-console "/student/shading/shade.frag:6" \
  --reload --wait-console-after-reload "/student/shading/shade.frag:6"
sed -n '/--- reloaded ---/,$p' "$out/student.log" | grep -qE "/student/shading/shade\.frag:6:([0-9]+:)? error:" ||
  { cat "$out/student.log"; echo "the student's saved shader was not there after a reload"; exit 1; }
# It never compiled in this page: the loud magenta checker is drawn in its place, not nothing.
"$check" "$out/student.png" --crop "$viewport" --min-colors 2 --color 255,0,255 --min-pixels 5000 ||
  { echo "a program that never compiled drew nothing in the page"; exit 1; }
echo "the student's folder survives a reload"

# An exercise checked in the page: the starter saved into the student's folder, the page reloaded on
# the exercise's link with "check", and Check's lines are the grader's (the diagnosis, a number per check).
# check_starter NAME LINK EXERCISE FILE SOURCE: SOURCE saved as the student's FILE, the page reloaded
# on LINK (which presses Check): Check's lines say it is the starter, and that it has not passed.
check_starter() {
  local name=$1 link=$2 exercise=$3 file=$4 source=$5 text save checked
  text=$(python3 -c 'import json, sys; print(json.dumps(open(sys.argv[1]).read()))' "$source")
  save="(async () => { Module.FS.mkdirTree('/student/$(dirname "$file")'); Module.FS.writeFile('/student/$file', $text);
    await new Promise((ok, fail) => Module.FS.syncfs(false, (e) => e ? fail(e) : ok())); return 'saved'; })()"
  # A Check in SwiftShader draws the solution and every listed mistake of each configuration: the
  # surface exercises' take minutes on two busy cores, so these drives may run past the usual 180 s.
  drive "$name" "$link" --frames 10 --eval "$save" --wait-console "$exercise: " --reload \
    --wait-console-after-reload "$exercise: " --timeout 420
  checked=$(sed -n '/--- reloaded ---/,$p' "$out/$name.log")
  grep -q "diagnosis: Your frames are the starter's" <<<"$checked" &&
    grep -qE "$exercise: [0-9.]+ / [0-9.]+ points .*NOT PASSED" <<<"$checked" ||
    { cat "$out/$name.log"; echo "Check in the page did not grade the $exercise starter"; exit 1; }
  grep -m1 -E "$exercise: [0-9.]+ / " <<<"$checked"
}
check_starter check "lab=shading&exercise=shading/blinn-phong&check" shading/blinn-phong common/specular.glsl \
  "$repo/exercises/shading/blinn-phong/starter/common/specular.glsl"
checked=$(sed -n '/--- reloaded ---/,$p' "$out/check.log")
grep -qE "FAIL +per-fragment: highlight +covered_rmse +0\.[0-9]+" <<<"$checked" &&
  grep -qE "shading/blinn-phong: 3 / 12 points .*NOT PASSED" <<<"$checked" ||
  { cat "$out/check.log"; echo "Check in the page did not grade the starter"; exit 1; }
grep -m1 -E "FAIL +per-fragment: highlight" <<<"$checked"
echo "Check grades an exercise in the page"
# The same diagnosis in the page as on the terminal, for a mistake no rubric lists (from
# tests/grade/unlisted: the highlight squared, which the grader finds by tracing the student's
# specular factor line by line beside the solution's: the page instruments and evaluates the
# function in GLSL ES 3.00 as the terminal does in 3.30).
squared=$out/squared/common/specular.glsl
mkdir -p "$(dirname "$squared")"
python3 - "$repo/exercises/shading/blinn-phong/starter/common/specular.glsl" "$repo/tests/grade/unlisted/shading/blinn-phong.json" \
  "$squared" <<'STUDENT'
import json, sys
starter, unlisted, out = sys.argv[1:]
body = next(m["body"] for m in json.load(open(unlisted))["mistakes"] if m["name"] == "n-dot-h-squared")
text = open(starter).read()
begin = text.index("  // TODO(exercise shading/blinn-phong): begin")
end = text.index("\n", text.index("// TODO(exercise shading/blinn-phong): end")) + 1
open(out, "w").write(text[:begin] + body + "\n" + text[end:])
STUDENT
text=$(python3 -c 'import json, sys; print(json.dumps(open(sys.argv[1]).read()))' "$squared")
drive check-squared "lab=shading&exercise=shading/blinn-phong&check" --frames 10 --eval "(async () => {
    Module.FS.mkdirTree('/student/common'); Module.FS.writeFile('/student/common/specular.glsl', $text);
    await new Promise((ok, fail) => Module.FS.syncfs(false, (e) => e ? fail(e) : ok())); return 'saved'; })()" \
  --wait-console "shading/blinn-phong: " --reload --wait-console-after-reload "shading/blinn-phong: "
page_diagnosis=$(sed -n '/--- reloaded ---/,$p' "$out/check-squared.log" | grep -m1 -o "diagnosis: .*" || true)
rm -rf "$out/squared-grade"
LIBGL_ALWAYS_SOFTWARE=1 "$shadelab" grade --exercise shading/blinn-phong --shaders "$out/squared" \
  --out "$out/squared-grade" >"$out/squared-grade.log" 2>&1 || true
terminal_diagnosis=$(grep -m1 -o "diagnosis: .*" "$out/squared-grade.log" || true)
grep -q "Line 11 of common/specular.glsl .*It is the solution's result, squared" <<<"$terminal_diagnosis" &&
  [ "$page_diagnosis" = "$terminal_diagnosis" ] ||
  { echo "page:     $page_diagnosis"; echo "terminal: $terminal_diagnosis"; echo "the page's diagnosis is not the grader's"; exit 1; }
echo "the page's Check says the grader's diagnosis: ${page_diagnosis:0:100}..."
squared=$(sed -n '/--- reloaded ---/,$p' "$out/check-squared.log")
lost=$(grep -E "^(console log: )?  (FAIL|PARTIAL)" <<<"$squared" |
  sed -E 's/^(console log: )?  (FAIL|PARTIAL) +([^:]*):.*/\3/' | sort -u | wc -l)
shown=$(grep -c "pictures of '" <<<"$squared" || true)
[ "$lost" -gt 0 ] && [ "$shown" -eq "$lost" ] ||
  { echo "$squared"; echo "the page's Check showed pictures for $shown of $lost configurations that lost points"; exit 1; }

# A link with only the exercise opens the page on the exercise's lab and its first configuration.
drive exercise-link "exercise=surface/normal-map" --wait-console "exercise surface/normal-map opened"
grep -q "exercise surface/normal-map opened on the surface lab" "$out/exercise-link.log" ||
  { cat "$out/exercise-link.log"; echo "the exercise's link did not open its lab"; exit 1; }
echo "a link with only exercise= opens its lab"

# The exercise as text in the document beside the canvas: its statement, and once Check has run,
# the grader's lines, read from document.body as a screen reader or a translator would.
text_after_check="(async () => { const c = document.getElementById('exercise-check'); \
  for (let i = 0; i < 600 && !/points \\(/.test(c.innerText); ++i) await new Promise((r) => setTimeout(r, 250)); \
  return document.body.innerText; })()"
drive exercise-text "exercise=shading/blinn-phong&check" --frames 5 --eval "$text_after_check"
python3 - "$out/exercise-text.log" "$repo/exercises/shading/blinn-phong/statement.md" <<'PY' ||
import json, sys
line = next(l for l in open(sys.argv[1]) if l.startswith("eval "))
body = json.loads(line[line.index(': "') + 2:])  # the result, a JSON string, after the expression (which has no '"')
heading = next(l for l in open(sys.argv[2]) if l.startswith("#")).lstrip("#").strip()
for want in ("Exercise shading/blinn-phong", heading, "Check", "shading/blinn-phong: 0 / "):
    assert want in body, f"not in the page's text: {want!r}"
print("the exercise's statement and Check's lines are text in the page")
PY
  { cat "$out/exercise-text.log"; echo "the page's exercise text is missing"; exit 1; }
# One exercise of each kind since (the from-scratch ones, a vertex stage, the GPU smoothing):
# each starter checked in the page, told it is the starter, not passed.
for exercise in filtering/mip-level shading/perspective-correct shadows/shadow-lookup shadows/point-light surface/displacement surface/screen-tbn denoise/laplacian denoise/apply-map; do
  file=$(cd "$repo/exercises/$exercise/starter" && find . -type f | sed 's|^\./||' | head -1)
  check_starter "check-${exercise//\//-}" "lab=${exercise%%/*}&exercise=$exercise&check" "$exercise" "$file" \
    "$repo/exercises/$exercise/starter/$file"
done
# A course zip of the site, as a teacher puts one beside the page: opened by the link, its part-file
# exercise listed and graded by Check; a zip that is not one, and one whose names leave its folder, are
# refused with the zip's name; a zip dropped on the page opens as a course.
course_site=$out/course-site
rm -rf "$course_site" && mkdir -p "$course_site"
for f in index.html isolation.js course.js exercise.js shadelab.js shadelab.wasm shadelab.data shadelab.worker.js; do
  ln -s "$(realpath "$site/$f")" "$course_site/$f"
done
python3 - "$repo/tests/data/course" "$course_site" <<'ZIP'
import os, sys, zipfile
course, site = sys.argv[1:]
with zipfile.ZipFile(os.path.join(site, "week3.zip"), "w", zipfile.ZIP_DEFLATED) as z:
    for folder, _, files in os.walk(course):
        for f in files:
            z.write(os.path.join(folder, f), os.path.join("week3", os.path.relpath(os.path.join(folder, f), course)))
with zipfile.ZipFile(os.path.join(site, "evil.zip"), "w") as z:
    z.writestr("week3/shading/x/rubric.json", "{}")
    z.writestr("week3/../../student/common/lighting.glsl.part", "overwritten")
open(os.path.join(site, "broken.zip"), "w").write("not a zip")
ZIP
course_port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 "$repo/tools/serve_web.py" "$course_site" --port "$course_port" >"$out/course-serve.log" 2>&1 &
course_server=$!
trap 'kill $server $course_server 2>/dev/null || true' EXIT
for _ in $(seq 50); do grep -q "http://" "$out/course-serve.log" 2>/dev/null && break; sleep 0.1; done
drive_port=$course_port
check_starter course-link "lab=shading&course=week3.zip&exercise=shading/point-lights&check" shading/point-lights \
  common/lighting.glsl.part "$repo/tests/data/course/shading/point-lights/starter/common/lighting.glsl.part"
# Its "per vertex" configuration is hidden until the due date: the page's Check neither draws nor names it.
grep -q "hidden by your teacher" "$out/course-link.log" && ! grep -q "per vertex" "$out/course-link.log" ||
  { cat "$out/course-link.log"; echo "the page's Check showed a hidden configuration"; exit 1; }
drive course-broken "lab=shading&course=broken.zip" --wait-console "broken.zip: not a zip archive"
drop_zip="(async () => { for (const name of ['evil.zip', 'week3.zip']) {
    const bytes = await (await fetch(name)).arrayBuffer();
    const dt = new DataTransfer(); dt.items.add(new File([bytes], name, {type: 'application/zip'}));
    Module.canvas.dispatchEvent(new DragEvent('drop', {dataTransfer: dt, bubbles: true, cancelable: true})); }
  return 'dropped'; })()"
drive course-drop "lab=shading" --frames 10 --eval "$drop_zip" --wait-console "course week3 opened"
grep -q "evil.zip: 'week3/../../student/common/lighting.glsl.part' leaves the course's folder" "$out/course-drop.log" &&
  grep -q "course week3 opened (Exercises): shading/point-lights, shading/specular-lobe" "$out/course-drop.log" ||
  { cat "$out/course-drop.log"; echo "a dropped course zip was not opened (or a hostile one not refused)"; exit 1; }
# Copy link on a page the course link opened, its exercise selected: the address (the page puts it
# in the address bar too) carries the exercise and the course zip on. The button sits where the
# page's Lab panel puts it for the shading lab in a 1660x1000 page, the exercise's text beside the
# canvas and the Exercises section on top (course-copy-link.png shows it).
copy_link="(async () => { const at = (type, x, y) => Module.canvas.dispatchEvent(new MouseEvent(type,
    {clientX: x, clientY: y, button: 0, bubbles: true}));
  const frames = (n) => new Promise((ok) => { const end = Module.shadelabFrames + n;
    const wait = () => Module.shadelabFrames >= end ? ok() : setTimeout(wait, 20); wait(); });
  at('mousemove', 644, 802); await frames(3); at('mousedown', 644, 802); await frames(3);
  at('mouseup', 644, 802); await frames(3); return 'hash: ' + location.hash; })()"
drive course-copy-link "lab=shading&course=week3.zip&exercise=shading/point-lights" --frames 5 --size 1660,1000 \
  --eval "$copy_link"
grep -q "hash: #lab=shading&.*&exercise=shading%2Fpoint-lights&course=week3.zip" "$out/course-copy-link.log" ||
  { cat "$out/course-copy-link.log"; echo "Copy link did not carry the course's exercise on"; exit 1; }
unset drive_port
echo "a course zip opens in the page by link and by drop, is graded there, and Copy link carries it on"

# A shader that runs too long makes the browser take the WebGL context away (here: asked for with
# WEBGL_lose_context): the page stops drawing, says why and offers a reload without the student's folder.
lose="(async () => { Module.canvas.getContext('webgl2').getExtension('WEBGL_lose_context').loseContext();
  await new Promise((ok) => setTimeout(ok, 500)); return 'status: ' + document.getElementById('status').textContent; })()"
drive context-lost "lab=shading" --frames 5 --eval "$lose" --wait-console "the WebGL context was lost"
grep -q "status: The browser took the page's WebGL context away.*Reload with the lab's own shaders" "$out/context-lost.log" ||
  { cat "$out/context-lost.log"; echo "a lost WebGL context was not reported in the page"; exit 1; }
echo "a lost WebGL context is reported, with a reload"
# A static host that sends no headers (GitHub Pages, a course site): the page registers its
# service worker (isolation.js), which adds the isolation headers, reloads once, and draws.
plain_port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$plain_port" --bind 127.0.0.1 --directory "$site" >"$out/plain-host-server.log" 2>&1 &
plain=$!
trap 'kill $server $course_server $plain 2>/dev/null || true' EXIT
for _ in $(seq 50); do grep -q "Serving HTTP" "$out/plain-host-server.log" 2>/dev/null && break; sleep 0.1; done
python3 "$repo/tools/web_driver.py" "http://127.0.0.1:$plain_port/index.html#lab=shading" --frames 10 --timeout 90 \
  --screenshot "$out/plain-host.png" >"$out/plain-host.log" 2>&1 || { cat "$out/plain-host.log"; echo "the page did not start on a host without headers"; exit 1; }
grep -q "GET /isolation.js" "$out/plain-host-server.log" || { echo "the page started without its service worker"; exit 1; }
echo "the page starts on a host that sends no headers (its service worker isolates it)"
echo "web test passed"
