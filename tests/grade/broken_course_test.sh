#!/usr/bin/env bash
# A broken course is refused by `exercise check`, each exercise with its reason: a parameter the
# lab does not have, a starter that does not compile, a check the solution itself cannot pass.
# The course is made here from the built-in shading/blinn-phong (its first two configurations, no
# mistakes), three copies each broken one way, so it follows that exercise as it changes.
# usage: broken_course_test.sh SHADELAB REPO OUT_DIR
set -euo pipefail
shadelab=$1 repo=$2 out=$3
mkdir -p "$out"
course=$out/broken_course
rm -rf "$course"
python3 - "$repo/exercises/shading/blinn-phong" "$course/shading" <<'PY'
import json, os, shutil, sys
source, shading = sys.argv[1:]
def exercise(name, breaks):
    folder = os.path.join(shading, name)
    shutil.copytree(source, folder)
    rubric = json.load(open(os.path.join(folder, "rubric.json")))
    rubric["title"] = "A broken exercise: " + name
    rubric["configurations"] = rubric["configurations"][:2]
    rubric["mistakes"], rubric["correct"] = [], []
    starter = os.path.join(folder, "starter", "common", "specular.glsl")
    text = open(starter).read().replace("exercise shading/blinn-phong", "exercise shading/" + name)
    text = breaks(rubric, text)
    open(starter, "w").write(text)
    json.dump(rubric, open(os.path.join(folder, "rubric.json"), "w"), indent=2)
def bad_key(rubric, text):
    rubric["configurations"][0]["set"]["bogus"] = 1
    return text
def unreachable(rubric, text):  # the truth check asks for an exact match: the solution cannot give one
    checks = {c["name"]: c for c in rubric["configurations"][0]["checks"]}
    checks["highlight"]["partial"] = 0.02
    checks["against the truth"]["full"] = checks["against the truth"]["partial"] = 0
    return text
def no_build(rubric, text):
    assert "  return 0.0;\n" in text
    return text.replace("  return 0.0;\n", "  return 0.0  // the semicolon is missing\n")
exercise("bad-key", bad_key)
exercise("unreachable", unreachable)
exercise("no-build", no_build)
PY
status=0
LIBGL_ALWAYS_SOFTWARE=1 "$shadelab" exercise check "$course" >"$out/broken_course.log" 2>&1 || status=$?
cat "$out/broken_course.log"
[ "$status" -eq 1 ] || { echo "exercise check exited $status on a broken course, not 1"; exit 1; }
for reason in "unknown parameter 'shading.bogus'" "mistake 'starter' does not build" \
  "scores 77.77778 %, not 100 %" "exercise check: 3 exercises, 3 not ready"; do
  grep -qF "$reason" "$out/broken_course.log" || { echo "missing from the refusal: $reason"; exit 1; }
done
echo "the broken course is refused with each exercise's reason"
