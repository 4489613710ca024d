#!/usr/bin/env bash
# How the grader does on mistakes no rubric lists: every exercise with a set in
# tests/grade/unlisted/ checked (`shadelab exercise check ID --unlisted ...`), each mistake's
# verdict (named with its cause, unnamed, named wrongly, passes), then the totals.
#   tools/unlisted_report.sh [SHADELAB]     default build/shadelab
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shadelab=${1:-$root/build/shadelab}
sets=$root/tests/grade/unlisted
export LIBGL_ALWAYS_SOFTWARE=1
total=0 named=0 unnamed=0 wrong=0 passes=0
for file in "$sets"/*/*.json; do
  id=${file#"$sets"/}
  id=${id%.json}
  out=$("$shadelab" exercise check "$id" --unlisted "$sets" 2>&1 || true)
  printf '%s\n' "$id"
  while read -r _ name verdict explanation; do
    printf '  %-36s %-8s %s\n' "$name" "$verdict" "$explanation"
    total=$((total + 1))
    case $verdict in named) named=$((named + 1)) ;; unnamed) unnamed=$((unnamed + 1)) ;;
      wrong) wrong=$((wrong + 1)) ;; passes) passes=$((passes + 1)) ;; esac
  done < <(grep -E '^ +unlisted [^ ]+ +(named|unnamed|wrong|passes)' <<<"$out")
  grep -E '^(ok|FAIL) ' <<<"$out" | sed 's/^/  /'
done
echo "unlisted: $total mistakes: $named named with their cause, $unnamed unnamed, $wrong named wrongly, $passes passing"
