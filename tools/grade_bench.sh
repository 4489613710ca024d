#!/usr/bin/env bash
# Grading a class: seconds per submission, measured side by side in one run.
#   tools/grade_bench.sh [BUILD_DIR] [STUDENTS] [EXERCISE] [SCOPE]  (defaults: build 6 shadows/pcf "one all")
# SCOPE "one" measures EXERCISE alone (a few minutes), without --all and the projection.
# A synthetic class of STUDENTS submissions (the solution, the starter and a seeded mistake in
# turn), graded for EXERCISE and for --all:
#   single   `grade --shaders` of one submission without the cache: how one student is graded alone
#   cold     `grade --class` with an empty cache (the solutions rendered once, then every student)
#   warm     the same again: the solutions from the cache
#   warm -j2 warm with --jobs 2
# each twice, side by side: with the rubrics as they are (their mistakes' frames drawn with the
# solution's) and with a copy of exercises/ whose rubrics list no mistakes (the starter alone), so
# the mistakes' share of the cost is read off one run;
# and a projection for 500 students x 6 exercises on one machine and on a 20-node array job
# (each node: one cold start of its own cache, then its share warm, at the best --jobs measured).
# Medians of 3 for the single grade of EXERCISE, one run each otherwise (a class run is itself
# an average over its students). Timings on a shared machine are noisy: compare ratios within
# one run, not across runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
students=${2:-6}
exercise=${3:-shadows/pcf}
scopes=${4:-one all}
case $scopes in "one" | "one all") ;; *) echo "grade_bench: SCOPE is 'one' or 'one all', not '$scopes'" >&2; exit 2 ;; esac
bin=$build/shadelab
[ -x "$bin" ] || { echo "grade_bench: no $bin; build first (cmake --build $build)" >&2; exit 2; }
export LIBGL_ALWAYS_SOFTWARE=1
work=$(mktemp -d /tmp/shadelab-grade-bench.XXXXXX)
trap 'chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT

# The class: every third a solution, a starter, a solution with its first shader file changed by a comment.
mkdir -p "$work/class"
for ((i = 1; i <= students; ++i)); do
  s=$(printf "student%03d" "$i")
  case $((i % 3)) in
    1) cp -r "$root/shaders" "$work/class/$s" ;;
    2) mkdir -p "$work/class/$s"; for d in "$root"/exercises/*/*/starter; do cp -r "$d"/. "$work/class/$s/"; done ;;
    0) cp -r "$root/shaders" "$work/class/$s"; echo "// edited" >> "$work/class/$s/common/lighting.glsl" ;;
  esac
done

now() { date +%s.%N; }
seconds() { python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.2f}')" "$1" "$2"; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
per() { python3 -c "import sys; print(f'{float(sys.argv[1]) / float(sys.argv[2]):.2f}')" "$1" "$2"; }
run() {  # run LABEL ARGS...: prints the wall seconds of `shadelab grade ARGS` (in a subshell: a fresh --out each)
  local t0 t1 label=$1 out
  shift
  out=$(mktemp -d "$work/out.XXXXXX")
  rmdir "$out"
  t0=$(now)
  "$bin" grade "$@" --out "$out" > "$out.log" 2>&1 || [ $? -eq 1 ] ||
    { echo "grade_bench: $label failed:" >&2; tail -5 "$out.log" >&2; exit 1; }
  t1=$(now)
  seconds "$t0" "$t1"
}

# The same exercises without their listed mistakes.
cp -r "$root/exercises" "$work/no-mistakes"
for rubric in "$work"/no-mistakes/*/*/rubric.json; do
  python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); r.pop("mistakes", None); json.dump(r, open(sys.argv[1], "w"))' "$rubric"
done

declare -A result
for rubrics in with without; do
if [ $rubrics = with ]; then unset SHADELAB_EXERCISES; else export SHADELAB_EXERCISES=$work/no-mistakes; fi
for scope in $scopes; do
  if [ $scope = one ]; then sel=(--exercise "$exercise"); label=$exercise; reps=3; else sel=(--all); label="--all"; reps=1; fi
  times=()
  for ((r = 0; r < reps; ++r)); do times+=("$(run single "${sel[@]}" --shaders "$work/class/student001" --no-cache)"); done
  result[$scope.single]=$(median "${times[@]}")
  rm -rf "$work/cache"
  result[$scope.cold]=$(per "$(run cold "${sel[@]}" --class "$work/class" --cache "$work/cache")" "$students")
  result[$scope.warm]=$(per "$(run warm "${sel[@]}" --class "$work/class" --cache "$work/cache")" "$students")
  result[$scope.warm2]=$(per "$(run warm2 "${sel[@]}" --class "$work/class" --cache "$work/cache" --jobs 2)" "$students")
  printf '\n%s, %d submissions, rubrics %s their mistakes (seconds per submission)\n' "$label" "$students" "$rubrics"
  printf '| single grade, no cache | class, cold cache | class, warm | class, warm, --jobs 2 | single / warm |\n|---|---|---|---|---|\n'
  printf '| %s | %s | %s | %s | %sx |\n' "${result[$scope.single]}" "${result[$scope.cold]}" "${result[$scope.warm]}" \
    "${result[$scope.warm2]}" "$(per "${result[$scope.single]}" "${result[$scope.warm]}")"
  for k in single cold warm warm2; do result[$rubrics.$scope.$k]=${result[$scope.$k]}; done
done
done
unset SHADELAB_EXERCISES
[ "$scopes" = one ] && exit 0
printf '\nWith the mistakes against without (same run): single %sx, cold %sx, warm %sx (--all)\n' \
  "$(per "${result[with.all.single]}" "${result[without.all.single]}")" "$(per "${result[with.all.cold]}" "${result[without.all.cold]}")" \
  "$(per "${result[with.all.warm]}" "${result[without.all.warm]}")"
for k in single cold warm warm2; do result[all.$k]=${result[with.all.$k]}; done

python3 - "${result[all.single]}" "${result[all.cold]}" "${result[all.warm]}" "${result[all.warm2]}" "$students" <<'EOF'
import sys
single, cold, warm, warm2, n = map(float, sys.argv[1:])
best = min(warm, warm2)
start = max(cold * n - warm * n, 0.0)  # the cold run's extra: rendering the solutions once
one = start + 500 * best
node = start + 25 * best
print(f"\nProjection, 500 students x 6 exercises (--all), at {best:.2f} s per submission warm:")
print(f"  one machine like this:  {one / 3600:.2f} h  (today's grade, one student at a time: {500 * single / 3600:.2f} h)")
print(f"  20-node array job:      {node / 60:.1f} min per node (25 students each, its own cold cache first)")
EOF
