#!/usr/bin/env bash
# The figures a GPU gives, through EGL (a GPU server with no display): every lab's default frame
# at 1920x1080 with each pass's GPU time, the shadows lab's truth by Embree and by the GPU tracer
# side by side (BM_ShadowTruth), the GPU tracer's draws and walks of each size (BM_GpuTruthShape),
# the shadows frame beside a bare two-pass program, and the GL
# tests that hold the GPU tracer to Embree, run on the GPU's own driver.
#
#   tools/gpu_figures.sh [BUILD_DIR] [OUT_DIR]      (defaults: build, gpu-figures)
#
# BUILD_DIR is a build with the benchmarks and tests; on a server without X or OSMesa configure it
# with -DSHADELAB_OSMESA=OFF -DSHADELAB_WINDOW=OFF. Every step runs even if one fails; the exit
# status is non-zero if any did. Each step's output is in OUT_DIR/*.txt, the frames in OUT_DIR/*.png.
set -u
build=${1:-build}
out=${2:-gpu-figures}
mkdir -p "$out"
failed=0
step() {  # step NAME COMMAND...: run, keep its output, note a failure
  local name=$1
  shift
  echo "== $name: $*"
  if ! "$@" >"$out/$name.txt" 2>&1; then
    echo "   failed (exit $?), see $out/$name.txt"
    failed=1
  fi
  tail -n 40 "$out/$name.txt"
}

export SHADELAB_BACKEND=egl
for lab in shading shadows surface denoise filtering; do
  step "frame-$lab" "$build/shadelab" render --backend egl --lab "$lab" --size 1920x1080 --frames 20 \
    --out "$out/$lab.png"
done
step bench-shadow-truth "$build/bench/shadelab_bench" --benchmark_filter='BM_ShadowTruth|BM_ImageBuffer' \
  --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
step bench-gpu-truth-shape "$build/bench/shadelab_bench" --benchmark_filter='BM_GpuTruthShape' \
  --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
step bench-shadow-frame "$build/bench/shadelab_bench" \
  --benchmark_filter='BM_ShadowFrameworkOverhead|BM_ShadowFilter/0/' --benchmark_repetitions=3 \
  --benchmark_report_aggregates_only=true
step gl-tracer-agreement "$build/tests/gl_tests" --gtest_filter='Shadows.TheGpuTracer*'
exit $failed
