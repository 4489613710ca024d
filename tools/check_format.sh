#!/usr/bin/env bash
# The C++ sources against .clang-format (120 columns, Google style): names every file clang-format
# would change and exits 1; `tools/check_format.sh --fix` rewrites them instead.
# usage: tools/check_format.sh [--fix]
set -euo pipefail
cd "$(dirname "$0")/.."
format=clang-format-14  # one version: another formats some constructs differently
command -v "$format" >/dev/null || { echo "check_format: $format is missing (tools/install_deps.sh test)" >&2; exit 2; }
if [ -d .git ] && command -v git >/dev/null; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cpp' '*.h' | while read -r f; do [ -f "$f" ] && echo "$f"; done)
else
  mapfile -t files < <(find app labs tests bench tools -name '*.cpp' -o -name '*.h' | sort)
fi
if [ "${1:-}" = --fix ]; then
  "$format" -i "${files[@]}"
  exit 0
fi
# One clang-format per file, as many at a time as there are cores; each names its file if it fails.
check() { "$1" --dry-run -Werror "$2" >/dev/null 2>&1 || echo "$2: not formatted as .clang-format says (tools/check_format.sh --fix)"; }
export -f check
unformatted=$(printf '%s\0' "${files[@]}" | xargs -0 -n 1 -P "$(nproc)" bash -c 'check "$0" "$1"' "$format")
[ -z "$unformatted" ] && { echo "formatted: ${#files[@]} files"; exit 0; }
echo "$unformatted"
exit 1
