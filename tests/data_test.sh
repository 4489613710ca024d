#!/usr/bin/env bash
# tools/get_data.sh against a local server on 127.0.0.1: a good file is fetched, a corrupted one
# (its bytes differ from the manifest's hash) is refused and leaves nothing behind, a second run
# keeps what is there; with the real data beside the project, the real manifest fetches every
# file, their hashes match, and the app finds the scenes in the folder it was given.
# usage: tests/data_test.sh SHADELAB [SHARED_DATA_DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
shadelab="$1"
shared="${2:-}"
tmp="$(mktemp -d)"
server=""
cleanup() { [ -n "$server" ] && kill "$server" 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Serves $1 on a free port of 127.0.0.1; sets $port.
serve() {
  [ -n "$server" ] && kill "$server" 2>/dev/null && wait "$server" 2>/dev/null || true
  python3 -m http.server --bind 127.0.0.1 --directory "$1" 0 >"$tmp/server.log" 2>&1 &
  server=$!
  for _ in $(seq 50); do
    port="$(sed -n 's/.*port \([0-9]*\).*/\1/p' "$tmp/server.log" | head -1)"
    [ -n "$port" ] && return 0
    sleep 0.1
  done
  fail "the local server did not start: $(cat "$tmp/server.log")"
}

mkdir -p "$tmp/mirror/meshes"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$tmp/mirror/meshes/good.off"
printf 'the original bytes\n' >"$tmp/original"
printf 'the bytes after tampering\n' >"$tmp/mirror/meshes/corrupted.off"
{
  echo "# test manifest"
  echo "$(sha256sum "$tmp/mirror/meshes/good.off" | cut -d' ' -f1)  meshes/good.off  https://example.invalid/good.off"
  echo "$(sha256sum "$tmp/original" | cut -d' ' -f1)  meshes/corrupted.off  https://example.invalid/corrupted.off"
} >"$tmp/manifest.txt"
serve "$tmp/mirror"

if "$root/tools/get_data.sh" --to "$tmp/out" --mirror "http://127.0.0.1:$port" --manifest "$tmp/manifest.txt" 2>"$tmp/err.txt"; then
  fail "a corrupted file must make get_data.sh exit non-zero"
fi
grep -q "refused meshes/corrupted.off: SHA-256 .*, expected " "$tmp/err.txt" || fail "no refusal named: $(cat "$tmp/err.txt")"
[ -f "$tmp/out/meshes/good.off" ] || fail "the good file was not fetched"
[ ! -e "$tmp/out/meshes/corrupted.off" ] || fail "the corrupted file was kept"
[ -z "$(find "$tmp/out" -name '*.part')" ] || fail "a partial download was left behind"
"$root/tools/get_data.sh" --to "$tmp/out" --mirror "http://127.0.0.1:$port" --manifest "$tmp/manifest.txt" \
  >"$tmp/again.txt" 2>/dev/null || true
grep -q "0 fetched, 1 already there, 1 refused" "$tmp/again.txt" || fail "second run: $(cat "$tmp/again.txt")"
echo "local manifest: good fetched, corrupted refused, second run kept the good file"

if [ -n "$shared" ] && [ -d "$shared" ]; then
  serve "$shared"
  "$root/tools/get_data.sh" --to "$tmp/real" --mirror "http://127.0.0.1:$port" >"$tmp/real.txt" ||
    fail "the real manifest against a copy of the data: $(cat "$tmp/real.txt")"
  n="$(grep -c '^[0-9a-f]\{64\} ' "$root/tools/data_manifest.txt")"
  grep -q "$n fetched, 0 already there, 0 refused" "$tmp/real.txt" || fail "real manifest: $(cat "$tmp/real.txt")"
  SHADELAB_DATA="$tmp/real" LIBGL_ALWAYS_SOFTWARE=1 "$shadelab" list >"$tmp/list.txt"
  grep -q "^  spot " "$tmp/list.txt" || fail "the app does not list spot from the fetched folder"
  grep -q "not here" "$tmp/list.txt" && fail "the app still says scenes are missing: $(grep 'not here' "$tmp/list.txt")"
  echo "real manifest: $n files fetched and verified; the app lists their scenes"
else
  echo "real manifest: skipped (no data folder beside the project)"
fi
SHADELAB_DATA="$tmp/empty" LIBGL_ALWAYS_SOFTWARE=1 "$shadelab" list >"$tmp/none.txt"
grep -q "tools/get_data.sh fetches them): spot, teapot" "$tmp/none.txt" || fail "without data, list does not say what is missing"
echo "passed"
