#!/usr/bin/env bash
# PrairieLearn's external grader entry point for a ShadeLab exercise (tools/prairielearn/Dockerfile).
# PrairieLearn mounts the job under /grade: the student's files in /grade/student, the course's
# shared files in /grade/serverFilesCourse; EXERCISE (LAB/NAME) comes from the question's
# externalGradingOptions.environment. The student's files are put where the exercise's rubric
# expects them (by name: specular.glsl goes to common/specular.glsl), graded with
# `shadelab grade --format prairielearn`, and /grade/results/results.json written: a score in
# [0, 1], a test per check, the failing configurations' pictures inline (under 1 MB in all), or
# "gradable": false with the reason when a file is missing or does not compile.
# GRADE_ROOT overrides /grade and SHADELAB the binary (local tests).
set -uo pipefail
root=${GRADE_ROOT:-/grade}
shadelab=${SHADELAB:-/opt/shadelab/build/shadelab}
mkdir -p "$root/results"
results=$root/results/results.json
cannot_grade() {  # the grader could not run: the student is not charged an attempt
  python3 - "$results" "$1" <<'PY'
import json, sys
json.dump({"gradable": False, "format_errors": ["The grader could not run: " + sys.argv[2]],
           "message": "Your instructor has the grader's log."}, open(sys.argv[1], "w"))
PY
  echo "$1" >&2
  exit 0
}
[ -n "${EXERCISE:-}" ] || cannot_grade "EXERCISE is not set (externalGradingOptions.environment)"
course=()
[ -d "$root/serverFilesCourse/shadelab-course" ] && course=(--exercises "$root/serverFilesCourse/shadelab-course")
work=$(mktemp -d)
# The rubric's files, placed by name: an upload is flat, the exercise's files live in folders.
python3 - "$shadelab" "$EXERCISE" "$root/student" "$work/shaders" "${course[@]}" <<'PY' ||
import json, pathlib, shutil, subprocess, sys
shadelab, exercise, student, shaders = sys.argv[1:5]
roots = [pathlib.Path(sys.argv[6])] if len(sys.argv) > 6 else []
roots.append(pathlib.Path(shadelab).resolve().parent.parent / "exercises")
rubric = next((r / exercise / "rubric.json" for r in roots if (r / exercise / "rubric.json").is_file()), None)
if rubric is None:
    sys.exit(f"no exercise {exercise} in " + ", ".join(str(r) for r in roots))
for name in json.loads(rubric.read_text())["files"]:
    found = [p for p in pathlib.Path(student).rglob(pathlib.Path(name).name) if p.is_file()]
    if found:
        target = pathlib.Path(shaders) / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(found[0], target)
PY
  cannot_grade "the exercise $EXERCISE could not be read"
mkdir -p "$work/shaders"
# From inside the work folder, so that an error names shaders/common/specular.glsl, not a temporary path.
(cd "$work" && "$shadelab" grade --exercise "$EXERCISE" --shaders shaders "${course[@]}" --format prairielearn \
  --out report --no-cache)
status=$?
if [ -f "$work/report/results.json" ]; then
  cp "$work/report/results.json" "$results"
else
  cannot_grade "shadelab grade exited with $status"
fi
rm -rf "$work"
