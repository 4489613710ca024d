// The surface lab against its truth: the height field on a very fine mesh with normals from the
// field, supersampled; three numbers (shaded RMSE, normal angle, silhouette), what the student is
// warned about, the panels, the standard sweep and the stress cases.
#include <cmath>
#include <cstdio>

#include "app/util/format.h"
#include "labs/surface/surface_lab.h"

namespace shadelab {
ReferenceSpec SurfaceLab::reference() const {
  ReferenceSpec spec;
  if (!heightless_.empty()) {  // the truth is the height field as geometry: without one there is none
    spec.description =
        "material '" + heightless_ + "' has no height map, so there is no true surface to measure against";
    return spec;
  }
  spec.kind = TruthKind::Image;
  spec.truth = "true surface";
  spec.description =
      "the height field applied to the mesh subdivided to about one vertex per texel, normals from the "
      "field per fragment, Blinn-Phong as every technique; 4 x 4 jittered frames per pixel";
  spec.overrides = edits<SurfaceLab>(params, [](SurfaceParams& p) {
    p.technique = SurfaceTechnique::Truth;
    p.displacedNormals = DisplacedNormals::FromHeight;
    p.tangents = TangentSource::Generated;
    p.addToOldNormal = p.noRenormalize = p.noOrthogonalize = false;
    p.decoding = MapDecoding::Linear;
    p.green = GreenConvention::OpenGl;
    p.filter = TextureFilter::Trilinear;
    p.overlay = false;
  });
  spec.jitterGrid = 4;
  // The true surface is about a vertex per texel (two million triangles on the brick wall), about
  // 0.3 s of vertex work a frame on llvmpipe: drawn in twelve parts, one per window frame, the
  // window's frame stays within 2x its idle time while the truth is built.
  spec.slices = 12;
  return spec;
}

std::vector<MeasuredView> SurfaceLab::measuredViews() const {
  return {{{{"view", "shaded"}, {"overlay", "off"}}, true}, {{{"view", "normals"}, {"overlay", "off"}}, false}};
}

Metrics SurfaceLab::viewMetrics(const std::vector<ImageF>& images, const std::vector<ImageF>& references) const {
  const ImageError shaded = compareImages(images.at(0), references.at(0));
  const ImageF &n = images.at(1), &r = references.at(1);
  double angle = 0.0, covered = 0.0, mismatch = 0.0;
  const size_t pixels = size_t(n.size.x) * size_t(n.size.y);
  for (size_t i = 0; n.size == r.size && i < pixels; ++i) {
    const bool a = n.rgba[i * 4 + 3] >= 0.5f, b = r.rgba[i * 4 + 3] >= 0.5f;
    mismatch += a != b;
    if (!a || !b) continue;
    const glm::vec3 na = glm::vec3(n.rgba[i * 4], n.rgba[i * 4 + 1], n.rgba[i * 4 + 2]) * 2.0f - 1.0f;
    const glm::vec3 nb = glm::vec3(r.rgba[i * 4], r.rgba[i * 4 + 1], r.rgba[i * 4 + 2]) * 2.0f - 1.0f;
    const float la = glm::length(na), lb = glm::length(nb);
    if (!(la > 1e-6f && lb > 1e-6f) || !std::isfinite(la + lb)) continue;
    angle += std::acos(std::clamp(double(glm::dot(na, nb)) / (double(la) * lb), -1.0, 1.0));
    covered += 1.0;
  }
  return {{"rmse", shaded.rmse},
          {"surface_rmse", shaded.coveredRmse},
          {"normal_angle_deg", covered > 0 ? glm::degrees(angle / covered) : 90.0},
          {"silhouette_pct", pixels ? 100.0 * mismatch / double(pixels) : 0.0},
          {"max_error", shaded.maxError}};
}

std::vector<PlotSpec> SurfaceLab::plots() const { return {{"rmse"}, {"normal_angle_deg"}, {"silhouette_pct"}}; }

std::vector<std::string> SurfaceLab::warnings() const {
  std::vector<std::string> w = frameNotes_;
  const auto& p = params;
  if (p.addToOldNormal)
    w.push_back("wrong step: the map's normal is added to the old one (n_old + TBN (2c - 1)): the relief flattens");
  if (p.noRenormalize) w.push_back("wrong step: no renormalisation: interpolated vectors are short and the light dims");
  if (p.noOrthogonalize)
    w.push_back("wrong step: the tangent is not made perpendicular to the normal again: a skewed frame");
  if (p.decoding == MapDecoding::Srgb && p.technique == SurfaceTechnique::NormalMap)
    w.push_back("wrong step: the normal map is decoded as sRGB colour: its vectors bend towards the surface");
  if (p.green == GreenConvention::DirectX && p.technique == SurfaceTechnique::NormalMap)
    w.push_back("wrong step: DirectX green on an OpenGL map: the vertical slopes point the other way");
  if (p.heightScale < 0.0f) w.push_back("a negative height scale turns bumps into dents and dents into bumps");
  if (std::abs(p.heightScale) > 0.5f)
    w.push_back("height scale " + formatFixed(p.heightScale, 2) +
                ": relief this deep folds displaced geometry over itself and stretches parallax far beyond what one "
                "layer of texels can show");
  if (isParallax(p.technique) && p.surfaceAt == SurfaceAt::Bottom)
    w.push_back(
        "parallax mapping reads depth below the polygon (the surface at the top of the field); with "
        "surface_at = bottom the truth stands out by the height scale instead");
  if (p.technique == SurfaceTechnique::Displacement && drawnLevel_ < p.subdivision)
    w.push_back("subdivision capped at level " + std::to_string(drawnLevel_) + " (2.5 M triangles)");
  if (p.technique == SurfaceTechnique::SteepParallax && p.layers < 4)
    w.push_back("fewer than 4 layers: steep parallax shows its slices as steps");
  if (p.lightElevationDeg < 0.0f) w.push_back("the light is below the surface: only the ambient term lights it");
  return w;
}

std::vector<LabPanel> SurfaceLab::panels() const {
  LabPanel drawn{"Drawn", {}};
  drawn.items.push_back(PanelTable{{"", "value"},
                                   {{"triangles drawn", std::to_string(drawnTriangles_)},
                                    {"subdivision level", std::to_string(drawnLevel_)},
                                    {"height scale (world)", formatFixed(params.heightScale, 4)},
                                    {"UV shear, median (deg)", formatFixed(shearMedian_, 1)},
                                    {"UV shear, 90 % (deg)", formatFixed(shearP90_, 1)}}});
  drawn.items.push_back(
      PanelText{"Every technique is measured against the true surface (Measure): shaded RMSE, the "
                "mean angle between its normals and the truth's, and the share of pixels covered by "
                "one but not the other (silhouette). UV shear is the angle between dp/du and the "
                "gradient of u per triangle: where generated and screen-space tangents part (the "
                "tangent-angle view)."});
  return {drawn};
}

std::vector<SweepAxis> SurfaceLab::standardSweep() const {
  return {{"technique",
           {"none", "normal-map", "bump", "displacement:subdivision=3", "displacement:subdivision=5",
            "displacement:subdivision=7", "tessellation:tess_level=4", "tessellation:tess_level=16",
            "tessellation:tess_level=64", "parallax", "steep-parallax:layers=8", "steep-parallax:layers=32",
            "pom:layers=4", "pom:layers=8", "pom:layers=16", "pom:layers=32", "pom:layers=64"}}};
}

std::vector<StressCase> SurfaceLab::stressCases() const {
  const auto edit = [](auto change) { return fromDefaults<SurfaceLab>(change); };
  return {
      {"huge-displacement",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Displacement, p.heightScale = 2.0f; }), "", "",
       "folds"},
      {"huge-tessellated", edit([](SurfaceParams& p) {
         p.technique = SurfaceTechnique::Tessellation, p.heightScale = -2.0f, p.tessLevel = 64;
       }),
       "", "", "dents"},
      // 65,536 patches at level 64: 268 M triangles (minutes a frame on llvmpipe) unless held
      {"tessellated-dense-sphere", edit([](SurfaceParams& p) {
         p.technique = SurfaceTechnique::Tessellation, p.tessLevel = 64, p.tessellation = 256;
       }),
       "bricks-sphere", "", "drawn at level"},
      {"negative-pom", edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Pom, p.heightScale = -0.3f; }), "",
       "", "dents"},
      {"spike-displacement",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Displacement, p.heightScale = 0.5f; }), "spike", "",
       ""},
      {"spike-pom",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Pom, p.layers = 128, p.heightScale = 0.8f; }),
       "spike", "", "folds"},
      {"spike-bump", edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Bump, p.heightScale = 0.5f; }),
       "spike", "", ""},
      {"zero-length-normals", edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::NormalMap; }), "broken-maps",
       "", ""},
      {"zero-length-normals-no-renormalize",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::NormalMap, p.noRenormalize = true; }), "broken-maps",
       "", "no renormalisation"},
      {"mirrored-uvs",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::NormalMap, p.view = SurfaceView::TangentAngle; }),
       "uv-trouble", "", ""},
      {"degenerate-uvs", edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Pom, p.overlay = true; }),
       "uv-trouble", "", "degenerate UVs"},
      {"degenerate-uvs-screen-frame",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Bump, p.tangents = TangentSource::Screen; }),
       "uv-trouble", "", ""},
      {"grazing-pom-128",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Pom, p.layers = 128, p.selfShadow = true; }),
       "bricks-grazing", "pitch=0.5,distance=3", ""},
      {"grazing-parallax",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Parallax, p.heightScale = 0.3f; }), "bricks-grazing",
       "pitch=0.5", ""},
      {"grazing-screen-tangents",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::NormalMap, p.tangents = TangentSource::Screen; }),
       "bricks-grazing", "pitch=0.2", ""},
      {"no-uvs", edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Pom; }), "no-uvs", "", "no UVs"},
      {"subdivision-capped",
       edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Displacement, p.subdivision = 10; }),
       "bricks-sphere", "", "capped"},
      {"every-wrong-step", edit([](SurfaceParams& p) {
         p.technique = SurfaceTechnique::NormalMap, p.addToOldNormal = true, p.noRenormalize = true,
         p.noOrthogonalize = true, p.decoding = MapDecoding::Srgb, p.green = GreenConvention::DirectX;
       }),
       "", "", "wrong step"},
      {"light-below", edit([](SurfaceParams& p) {
         p.technique = SurfaceTechnique::Pom, p.selfShadow = true, p.lightElevationDeg = -10.0f;
       }),
       "", "", "below"},
      {"one-layer", edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::SteepParallax, p.layers = 1; }), "", "",
       "fewer than 4 layers"},
      {"truth-on-the-sphere", edit([](SurfaceParams& p) { p.technique = SurfaceTechnique::Truth; }), "bricks-sphere",
       "", ""},
  };
}

}  // namespace shadelab
