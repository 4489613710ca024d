#!/usr/bin/env bash
# tools/gradescope/run_autograder on a fake /autograder tree (no network, no Gradescope): a
# student's upload graded, and results.json checked against the autograder specification.
# usage: gradescope_test.sh SHADELAB_BINARY REPO OUT_DIR
set -euo pipefail
shadelab=$1 repo=$2 out=$3
rm -rf "$out" && mkdir -p "$out/source" "$out/submission/common"
echo "EXERCISE=shading/blinn-phong" > "$out/source/config.env"
cp "$repo/exercises/shading/blinn-phong/starter/common/specular.glsl" "$out/submission/common/"
AUTOGRADER=$out SHADELAB=$shadelab "$repo/tools/gradescope/run_autograder" > "$out/log.txt" 2>&1 ||
  { cat "$out/log.txt"; echo "run_autograder failed"; exit 1; }
python3 - "$out/results/results.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert isinstance(r["score"], (int, float)), "score is a number"
assert isinstance(r["tests"], list) and r["tests"], "tests is a non-empty list"
visible = {"visible", "hidden", "after_due_date", "after_published"}
for t in r["tests"]:
    assert isinstance(t["name"], str) and t["name"], t
    assert 0 <= t["score"] <= t["max_score"], t
    assert t["status"] in ("passed", "failed"), t
    assert t["visibility"] in visible, t
assert abs(sum(t["score"] for t in r["tests"]) - r["score"]) < 1e-9, "the tests' scores sum to the score"
assert "the TODO region still holds its placeholder" in r["output"], "the starter is told it is the starter"
print("passed: results.json with", len(r["tests"]), "tests, score", r["score"])
PY
