#!/usr/bin/env bash
# The grading step of a GitHub Classroom assignment (classroom.yml beside this file): grades the
# student's shaders/ (their files laid out like ShadeLab's shaders/) against $EXERCISE, with the
# course folder course/ where the repository has one, and hands the points to GitHub Classroom's
# grading reporter through the step's output `result` (base64 JSON, the reporter's format). The
# report itself goes to the job's log.
# Environment: SHADELAB (the binary), EXERCISE (lab/name), SHADERS (default shaders), COURSE
# (default course), GITHUB_OUTPUT (set by GitHub Actions).
set -uo pipefail
shadelab=${SHADELAB:?SHADELAB names the shadelab binary}
exercise=${EXERCISE:?EXERCISE names the exercise, lab/name}
shaders=${SHADERS:-shaders}
course=()
[ -d "${COURSE:-course}" ] && course=(--exercises "${COURSE:-course}")
out="$(mktemp -d)/report"
LIBGL_ALWAYS_SOFTWARE=1 "$shadelab" grade --exercise "$exercise" --shaders "$shaders" "${course[@]}" \
  --format classroom --out "$out" --no-cache
if [ -f "$out/classroom.json" ]; then
  json=$(cat "$out/classroom.json")
else  # the grader could not grade: an error the reporter shows, not an empty pass
  json='{"version": 1, "status": "error", "max_score": 0, "tests": []}'
fi
echo "result=$(printf '%s' "$json" | base64 -w0)" >> "${GITHUB_OUTPUT:?GITHUB_OUTPUT is set by GitHub Actions}"
[ -f "$out/report.md" ] && cat "$out/report.md"
exit 0
