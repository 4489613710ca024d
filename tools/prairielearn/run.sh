#!/usr/bin/env bash
# PrairieLearn's external grader entry point for a ShadeLab exercise (tools/prairielearn/Dockerfile).
# PrairieLearn mounts the job under /grade: the student's files in /grade/student, the course's
# shared files in /grade/serverFilesCourse; EXERCISE (LAB/NAME) comes from the question's
# externalGradingOptions.environment. The student's files are put where the exercise's rubric
# expects them (specular.glsl goes to common/specular.glsl; the placement `grade --class` does),
# graded with `--format prairielearn`, and /grade/results/results.json written: a score in
# [0, 1], a test per check, the failing configurations' pictures inline (under 1 MB in all), or
# "gradable": false with the reason when a file is missing or does not compile.
# GRADE_ROOT overrides /grade and SHADELAB the binary (local tests).
set -uo pipefail
root=${GRADE_ROOT:-/grade}
shadelab=${SHADELAB:-/opt/shadelab/build/shadelab}
mkdir -p "$root/results"
root=$(cd "$root" && pwd)  # absolute: the class folder links to it
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
# A class of one upload: `grade --class` puts each of the rubric's files where it expects them (by
# path, by name, by name in any case; a zip unpacked), the notes say what was taken, ignored or
# missing. From inside the work folder, so that an error names a short path, not a temporary one.
mkdir "$work/class"
ln -s "$root/student" "$work/class/student"
# The solutions the image drew when it was built (SOLUTION_CACHE overrides where, for local tests).
cache=(--no-cache)
solutions=${SOLUTION_CACHE:-/opt/shadelab/solution-cache}
[ -d "$solutions" ] && cache=(--cache "$solutions")
(cd "$work" && "$shadelab" grade --class class --exercise "$EXERCISE" "${course[@]}" --format prairielearn \
  --out report "${cache[@]}")
status=$?
[ -f "$work/report/students/student/grade.log" ] && cat "$work/report/students/student/grade.log"
if [ -f "$work/report/students/student/results.json" ]; then
  cp "$work/report/students/student/results.json" "$results"
else
  cannot_grade "shadelab grade exited with $status"
fi
rm -rf "$work"
