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

#
# shadows.md: the path, step by step (each image 480x270; the errors and costs come from the sweep below)
r="$sl render --lab shadows --size 480x270"
$r --set shadows.filter=hard --set shadows.bias=0 --set shadows.slope_bias=0 --out $f/shadows_1_acne.png
$r --set shadows.filter=hard --out $f/shadows_2_bias.png
$r --set shadows.filter=hard --set shadows.bias=45 --set shadows.slope_bias=0 \
  --camera "yaw=60,pitch=22,distance=3.2,target=-1;0.3;-2.2" --out $f/shadows_3_peter_panning.png
$r --set shadows.filter=hard --camera "yaw=60,pitch=22,distance=3.2,target=-1;0.3;-2.2" --out $f/shadows_3_contact.png
$r --set shadows.filter=hard --set shadows.auto_fit=off --set shadows.ortho_extent=0.45 --set shadows.near=1 \
  --set shadows.far=3 --set shadows.border_clamp=off --out $f/shadows_4_edge_clamp.png
$r --set shadows.filter=hard --set shadows.auto_fit=off --set shadows.ortho_extent=0.45 --set shadows.near=1 \
  --set shadows.far=3 --out $f/shadows_4_border_clamp.png
$r --set shadows.filter=hard --set shadows.auto_fit=off --set shadows.near=1 --set shadows.far=2.3 \
  --set shadows.far_fix=off --out $f/shadows_5_far_plane.png
$r --set shadows.filter=hard --set shadows.auto_fit=off --set shadows.near=1 --set shadows.far=2.3 \
  --out $f/shadows_5_far_fix.png
$r --set shadows.filter=pcf --set shadows.pcf_size=5 --out $f/shadows_6_pcf5.png
$r --set shadows.filter=poisson --set shadows.filter_radius=3 --out $f/shadows_7_poisson.png
$r --set shadows.filter=pcss --set shadows.light_radius=0.12 --out $f/shadows_8_pcss.png
$r --set shadows.filter=pcss --set shadows.light_radius=0.12 --set shadows.view=pcss-penumbra --out $f/shadows_8_penumbra.png
$r --set shadows.filter=hard --set shadows.bias=0.5 --set shadows.slope_bias=0 --set shadows.view=bias-heat \
  --out $f/shadows_9_bias_heat.png
$r --set shadows.view=texel-density --set shadows.map_size=512 --out $f/shadows_9_texel_density.png
$r --set shadows.view=depth-linear --out $f/shadows_9_depth_map.png
$r --set shadows.light_type=point --set shadows.light_distance=1.2 --set shadows.view=depth-linear \
  --out $f/shadows_9_cube_map.png
$r --set shadows.light_type=point --set shadows.light_distance=1.2 --set shadows.filter=pcss \
  --set shadows.light_radius=0.05 --out $f/shadows_10_point_pcss.png
$r --set shadows.light_type=spot --set shadows.fill_light=on --set shadows.filter=pcss --out $f/shadows_10_spot_fill.png

# shadows.md: the same path, measured against ray-traced visibility
"$sl" sweep --lab shadows --size 960x540 --frames 7 --out build/tutorial-shadows-path \
  --vary filter=hard:bias=0:slope_bias=0,hard,hard:bias=45:slope_bias=0,hardware-pcf,pcf:pcf_size=3,pcf:pcf_size=5,pcf:pcf_size=5:receiver_plane=off,poisson,pcss
cp build/tutorial-shadows-path/shadows_sweep.csv $f/shadows_path.csv
# shadows.md: the standard sweep (filter x map size x bias)
"$sl" sweep --lab shadows --size 960x540 --frames 5 --out build/tutorial-shadows
cp build/tutorial-shadows/shadows_misclassified_pct.svg build/tutorial-shadows/shadows_visibility_rmse.svg \
  build/tutorial-shadows/shadows_sweep.csv $f/
