#!/usr/bin/env bash
# Regenerates every figure of the tutorials from the headless renderer. Each command here is the
# one printed beside its figure. usage: tutorials/make_figures.sh [path/to/shadelab]
set -euo pipefail
cd "$(dirname "$0")/.."
sl=${1:-build/shadelab}
f=tutorials/figures
mkdir -p "$f"

# shading.md: one coarse sphere, three frequencies, and the reference
for mode in flat gouraud phong; do
  "$sl" render --scene sphere --set shading.tessellation=8 --set shading.mode=$mode --size 320x320 \
    --out $f/sphere_$mode.png
done
"$sl" render --scene sphere --set shading.tessellation=256 --set shading.mode=phong --size 320x320 \
  --out $f/sphere_reference.png

# shading.md: a sharp highlight between vertices
for mode in gouraud phong; do
  "$sl" render --scene sphere --set shading.tessellation=16 --set shading.mode=$mode --set shading.shininess=400 \
    --set shading.ks=1 --size 320x320 --out $f/highlight_$mode.png
done

# shading.md: Phong's and Blinn-Phong's lobes at one exponent, and Blinn-Phong at four times it
"$sl" render --scene sphere --set shading.specular=phong --set shading.shininess=32 --set shading.tessellation=64 \
  --size 320x320 --out $f/specular_phong_32.png
"$sl" render --scene sphere --set shading.specular=blinn-phong --set shading.shininess=32 \
  --set shading.tessellation=64 --size 320x320 --out $f/specular_blinn_32.png
"$sl" render --scene sphere --set shading.specular=blinn-phong --set shading.shininess=128 \
  --set shading.tessellation=64 --size 320x320 --out $f/specular_blinn_128.png

# shading.md: perspective-correct against affine UVs on a two-triangle floor
for uv in perspective affine; do
  "$sl" render --scene checker-plane --set shading.uv_interpolation=$uv --size 480x270 --out $f/checker_$uv.png
done

# shading.md: error against cost, the lab's standard sweep
"$sl" sweep --lab shading --size 640x360 --frames 9 --out build/tutorial-sweep
cp build/tutorial-sweep/shading_rmse.svg build/tutorial-sweep/shading_surface_rmse.svg \
  build/tutorial-sweep/shading_sweep.csv $f/
