#!/usr/bin/env bash
# tools/github-classroom/grade.sh on a fake student repository (no network, no GitHub): the step's
# output decoded and checked as GitHub Classroom's grading reporter reads it.
# usage: classroom_test.sh SHADELAB_BINARY REPO OUT_DIR
set -euo pipefail
shadelab=$(realpath "$1") repo=$2 out=$3
rm -rf "$out" && mkdir -p "$out/student/shaders/common"
cp "$repo/exercises/shading/blinn-phong/starter/common/specular.glsl" "$out/student/shaders/common/"
touch "$out/github_output"
(cd "$out/student" && SHADELAB=$shadelab EXERCISE=shading/blinn-phong GITHUB_OUTPUT="$out/github_output" \
  "$repo/tools/github-classroom/grade.sh" > "$out/log.txt" 2>&1) || { cat "$out/log.txt"; echo "grade.sh failed"; exit 1; }
python3 - "$out/github_output" <<'PY'
import base64, json, sys
line = [l for l in open(sys.argv[1]) if l.startswith("result=")][-1]
r = json.loads(base64.b64decode(line[len("result="):].strip()))
assert r["status"] in ("pass", "fail"), r["status"]
assert isinstance(r["max_score"], (int, float)) and r["max_score"] > 0, "max_score is the exercise's points"
assert r["tests"], "a test per check"
for t in r["tests"]:
    assert isinstance(t["name"], str) and t["name"], t
    assert t["status"] in ("pass", "fail"), t
    assert isinstance(t["score"], (int, float)) and t["score"] >= 0, t
total = sum(t["score"] for t in r["tests"])
assert total <= r["max_score"], (total, r["max_score"])
assert r["status"] == "fail", "the starter does not pass"
print("passed: the reporter's result with", len(r["tests"]), "tests,", total, "of", r["max_score"], "points")
PY
