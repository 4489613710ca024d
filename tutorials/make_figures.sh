#!/usr/bin/env bash
# Regenerates the figures of the tutorials from the headless renderer. Each command here is the
# one printed beside its figure.
# usage: tutorials/make_figures.sh [path/to/shadelab] [shading] [shadows] [surface] [denoise] [filtering] (none named: all)
set -euo pipefail
cd "$(dirname "$0")/.."
sl=build/shadelab
if [ $# -gt 0 ] && [ -x "$1" ]; then sl=$1; shift; fi
labs=${*:-shading shadows surface denoise filtering}
f=tutorials/figures
mkdir -p "$f"

shading_figures() {
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

}

shadows_figures() {
# shadows.md: the path, step by step (each image 480x270; the errors and costs come from the sweeps below)
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
$r --set shadows.view=bias-heat --out $f/shadows_9_bias_heat.png
$r --set shadows.filter=hard --set shadows.bias=0.5 --set shadows.slope_bias=0 --set shadows.view=bias-heat \
  --out $f/shadows_9_bias_heat_low.png
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

# shadows.md: LearnOpenGL's scene at the chapter's 800x600, one 1024^2 map fitted to the scene, to
# the view, and cascades of the same memory (4 x 512^2)
l="$sl render --lab shadows --scene learnopengl --size 800x600 --set shadows.filter=hard"
$l --set shadows.map_size=1024 --set shadows.fit=scene --out $f/shadows_11_scene_fit.png
$l --set shadows.map_size=1024 --set shadows.fit=view --out $f/shadows_11_view_fit.png
$l --set shadows.map_size=512 --set shadows.fit=cascades --out $f/shadows_11_cascades.png
$l --set shadows.map_size=512 --set shadows.fit=cascades --set shadows.view=cascades --out $f/shadows_11_cascade_view.png
$l --set shadows.map_size=1024 --set shadows.fit=scene --set shadows.view=texel-density --out $f/shadows_11_density_scene.png
$l --set shadows.map_size=512 --set shadows.fit=cascades --set shadows.view=texel-density \
  --out $f/shadows_11_density_cascades.png
$l --set shadows.map_size=512 --set shadows.fit=cascades --set shadows.view=depth-linear --set shadows.depth_cascade=1 \
  --out $f/shadows_11_cascade1_map.png
"$sl" sweep --lab shadows --scene learnopengl --size 800x600 --frames 7 --set shadows.filter=hard \
  --set shadows.map_size=1024 --out build/tutorial-shadows-fit \
  --vary fit=scene,view,cascades:map_size=512,cascades:map_size=512:split_lambda=0,cascades:map_size=512:split_lambda=1,cascades:map_size=512:cascade_count=2,cascades:map_size=1024
cp build/tutorial-shadows-fit/shadows_sweep.csv $f/shadows_fit.csv

# shadows.md: filtered maps (moments of depth, blurred and mipmapped) beside PCF and PCSS
$r --set shadows.filter=vsm --set shadows.light_radius=0.12 --out $f/shadows_12_vsm.png
$r --set shadows.filter=esm --set shadows.light_radius=0.12 --out $f/shadows_12_esm.png
$r --set shadows.filter=evsm --set shadows.light_radius=0.12 --out $f/shadows_12_evsm.png
$l --set shadows.map_size=512 --set shadows.fit=cascades --set shadows.filter=evsm \
  --camera "yaw=-30,pitch=35,distance=4,target=1.5;0;1,fov=45,near=0.1,far=100" --out $f/shadows_12_evsm_cascades.png
"$sl" sweep --lab shadows --size 960x540 --frames 7 --set shadows.light_radius=0.12 --out build/tutorial-shadows-filtered \
  --vary filter=hard,pcf:pcf_size=5,pcss,vsm,vsm:bleed_reduction=0,vsm:blur_radius=6,esm,esm:esm_exponent=20,evsm,evsm:moment_mips=off
cp build/tutorial-shadows-filtered/shadows_sweep.csv $f/shadows_filtered.csv

# shadows.md: the standard sweep (filter x map size x bias), one front per truth
"$sl" sweep --lab shadows --size 960x540 --frames 5 --out build/tutorial-shadows
cp build/tutorial-shadows/shadows_visibility_rmse_hard.svg build/tutorial-shadows/shadows_visibility_rmse_area.svg \
  build/tutorial-shadows/shadows_misclassified_pct.svg build/tutorial-shadows/shadows_sweep.csv $f/
}

surface_figures() {
# surface.md: the wall, step by step (each 480x270 with --measure; the numbers quoted are printed by these)
local r="$sl render --lab surface --size 480x270 --measure"
$r --set surface.technique=none --out $f/surface_1_none.png
$r --set surface.technique=normal-map --out $f/surface_2_normal_map.png
$r --set surface.technique=normal-map --set surface.decoding=srgb --out $f/surface_3_srgb.png
$r --set surface.technique=normal-map --set surface.green=directx --out $f/surface_3_directx.png
$r --set surface.technique=normal-map --set surface.add_to_old_normal=on --out $f/surface_3_added.png
$r --set surface.technique=normal-map --set surface.view=normals --out $f/surface_4_normal_map_normals.png
$r --set surface.technique=truth --set surface.view=normals --out $f/surface_4_truth_normals.png
$r --set surface.technique=bump --out $f/surface_5_bump.png
$r --set surface.technique=bump --set surface.bump_form=games101 --out $f/surface_5_bump_games101.png
$r --set surface.technique=displacement --set surface.subdivision=3 --out $f/surface_6_displacement_3.png
$r --set surface.technique=displacement --set surface.subdivision=7 --out $f/surface_6_displacement_7.png
$r --set surface.technique=displacement --set surface.subdivision=7 --set surface.displaced_normals=unchanged \
  --out $f/surface_6_displacement_unchanged.png
$r --set surface.technique=tessellation --set surface.tess_level=64 --out $f/surface_6_tessellation_64.png
$r --set surface.technique=parallax --out $f/surface_7_parallax.png
$r --set surface.technique=steep-parallax --set surface.layers=8 --out $f/surface_7_steep_8.png
$r --set surface.technique=pom --out $f/surface_7_pom.png
local close="yaw=60,pitch=8,distance=0.45,target=0.4;0.1;0"
$r --set surface.technique=steep-parallax --set surface.layers=8 --camera "$close" --out $f/surface_7_steep_8_close.png
$r --set surface.technique=pom --camera "$close" --out $f/surface_7_pom_close.png
$r --set surface.technique=pom --set surface.self_shadow=on --out $f/surface_7_pom_shadow.png
$r --set surface.technique=truth --out $f/surface_7_truth.png
$r --set surface.technique=truth --set surface.self_shadow=on --out $f/surface_7_truth_shadow.png
# surface.md: a brick floor at a grazing angle, where parallax is hardest
local g="$sl render --lab surface --scene bricks-grazing --size 480x270 --measure"
$g --set surface.technique=parallax --out $f/surface_8_grazing_parallax.png
$g --set surface.technique=steep-parallax --set surface.layers=8 --out $f/surface_8_grazing_steep_8.png
$g --set surface.technique=pom --set surface.layers=32 --out $f/surface_8_grazing_pom_32.png
$g --set surface.technique=truth --out $f/surface_8_grazing_truth.png
# surface.md: tangent frames (no measure: these are diagnostic views)
local t="$sl render --lab surface --size 480x270"
$t --scene bricks-sphere --set surface.overlay=on --set surface.technique=normal-map --out $f/surface_9_sphere_frames.png
$t --scene spot-bricks --set surface.view=tangent-angle --out $f/surface_9_spot_tangent_angle.png
$t --scene uv-trouble --set surface.overlay=on --set surface.technique=normal-map --camera "yaw=0,pitch=55,distance=1.5" \
  --out $f/surface_9_uv_trouble.png
# surface.md: error against cost, the standard sweep (every technique and its knob) at 960x540
"$sl" sweep --lab surface --frames 5 --out build/tutorial-surface
cp build/tutorial-surface/surface_rmse.svg build/tutorial-surface/surface_normal_angle_deg.svg \
  build/tutorial-surface/surface_silhouette_pct.svg build/tutorial-surface/surface_sweep.csv $f/
# surface.md: how deep can relief be before a normal map is not enough? (the map's strength follows the depth)
"$sl" sweep --lab surface --frames 3 --out build/tutorial-surface-depth \
  --vary technique=normal-map,pom \
  --vary height_scale=0.005:normal_strength=0.125,0.01:normal_strength=0.25,0.02:normal_strength=0.5,0.04:normal_strength=1
cp build/tutorial-surface-depth/surface_sweep.csv $f/surface_depth_sweep.csv
}

denoise_figures() {
# denoise.md: Fandisk with its published noise, then each method (each image 480x360)
local d="$sl render --lab denoise --size 480x360 --measure"
$d --set denoise.show=noisy --out $f/denoise_1_noisy.png
$d --out $f/denoise_2_explicit.png
$d --set denoise.view=error --out $f/denoise_3_explicit_error.png
$d --set denoise.iterations=60 --out $f/denoise_3_oversmoothed.png
$d --set denoise.along_normal=off --set denoise.lambda=1.5 --set denoise.iterations=40 --out $f/denoise_4_diverging.png
$d --set denoise.method=implicit --set denoise.lambda=1000 --set denoise.iterations=1 --out $f/denoise_5_implicit_1000.png
$d --set denoise.method=taubin --set denoise.lambda=0.6 --out $f/denoise_5_taubin.png
$d --set denoise.method=bilateral --out $f/denoise_6_bilateral.png
$d --set denoise.method=bilateral --set denoise.view=error --out $f/denoise_6_bilateral_error.png
# denoise.md: the seam crack and its fix, on the seamed cube (generated noise) and on Spot
local c="$sl render --lab denoise --scene denoise-cube --size 720x300 --measure --set denoise.input=generated"
$c --set denoise.show=compare --set denoise.weld=off --set denoise.view=seam-gap --set denoise.heat_scale=0.3 \
  --camera "yaw=135,pitch=32,distance=2.6" --out $f/denoise_7_weld_off.png
$c --set denoise.show=compare --set denoise.view=seam-gap --set denoise.heat_scale=0.3 \
  --camera "yaw=135,pitch=32,distance=2.6" --out $f/denoise_7_weld_on.png
local s="$sl render --lab denoise --scene spot --size 720x300 --measure --set denoise.show=compare --set denoise.view=seam-gap --camera yaw=150,pitch=15,distance=2.05"
$s --set denoise.heat_scale=0.1 --set denoise.bake=nearest-exact --set denoise.map_size=256 --out $f/denoise_8_nearest_256.png
$s --set denoise.heat_scale=0.1 --set denoise.bake=raster --set denoise.map_size=256 --out $f/denoise_8_raster_256.png
# denoise.md: error against time, the standard sweep (methods x their knob x iterations) on Fandisk
"$sl" sweep --lab denoise --size 480x360 --frames 3 --out build/tutorial-denoise
cp build/tutorial-denoise/denoise_angle_error_deg.svg build/tutorial-denoise/denoise_rms_distance.svg \
  build/tutorial-denoise/denoise_sweep.csv $f/
# denoise.md: bake error against bake time on Spot, by method and resolution; FLANN's checks
"$sl" sweep --lab denoise --scene spot --size 480x360 --frames 1 --out build/tutorial-denoise-bake \
  --vary bake=nearest-exact,raster --vary map_size=64,256,1024,4096
cp build/tutorial-denoise-bake/denoise_bake_rms.svg $f/denoise_bake_rms.svg
cp build/tutorial-denoise-bake/denoise_sweep.csv $f/denoise_bake_sweep.csv
"$sl" sweep --lab denoise --scene spot --size 480x360 --frames 1 --out build/tutorial-denoise-checks \
  --set denoise.bake=nearest-approx --set denoise.map_size=1024 --vary checks=1,2,4,8,32,128
cp build/tutorial-denoise-checks/denoise_sweep.csv $f/denoise_checks_sweep.csv
}

filtering_figures() {
# filtering.md: the grazing plane, filter by filter (480x270, no probe ring)
r="$sl render --lab filtering --size 480x270 --set filtering.footprint_probe=off"
$r --set filtering.filter=nearest --set filtering.mipmaps=off --out $f/filtering_1_nearest.png
$r --set filtering.filter=bilinear --set filtering.mipmaps=off --out $f/filtering_2_bilinear.png
$r --set filtering.mipmaps=nearest-level --out $f/filtering_3_mip_nearest.png
$r --set filtering.mipmaps=nearest-level --set filtering.view=mip-level --out $f/filtering_3_mip_nearest_levels.png
$r --out $f/filtering_4_trilinear.png
$r --set filtering.view=mip-level --out $f/filtering_4_trilinear_levels.png
$r --set filtering.anisotropy=16 --out $f/filtering_5_anisotropic.png
$r --set filtering.anisotropy=16 --set filtering.view=mip-level --out $f/filtering_5_anisotropic_levels.png
$r --set filtering.view=anisotropy --out $f/filtering_5_anisotropy_view.png
$r --set filtering.lod_bias=2 --out $f/filtering_6_bias_plus_2.png
$r --set filtering.lod_bias=-2 --out $f/filtering_6_bias_minus_2.png

# filtering.md: magnification, a 16 x 16 texture over the screen
for filter in nearest bilinear bicubic; do
  $r --scene magnify --set filtering.filter=$filter --out $f/filtering_magnify_$filter.png
done

# filtering.md: the zone plate to the horizon, bilinear without levels and trilinear with each chain
$r --scene grazing-zoneplate --set filtering.mipmaps=off --out $f/filtering_zoneplate_no_mips.png
for chain in box kaiser; do
  $r --scene grazing-zoneplate --set filtering.downsampler=$chain --out $f/filtering_zoneplate_$chain.png
done

# filtering.md: error against cost, the lab's standard sweep, and the two chains' tables
"$sl" sweep --lab filtering --size 960x540 --frames 5 --set filtering.footprint_probe=off --out build/tutorial-filtering
cp build/tutorial-filtering/filtering_rmse.svg build/tutorial-filtering/filtering_flicker.svg \
  build/tutorial-filtering/filtering_sweep.csv $f/
for chain in box kaiser; do
  "$sl" render --lab filtering --scene grazing-zoneplate --size 480x270 --set filtering.downsampler=$chain \
    --out build/tutorial-filtering/chain_$chain.png
  cp build/tutorial-filtering/chain_$chain.json $f/filtering_chain_$chain.json
done
}

for lab in $labs; do
  case $lab in
    shading) shading_figures ;;
    shadows) shadows_figures ;;
    surface) surface_figures ;;
    denoise) denoise_figures ;;
    filtering) filtering_figures ;;
    *) echo "make_figures.sh: unknown lab '$lab' (valid: shading, shadows, surface, denoise, filtering)" >&2; exit 1 ;;
  esac
done
