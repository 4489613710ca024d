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
bad=0
for f in "${files[@]}"; do
  if ! "$format" --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "$f: not formatted as .clang-format says (tools/check_format.sh --fix)"
    bad=1
  fi
done
[ $bad -eq 0 ] && echo "formatted: ${#files[@]} files"
exit $bad
