#!/usr/bin/env bash
# Fuzzes one reader of outside input with libFuzzer (clang, AddressSanitizer, UBSan).
#
#   tools/fuzz.sh TARGET SECONDS     build if needed, replay the seeds and kept regressions, then fuzz
#   tools/fuzz.sh --build            build every target into build-fuzz/ (./test.sh does this)
#   tools/fuzz.sh --list             the targets
#   tools/fuzz.sh TARGET SECONDS --ci   no build; what ctest runs (label fuzz)
#
# Targets are tests/fuzz/fuzz_<TARGET>.cpp. Seeds: tests/fuzz/seeds/<TARGET>/; inputs that once
# crashed, hung or leaked: tests/fuzz/regressions/<TARGET>/ (every one is replayed first). New
# inputs go to build-fuzz/corpus/<TARGET>/, findings to build-fuzz/findings/<TARGET>/: a finding
# is fixed, then its input is copied into regressions/. A hang is an input over 1 s; memory is
# capped at 2 GiB resident and 512 MiB per allocation. SHADELAB_FUZZ_RUNS=N also stops after N
# executions, whichever comes first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADELAB_FUZZ_BUILD:-$root/build-fuzz}
targets=$(sed -n 's/^set(SHADELAB_FUZZ_TARGETS \(.*\))$/\1/p' "$root/tests/fuzz/targets.cmake")

build_all() {
  "$root/tools/install_deps.sh" fuzz
  # -O1 and line tables only: what AddressSanitizer's reports need (file and line), at half the
  # build time of -O2 -g (rubric.cpp: 56 s -> 27 s).
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
    -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
    -DSHADELAB_FUZZ=ON -DSHADELAB_TESTS=OFF -DSHADELAB_BENCH=OFF -DSHADELAB_WINDOW=OFF >/dev/null
  cmake --build "$build" --target "${1:-fuzzers}"
}

case "${1:-}" in
  --list) echo "$targets"; exit 0 ;;
  --build) build_all; exit 0 ;;
  ""|-h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
esac
target=$1 seconds=${2:-}
ci=false
[ "${3:-}" = --ci ] && ci=true
if ! grep -qw -- "$target" <<<"$targets"; then
  echo "fuzz: unknown target '$target' (valid: $(echo $targets | sed 's/ /, /g'))" >&2
  exit 2
fi
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "fuzz: SECONDS must be a whole number of seconds >= 1, not '$seconds'" >&2
  exit 2
fi
bin=$build/tests/fuzz/fuzz_$target
if $ci; then
  [ -x "$bin" ] || { echo "fuzz: $bin is not built (./test.sh or tools/fuzz.sh --build builds it)" >&2; exit 1; }
else
  build_all "fuzz_$target"
fi

seeds=$root/tests/fuzz/seeds/$target regressions=$root/tests/fuzz/regressions/$target
corpus=$build/corpus/$target findings=$build/findings/$target
mkdir -p "$corpus" "$findings"
dict=()
[ -f "$root/tests/fuzz/$target.dict" ] && dict=(-dict="$root/tests/fuzz/$target.dict")
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
limits=(-timeout=1 -rss_limit_mb=2048 -malloc_limit_mb=512 -max_len=65536)
# ctest shares the machine with other tests: a CI hang is an input over 3 s, not 1 s.
$ci && limits[0]=-timeout=3

# 1. Every kept input once: seeds, and the regressions that each once found a bug.
replay=()
for d in "$seeds" "$regressions"; do
  [ -d "$d" ] && while IFS= read -r -d '' f; do replay+=("$f"); done < <(find "$d" -type f -print0 | sort -z)
done
if [ ${#replay[@]} -gt 0 ]; then
  "$bin" "${limits[@]}" "${replay[@]}" >"$findings/replay.log" 2>&1 ||
    { tail -40 "$findings/replay.log"; echo "fuzz $target: a kept input fails (log: $findings/replay.log)" >&2; exit 1; }
  echo "fuzz $target: ${#replay[@]} kept inputs replayed, all pass"
fi

# 2. Fresh fuzzing from the corpus so far, the seeds and the regressions.
# New inputs are written to the first folder only, so the source tree is never written.
dirs=("$corpus")
for d in "$seeds" "$regressions"; do [ -d "$d" ] && dirs+=("$d"); done
log=$findings/fuzz-$(date +%Y%m%d-%H%M%S).log
set +e
runs=()
[ -n "${SHADELAB_FUZZ_RUNS:-}" ] && runs=(-runs="$SHADELAB_FUZZ_RUNS")
"$bin" "${limits[@]}" "${dict[@]}" "${runs[@]}" -max_total_time="$seconds" -print_final_stats=1 \
  -artifact_prefix="$findings/" "${dirs[@]}" >"$log" 2>&1
rc=$?
set -e
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1)
took=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
echo "fuzz $target: ${runs:-?} executions in ${took:-$seconds} s, ${cov:-cov: ?}, corpus $(ls "$corpus" | wc -l) inputs (log: $log)"
if [ $rc -ne 0 ]; then
  grep -E "ERROR: |SUMMARY: |Test unit written|^==[0-9]+==" "$log" | head -20
  echo "fuzz $target: found a failure; the input is in $findings/" >&2
  exit 1
fi
