#!/usr/bin/env bash
# Installs the Debian packages ShadeLab needs, if any are missing. Nothing else is downloaded.
# usage: tools/install_deps.sh [build|test|fuzz|data|web]
set -euo pipefail
build_pkgs=(cmake ninja-build g++ pkg-config python3 libglfw3-dev libglm-dev libimgui-dev libtinygltf-dev
  libtinyobjloader-dev libstb-dev nlohmann-json3-dev libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libbenchmark-dev libembree-dev libeigen3-dev libflann-dev liblz4-dev libopenmesh-dev libzip-dev)
test_pkgs=(xvfb xauth xdotool glslang-tools clang-format-14 python3-jsonschema git)  # glslang-tools:
# check-shaders --dialect es; clang-format-14: the style check (tools/check_format.sh);
# python3-jsonschema and git: the gradebooks' test (schemas, a Classroom 50 checkout)
fuzz_pkgs=(clang-14 libclang-rt-14-dev)  # libFuzzer and the sanitizer runtimes for clang
data_pkgs=(curl ca-certificates)          # tools/get_data.sh
# ./web.sh: emscripten, dpkg-dev for Dear ImGui's source package, and what the page's tests drive it with
web_pkgs=(emscripten dpkg-dev ninja-build python3 libglm-dev libtinygltf-dev libtinyobjloader-dev libstb-dev
  nlohmann-json3-dev libeigen3-dev libflann-dev liblz4-dev libgl-dev chromium glslang-tools)
want=("${build_pkgs[@]}")
case "${1:-build}" in
  build) ;;
  test) want+=("${test_pkgs[@]}" "${fuzz_pkgs[@]}" "${data_pkgs[@]}") ;;
  data) want=("${data_pkgs[@]}") ;;
  fuzz) want+=("${fuzz_pkgs[@]}") ;;
  web) want=("${web_pkgs[@]}") ;;
  *) echo "install_deps: unknown set '$1' (valid: build, test, fuzz, data, web)" >&2; exit 2 ;;
esac

missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null; then
  sudo=(sudo)
else
  echo "error: missing packages (${missing[*]}) and not root, and no sudo to install them" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
