#!/usr/bin/env bash
# Gradescope's setup.sh for a ShadeLab assignment (its Ubuntu image, run once when the
# autograder is built). The autograder zip holds this file, run_autograder, config.env, the
# ShadeLab source as shadelab/ and the course folder as course/ (see docs/courses.md).
set -euo pipefail
cd /autograder/source
apt-get update -qq
# What tools/install_deps.sh build installs on Debian, by Ubuntu's names; the grader draws through
# OSMesa (llvmpipe), so no GPU and no display are needed.
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends cmake ninja-build g++ pkg-config \
  python3 libglfw3-dev libglm-dev libimgui-dev libtinygltf-dev libtinyobjloader-dev libstb-dev nlohmann-json3-dev \
  libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgtest-dev libbenchmark-dev libembree-dev \
  libeigen3-dev libflann-dev liblz4-dev libopenmesh-dev libzip-dev
cmake -S shadelab -B shadelab-build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSHADELAB_BENCH=OFF > /dev/null
cmake --build shadelab-build --target shadelab
# The solution's side of the exercise (its frames, truths, listed mistakes and slips) drawn once,
# here, into the image: each submission then draws only the student's frames (run_autograder).
source /autograder/source/config.env
course=()
[ -d course ] && course=(--exercises course)
LIBGL_ALWAYS_SOFTWARE=1 shadelab-build/shadelab grade --prepare --exercise "$EXERCISE" "${course[@]}" \
  --cache solution-cache
