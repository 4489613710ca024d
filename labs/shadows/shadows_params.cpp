// The shadows lab's parameters: one visit function per section of the panel, each given its own
// part of ShadowsParams (and what of the others decides whether its parameters apply).
#include <cmath>

#include <glm/glm.hpp>

#include "app/lab/technique.h"
#include "app/shader/preprocessor.h"
#include "app/util/format.h"
#include "labs/shadows/shadow_options.h"
#include "labs/shadows/shadows_lab.h"

namespace shadelab {
namespace {

void visitKeyLight(ParamVisitor& v, ShadowsParams::KeyLight& key, bool sceneLit) {
  v.enumParam({"light_type", "Key light", "",
               "directional: orthographic map; spot: perspective map; point: a cube "
               "map drawn in one pass (geometry shader writes gl_Layer)."},
              key.type, namesOf<kLightTypes>());
  v.boolParam({"key_casts", "Key casts shadows", "", "Off: no depth pass runs for the key light."}, key.casts);
  v.boolParam({"scene_light", "Scene's own light", "",
               "A scene with a light of its own (learnopengl: from (-2, 4, "
               "-1) towards the origin, as in the chapter) sets the key light's direction; off: the sliders do."},
              key.sceneLight);
  {
    const ParamVisitor::UnavailableGroup direction(v, sceneLit
                                                          ? "the scene sets the light's direction (untick 'Scene's "
                                                            "own light')"
                                                          : "");
    v.floatParam({"light_elevation", "Light elevation", "deg",
                  "Key light above the horizon; 85..89.9 from zenith is "
                  "grazing (elevation 5..0.1)."},
                 key.elevationDeg, 0.1f, 90.0f);
    v.floatParam({"light_azimuth", "Light azimuth", "deg", "Key light around the vertical axis."}, key.azimuthDeg,
                 -180.0f, 180.0f);
  }
  v.floatParam({"light_distance", "Light distance", "radii",
                "Spot/point light distance from the scene centre, in "
                "scene radii (below 1 the light is inside the scene)."},
               key.distance, 0.0f, 20.0f);
  v.floatParam({"spot_angle", "Spot angle", "deg", "Full cone angle of the spot light (and its map's field of view)."},
               key.spotAngleDeg, 5.0f, 160.0f);
  v.floatParam({"light_radius", "Light radius", "radii",
                "Area light radius in scene radii, for PCSS and its "
                "reference; 0 = a point light, hard shadows. Directional: seen from 3 radii away."},
               key.radius, 0.0f, 10.0f);
}

void visitFillLight(ParamVisitor& v, ShadowsParams::FillLight& fill) {
  v.boolParam({"fill_light", "Fill light", "", "A second light (a spot) with its own shadow map."}, fill.on);
  v.boolParam({"fill_casts", "Fill casts shadows", "", "Off: the fill light lights, but no depth pass runs for it."},
              fill.casts);
}

void visitMap(ParamVisitor& v, ShadowsParams::Map& map, LightType keyType) {
  v.choiceParam({"map_size", "Map size", "texels", "Shadow map resolution (per cube face for a point light)."},
                map.sizeIndex, kMapSizes);
  v.enumParam({"depth_format", "Depth format", "bits", "16, 24-bit fixed point or 32-bit float depth."}, map.format,
              namesOf<kDepthFormats>());
  v.boolParam({"auto_fit", "Auto-fit frustum", "", "Fit the light's extent and near/far to the scene bounds."},
              map.autoFit);
  const std::string_view fitReason = keyType != LightType::Directional ? "fitting to the view is for directional lights"
                                     : !map.autoFit                    ? "auto-fit is off: the extent is set by hand"
                                                                       : "";
  {
    const ParamVisitor::UnavailableGroup fitted(v, fitReason);
    v.enumParam({"fit", "Directional map covers", "",
                 "scene: the whole scene's bounds (texels wasted on what the camera "
                 "never sees); view: what the camera sees (its frustum clipped to the scene); cascades: the view split "
                 "by depth into cascade_count maps of map_size^2 each, near slices getting the finest texels; "
                 "depth-range: the same cascades split over the depth range the camera drew last frame (its depth "
                 "buffer's nearest and farthest, reduced on the GPU: sample distribution shadow maps), not the range "
                 "its frustum could see."},
                map.fit, namesOf<kFits>());
    {
      const bool split = map.fit == MapFit::Cascades || map.fit == MapFit::DepthRange;
      const ParamVisitor::UnavailableGroup cascaded(v, split ? "" : "fit is neither 'cascades' nor 'depth-range'");
      v.intParam({"cascade_count", "Cascades", "maps",
                  "Cascaded shadow maps: 2..4 maps, each map_size^2 (memory "
                  "grows with the count)."},
                 map.cascadeCount, 2, 4);
      v.floatParam({"split_lambda", "Split lambda", "",
                    "Where the cascades split: 0 uniform in depth, 1 logarithmic "
                    "(equal texel-to-pixel ratio), between: the practical split scheme's blend."},
                   map.splitLambda, 0.0f, 1.0f);
      v.floatParam({"cascade_blend", "Cascade blend band", "",
                    "Fraction of each cascade's depth range over which it "
                    "fades into the next (both are filtered there): hides the seam; 0 = hard switch."},
                   map.cascadeBlend, 0.0f, 0.5f);
    }
    if (map.fit == MapFit::Scene) v.unavailable("fit is 'scene': the map never moves");
    v.boolParam({"snap_texels", "Snap to texels", "",
                 "Fitted maps move in whole texels and grow in 1/8-octave steps, "
                 "so a moving camera does not make shadow edges shimmer. Off: watch the edges crawl while orbiting."},
                map.snapTexels);
  }
  v.floatParam({"ortho_extent", "Ortho extent", "radii", "Directional light box half-width when auto-fit is off."},
               map.orthoExtent, 1e-3f, 1e3f, true);
  v.floatParam({"near", "Light near", "radii", "Light near plane when auto-fit is off."}, map.nearPlane, 1e-6f, 1e3f,
               true);
  v.floatParam({"far", "Light far", "radii", "Light far plane when auto-fit is off."}, map.farPlane, 1e-3f, 1e4f, true);
  v.boolParam(
      {"border_clamp", "Border clamp", "",
       "Outside the map reads depth 1 (lit). Off: CLAMP_TO_EDGE repeats "
       "edge texels, stretching shadows past the map. The hard filter with the far fix checks the map's bounds in "
       "its shader (shadows/shadow_lookup.glsl), as WebGL2 must: no border colour there."},
      map.borderClamp);
  v.boolParam({"far_fix", "Far-plane fix", "",
               "Receivers beyond the light's far plane are lit. Off: they compare as "
               "shadowed."},
              map.farFix);
  v.boolParam({"cull_front", "Cull front faces", "",
               "Depth pass draws back faces: closed meshes lose acne, thin "
               "ones leak."},
              map.cullFront);
  if (glslDialect() == GlslDialect::Es300)
    v.unavailable("WebGL2 has no geometry shaders: the cube is always drawn in six passes");
  v.boolParam({"six_cube_passes", "Cube map in six passes", "",
               "Point light: draw the six faces in six passes "
               "instead of one geometry-shader pass (compare their cost)."},
              map.sixCubePasses);
}

void visitBias(ParamVisitor& v, ShadowsParams::Bias& bias) {
  v.floatParam({"bias", "Constant bias", "texels", "Depth bias floor, in shadow-map texels at the receiver."},
               bias.constant, 0.0f, 50.0f);
  v.floatParam({"slope_bias", "Slope bias k", "texels",
                "bias = max(k (1 - N.L), constant): more where the light "
                "grazes."},
               bias.slope, 0.0f, 50.0f);
  v.floatParam({"normal_offset", "Normal offset", "texels",
                "Move the lookup point along the normal before "
                "projecting."},
               bias.normalOffset, 0.0f, 20.0f);
  v.floatParam({"offset_factor", "Polygon offset factor", "", "glPolygonOffset factor in the depth pass (slope)."},
               bias.offsetFactor, 0.0f, 20.0f);
  v.floatParam({"offset_units", "Polygon offset units", "", "glPolygonOffset units in the depth pass (constant)."},
               bias.offsetUnits, 0.0f, 10000.0f);
  v.boolParam({"receiver_plane", "Receiver-plane depth", "",
               "Each filter tap compares against the receiver's plane "
               "at that tap, not the centre depth: wide kernels on slopes need no extra bias."},
              bias.receiverPlane);
}

void visitFilter(ParamVisitor& v, ShadowsParams::Filter& filter, LightType keyType) {
  v.enumParam({"filter", "Filter", "", filterHelp()}, filter.type, namesOf<kShadowFilters>());
  v.intParam({"pcf_size", "PCF kernel N", "taps", "N x N taps; a compile-time loop bound (one program per N)."},
             filter.pcfSize, 1, 15);
  v.choiceParam({"poisson_samples", "Poisson samples", "", "Taps of the Poisson-disk filter."}, filter.poissonIndex,
                kSampleCounts);
  v.floatParam({"filter_radius", "Poisson radius", "texels", "Radius of the Poisson-disk filter."},
               filter.poissonRadius, 0.0f, 32.0f);
  v.boolParam({"rotate", "Rotate per pixel", "", "Rotate the Poisson disk per pixel: banding becomes noise."},
              filter.rotateSamples);
  v.choiceParam({"blocker_samples", "PCSS blocker samples", "", "Taps of the blocker search."}, filter.blockerIndex,
                kSampleCounts);
  v.choiceParam({"pcss_samples", "PCSS filter samples", "", "Taps of the penumbra filter."}, filter.pcssIndex,
                kSampleCounts);
  const std::string_view momentReason = !isMomentFilter(filter.type) ? "only for vsm, esm and evsm"
                                        : keyType == LightType::Point
                                            ? "filtered maps need a 2D map; the point light uses PCF"
                                            : "";
  {
    const ParamVisitor::UnavailableGroup filtered(v, momentReason);
    v.intParam({"blur_radius", "Moment blur", "texels",
                "Separable Gaussian blur of the moment map, texels each way "
                "(sigma = radius / 2); 0 runs no blur pass."},
               filter.blurRadius, 0, 16);
    v.boolParam({"moment_mips", "Mipmapped moments", "",
                 "Build the moment map's mip chain and sample it trilinearly "
                 "(the level chosen per pixel): distant receivers average many texels, not alias."},
                filter.momentMips);
    if (filter.type == ShadowFilter::Esm) v.unavailable("only for vsm and evsm");
    v.floatParam({"min_variance", "Minimum variance", "",
                  "Floor on the variance (normalised depth squared): too small, "
                  "acne-like noise; too large, contact shadows fade."},
                 filter.minVariance, 0.0f, 1e-2f, true);
    if (filter.type != ShadowFilter::Vsm) v.unavailable("only for vsm");
    v.floatParam({"bleed_reduction", "Light-bleeding reduction", "",
                  "VSM: p -> (p - a) / (1 - a) cuts the light that "
                  "bleeds through a second occluder behind the first, at the price of darker penumbrae."},
                 filter.bleedReduction, 0.0f, 0.95f);
    if (filter.type != ShadowFilter::Esm) v.unavailable("only for esm");
    v.floatParam({"esm_exponent", "ESM exponent c", "",
                  "exp(c t) in 32-bit float: larger c, sharper and less leaky "
                  "contact, until exp(c) nears float's limit at c = 88."},
                 filter.esmExponent, 1.0f, 85.0f);
    const ParamVisitor::UnavailableGroup evsm(v, filter.type != ShadowFilter::Evsm ? "only for evsm" : "");
    v.floatParam({"evsm_positive", "EVSM positive exponent", "",
                  "exp(c+ t) and its square are stored: c+ <= 42 keeps "
                  "the square finite in 32-bit float."},
                 filter.evsmPositive, 1.0f, 42.0f);
    v.floatParam({"evsm_negative", "EVSM negative exponent", "",
                  "-exp(-c- t) and its square: the second warp that "
                  "catches what the first lets bleed."},
                 filter.evsmNegative, 1.0f, 42.0f);
  }
}

void visitView(ParamVisitor& v, ShadowsParams::View& view, MapFit fit) {
  v.enumParam({"view", "View", "",
               "shaded; visibility (the key light's shadow term); bias-heat (receiver - stored "
               "depth in units of the bias: blue = the stored depth lies behind the surface, green = on it, a full "
               "bias of margin, orange = nearly acne, red = acne, grey = a real shadow, near-black = facing away from "
               "the light); texel-density (green = a texel per pixel, red = coarser, blue = finer); pcss-blocker; "
               "pcss-penumbra; cascades (one colour each, the blend band striped, magenta = a gap); "
               "depth-raw/-linear (the map; a cube unrolled)."},
              view.mode, namesOf<kShadowViews>());
  v.choiceParam({"depth_light", "Depth view of", "", "Which light's map the depth views show."}, view.depthLight,
                kDepthLights);
  if (fit != MapFit::Cascades || view.depthLight != 0) v.unavailable("the key light has one map");
  v.choiceParam({"depth_cascade", "Depth view cascade", "", "Which cascade's map the depth views show."},
                view.depthCascade, kCascadeIndices);
  v.floatParam({"depth_zoom", "Depth view zoom", "x", "Magnification of the depth views."}, view.depthZoom, 1.0f, 64.0f,
               true);
  v.floatParam({"depth_centre_u", "Depth view centre u", "", "Map coordinate at the middle of the view."},
               view.depthCentreU, 0.0f, 1.0f);
  v.floatParam({"depth_centre_v", "Depth view centre v", "", "Map coordinate at the middle of the view."},
               view.depthCentreV, 0.0f, 1.0f);
  v.boolParam({"frame_faces", "Frame cube faces", "",
               "A point light's cube: each face zoomed to the geometry it "
               "sees (its cell's border says how far: the brighter, the closer the zoom); off: the plain cross, "
               "each face whole."},
              view.frameFaces);
  v.boolParam({"show_frustum", "Show light frustum", "", "Draw the key light's frustum (directional, spot)."},
              view.showFrustum);
}

constexpr Named<TruthTracer> kTracers[] = {
    {TruthTracer::Auto, "auto"}, {TruthTracer::Embree, "embree"}, {TruthTracer::Gpu, "gpu"}};
static_assert(coversEnum<TruthTracer>(kTracers));

void visitTruth(ParamVisitor& v, ShadowsParams::Truth& truth) {
  v.enumParam({"truth_tracer", "Truth traced by", "",
               "auto: the GPU tracer on a GPU, Embree on a software renderer "
               "(llvmpipe, SwiftShader), where the fragment shader is the slower of the two; embree: Intel Embree on "
               "the CPU, the whole truth at once; gpu: a BVH walked by a fragment shader, samples of the light's disk "
               "pass by pass, so the area truth converges while the window keeps drawing (and where there is no "
               "Embree). Both trace the same rays."},
              truth.tracer, namesOf<kTracers>());
}

void visitScene(ParamVisitor& v, ShadowsParams::SceneSettings& scene) {
  v.intParam({"tessellation", "Tessellation", "segments", "Segments of procedural spheres and tori."},
             scene.tessellation, 3, 256);
  v.floatParam({"scene_scale", "Scene scale", "",
                "Uniform scale of the whole scene (1e-3 .. 1e6); lengths in "
                "radii and texels follow it."},
               scene.scale, 1e-3f, 1e6f, true);
  v.boolParam({"floor", "Floor under files", "",
               "A mesh from a file (dropped or --scene FILE) stands on a floor "
               "under its bounds, so its shadow has somewhere to fall; off: the file alone, self-shadowing only."},
              scene.floorUnderFiles);
}

}  // namespace

void ShadowsLab::visitParams(ParamVisitor& v) {
  visitParamsOf(v, params, params.key.sceneLight && glm::dot(sceneLight_, sceneLight_) > 0.0f);
}

void ShadowsLab::visitParamsOf(ParamVisitor& v, ShadowsParams& p, bool sceneLit) {
  v.section("Key light");
  visitKeyLight(v, p.key, sceneLit);
  v.section("Fill light");
  visitFillLight(v, p.fill);
  v.section("Shadow map");
  visitMap(v, p.map, p.key.type);
  v.section("Bias");
  visitBias(v, p.bias);
  v.section("Filter");
  visitFilter(v, p.filter, p.key.type);
  v.section("View");
  visitView(v, p.view, p.map.fit);
  v.section("Scene");
  visitScene(v, p.scene);
  v.section("Truth");
  visitTruth(v, p.truth);
}

// What the settings (and the last frame's light and maps) warn the student of, one line each.
std::vector<std::string> ShadowsLab::warnings() const {
  std::vector<std::string> w = lightWarnings_;
  w.insert(w.end(), mapWarnings_.begin(), mapWarnings_.end());
  if (tracer_ && tracer_->gaveUp() > 0)
    w.push_back("the GPU tracer stopped the rays of " + std::to_string(tracer_->gaveUp()) +
                " pixels after visiting "
                "more nodes than its tree has (a broken tree or driver): they count as lit in the truth; "
                "truth_tracer = embree is the check");
  const auto& p = params;
  if (p.key.type != LightType::Point && p.key.elevationDeg < 10.0f)
    w.push_back("grazing light (" + formatNumber(p.key.elevationDeg) +
                " deg above the horizon): texels stretch along the "
                "ground; expect acne unless the slope bias grows");
  if (p.key.casts && p.bias.constant == 0 && p.bias.slope == 0 && p.bias.normalOffset == 0 &&
      p.bias.offsetFactor == 0 && p.bias.offsetUnits == 0)
    w.push_back("no bias at all: lit surfaces shadow themselves (acne)");
  if (p.bias.constant + p.bias.slope > 12.0f || p.bias.normalOffset > 6.0f)
    w.push_back("large bias: shadows detach from their casters (peter-panning)");
  if (!p.map.borderClamp)
    w.push_back(p.filter.type == ShadowFilter::Hard && p.map.farFix
                    ? "border clamp off: the hard test checks the map's bounds itself (shadow_lookup.glsl); the other "
                      "filters' taps repeat the edge texels"
                    : "border clamp off: outside the map the edge texels repeat and stretch shadows");
  if (!p.map.farFix) w.push_back("far-plane fix off: receivers beyond the light's far plane come out shadowed");
  if (p.filter.type == ShadowFilter::Pcss && p.key.radius == 0.0f)
    w.push_back("light radius 0: PCSS reduces to a hard shadow");
  if (p.filter.type == ShadowFilter::Pcss && p.key.radius > 1.0f)
    w.push_back("light radius " + formatNumber(p.key.radius) +
                " scene radii: larger than the scene, penumbrae wash out");
  if (p.key.type == LightType::Point && p.key.distance < 0.5f)
    w.push_back("point light near the scene centre: it may sit inside geometry, which then hides everything");
  if (!p.key.casts && !(p.fill.on && p.fill.casts)) w.push_back("no light casts shadows: no depth pass runs");
  if (viewIsDepthMap(p.view.mode) && p.view.depthLight == 1 && !(p.fill.on && p.fill.casts))
    w.push_back("the depth view shows the fill light's map: turn on fill_light and fill_casts");
  if (viewIsDepthMap(p.view.mode) && p.view.depthLight == 0 && !p.key.casts)
    w.push_back("the depth view shows the key light's map, but the key light casts no shadow");
  if ((p.view.mode == ShadowView::PcssBlocker || p.view.mode == ShadowView::PcssPenumbra) &&
      p.filter.type != ShadowFilter::Pcss)
    w.push_back("the PCSS views show data only with filter = pcss");
  if (p.view.mode == ShadowView::BiasHeat && isMomentFilter(effectiveFilterOf(p)))
    w.push_back("the bias-heat view shows a depth test's margin, and " + filterName(p.filter.type) +
                " tests moments of depth instead: there is no margin to show (uniform green); pick hard or pcf");
  else if (p.view.mode == ShadowView::BiasHeat && p.bias.constant == 0 && p.bias.slope == 0)
    w.push_back(
        "bias-heat measures the gap in units of the bias, which is 0: every lit texel is red (acne) or blue "
        "(stored depth behind the surface), with nothing between; raise bias to see the margin");
  if (isMomentFilter(p.filter.type) && p.key.type == LightType::Point)
    w.push_back(filterName(p.filter.type) +
                " needs a 2D map: the point light's cube map is filtered with "
                "pcf (" +
                std::to_string(p.filter.pcfSize) + "x" + std::to_string(p.filter.pcfSize) + ") instead");
  if (p.map.fit != MapFit::Scene && (p.key.type != LightType::Directional || !p.map.autoFit))
    w.push_back("fit = " + std::string(rowOf(kFits, p.map.fit).name) +
                " applies to an auto-fitted directional light only");
  if (p.view.mode == ShadowView::Cascades && cascadeCountOf(p) < 2)
    w.push_back("one map, one colour: the cascades view needs fit = cascades or depth-range");
  if (p.filter.type == ShadowFilter::Esm && p.filter.esmExponent > 80.0f)
    w.push_back("ESM exponent " + formatNumber(p.filter.esmExponent) + ": exp(c) is within a factor " +
                formatNumber(std::exp(88.7f - p.filter.esmExponent)) +
                " of float's limit; a blur of overflowing texels would be inf");
  return w;
}

}  // namespace shadelab
