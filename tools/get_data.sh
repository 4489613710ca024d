#!/usr/bin/env bash
# Fetches the external meshes and textures the data scenes (spot, teapot, fandisk-0.3, ...), the
# surface lab's LearnOpenGL bricks and the data tests use: each file of tools/data_manifest.txt
# from its public source at a pinned commit, checked against its SHA-256. A file whose hash
# differs is refused (deleted, named, exit 1); a file already there with the right hash is kept.
#
# usage: tools/get_data.sh [--to DIR] [--mirror URL] [--manifest FILE]
#   --to DIR        where the files go (default: $SHADELAB_DATA, else data/ in this repository,
#                   which the app looks in after $SHADELAB_DATA and ../shared/data)
#   --mirror URL    fetch PATH from URL/PATH instead of each file's source (a course's own copy)
#   --manifest FILE another list in the same format
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
to="${SHADELAB_DATA:-$root/data}"
mirror=""
manifest="$root/tools/data_manifest.txt"
while [ $# -gt 0 ]; do
  case "$1" in
    --to) to="$2"; shift 2 ;;
    --mirror) mirror="${2%/}"; shift 2 ;;
    --manifest) manifest="$2"; shift 2 ;;
    *) echo "get_data: unknown option '$1' (valid: --to DIR, --mirror URL, --manifest FILE)" >&2; exit 2 ;;
  esac
done
[ -r "$manifest" ] || { echo "get_data: cannot read the manifest '$manifest'" >&2; exit 2; }
command -v curl >/dev/null || "$root/tools/install_deps.sh" data

have=0 fetched=0 refused=0
while read -r hash path url; do
  case "$hash" in ''|'#'*) continue ;; esac
  case "$path" in /*|*..*) echo "get_data: $manifest: '$path' must be a relative path inside the data folder" >&2; exit 2 ;; esac
  dest="$to/$path"
  if [ -f "$dest" ] && [ "$(sha256sum "$dest" | cut -d' ' -f1)" = "$hash" ]; then
    have=$((have + 1))
    continue
  fi
  source="${mirror:+$mirror/$path}"
  source="${source:-$url}"
  mkdir -p "$(dirname "$dest")"
  part="$dest.part"
  if ! curl -fsSL --retry 2 --max-time 300 -o "$part" "$source"; then
    rm -f "$part"
    echo "refused $path: could not download $source" >&2
    refused=$((refused + 1))
    continue
  fi
  got="$(sha256sum "$part" | cut -d' ' -f1)"
  if [ "$got" != "$hash" ]; then
    rm -f "$part"
    echo "refused $path: SHA-256 $got, expected $hash (from $source)" >&2
    refused=$((refused + 1))
    continue
  fi
  mv -f "$part" "$dest"
  fetched=$((fetched + 1))
  echo "fetched $path"
done < "$manifest"
echo "get_data: $fetched fetched, $have already there, $refused refused, in $to"
[ "$refused" -eq 0 ]
