// The filtering lab against its truth: each pixel's footprint integrated by 16 x 16 jittered
// samples of level 0, and a slow camera move over which a filter should change no more than the
// truth does. Also what the student is warned about, the panels, the sweep and the stress cases.
#include <algorithm>
#include <cmath>

#include "app/util/format.h"
#include "labs/filtering/filtering_lab.h"

namespace shadelab {

ReferenceSpec FilteringLab::reference() const {
  ReferenceSpec spec;
  spec.kind = TruthKind::Image;
  spec.truth = "supersampled";
  spec.description =
      "each pixel's footprint integrated over 16 x 16 jittered samples (bilinear lookups of level 0, "
      "no mip levels, no anisotropy), weighted by the pixel filter, averaged in linear light";
  spec.overrides = edits<FilteringLab>(params, [](FilteringParams& p) {
    p.filter = TexelFilter::Bilinear;
    p.mipmaps = MipSelection::Off;
    p.inShader = false;
    p.anisotropy = 1;
    p.lodBias = 0.0f;
    p.manualLevel = false;
    p.builder = MipBuilder::Box;
    p.view = FilteringView::Shaded;
    p.probe = false;
    p.animate = false;
  });
  spec.jitterGrid = 16;
  spec.pixelFilter = params.pixelFilter;
  return spec;
}

// The frame the student sees and the next two of the slow move: the first is compared with its
// truth; the three give the flicker.
std::vector<MeasuredView> FilteringLab::measuredViews() const {
  std::vector<MeasuredView> views;
  for (int i = 0; i < kMotionFrames; ++i)
    views.push_back({{{"view", "shaded"},
                      {"footprint_probe", "off"},
                      {"animate", "off"},
                      {"motion_frame", std::to_string(std::min(params.motionFrame, 30 - (kMotionFrames - 1)) + i)}},
                     true});
  return views;
}

Metrics FilteringLab::viewMetrics(const std::vector<ImageF>& images, const std::vector<ImageF>& references) const {
  const ImageError e = compareImages(images.at(0), references.at(0));
  // Flicker: the change from one frame to the next that the truth's own change does not explain,
  // RMS over the pixels every frame covers.
  double sq = 0.0;
  size_t count = 0;
  for (size_t k = 0; k + 1 < images.size() && k + 1 < references.size(); ++k) {
    const ImageF &t0 = images[k], &t1 = images[k + 1], &r0 = references[k], &r1 = references[k + 1];
    if (t0.size != t1.size || t0.size != r0.size || r0.size != r1.size) continue;
    for (size_t i = 0; i < t0.rgba.size(); i += 4) {
      if (r0.rgba[i + 3] < 0.5f || r1.rgba[i + 3] < 0.5f || t0.rgba[i + 3] < 0.5f || t1.rgba[i + 3] < 0.5f) continue;
      for (size_t c = 0; c < 3; ++c) {
        const double d = (double(t1.rgba[i + c]) - t0.rgba[i + c]) - (double(r1.rgba[i + c]) - r0.rgba[i + c]);
        sq += d * d;
      }
      count += 3;
    }
  }
  const double rmse = e.coveredRmse;
  return {{"rmse", rmse},
          {"psnr_db", 20.0 * std::log10(1.0 / std::max(rmse, 1e-6))},
          {"flicker", count ? std::sqrt(sq / double(count)) : 0.0},
          {"max_error", e.maxError}};
}

std::vector<PlotSpec> FilteringLab::plots() const { return {{"rmse"}, {"flicker"}}; }

std::vector<std::string> FilteringLab::warnings() const {
  std::vector<std::string> w = frameNotes_;
  const auto& p = params;
  const bool hardware = !inShader();
  if (p.filter == TexelFilter::Bicubic && !p.inShader)
    w.push_back("bicubic is written in the shader (filter.glsl): texture units have no bicubic filter");
  if (p.anisotropy > 1 && p.mipmaps == MipSelection::Off)
    w.push_back(
        "anisotropic filtering picks finer mip levels for its probes; with mip levels off it has none to "
        "pick, so it is left out (every probe would read level 0: the same picture at many times the cost)");
  if (anisotropyMovedToShader())
    w.push_back(
        "llvmpipe's anisotropic filtering takes about twice as long for each level finer than the "
        "footprint (a negative LOD bias or a chosen level): seconds a frame here, so the probes are the "
        "shader's (in_shader=on) instead of the driver's");
  if (hardware && anisotropyLimit_ > 0.0f && float(p.anisotropy) > std::max(anisotropyLimit_, 1.0f))
    w.push_back("anisotropy " + std::to_string(p.anisotropy) + "x clamped to the driver's limit of " +
                formatNumber(std::max(anisotropyLimit_, 1.0f)) + "x");
  if (hardware && std::abs(p.lodBias) > maxBias_)
    w.push_back("LOD bias " + formatFixed(p.lodBias, 1) + " clamped to the driver's limit of +-" +
                formatNumber(maxBias_));
  if (!p.manualLevel && p.lodBias >= 2.0f)
    w.push_back("LOD bias +" + formatFixed(p.lodBias, 1) + ": levels 2^" + formatFixed(p.lodBias, 1) +
                " times coarser than the footprint: the texture blurs");
  if (!p.manualLevel && p.lodBias <= -1.0f)
    w.push_back("LOD bias " + formatFixed(p.lodBias, 1) + ": levels finer than the footprint: the texture aliases");
  if (p.manualLevel && p.mipmaps == MipSelection::Off)
    w.push_back("a chosen level needs mip levels: with mip levels off, level 0 is read");
  if (shown_ >= 0 && size_t(shown_) < chains_.size()) {
    const ChainTexture& c = chains_[size_t(shown_)];
    const glm::ivec2 s = c.sizes.front();
    if (p.manualLevel && p.level > float(c.levels - 1))
      w.push_back("level " + formatFixed(p.level, 1) + " is past the last level (" + std::to_string(c.levels - 1) +
                  ", 1 x 1): clamped");
    if (s == glm::ivec2(1))
      w.push_back("a 1 x 1 texture: one level, one texel: every filter returns it");
    else if ((s.x & (s.x - 1)) != 0 || (s.y & (s.y - 1)) != 0)
      w.push_back(std::to_string(s.x) + " x " + std::to_string(s.y) +
                  " is not a power of two: level k is floor(size / "
                  "2^k) (" +
                  std::to_string(c.sizes[1].x) + " x " + std::to_string(c.sizes[1].y) +
                  ", ...), and each "
                  "texel of a level covers a little more than 2 x 2 of the one before");
  }
  return w;
}

std::vector<LabPanel> FilteringLab::panels() const {
  std::vector<LabPanel> out;
  const auto& p = params;
  if (p.probe) {
    LabPanel panel{"Footprint", {}};
    const Footprint& f = footprint_;
    if (!f.covered) {
      panel.items.push_back(PanelText{"The probe pixel (" + std::to_string(f.pixel.x) + ", " +
                                      std::to_string(f.pixel.y) +
                                      ") shows no texture: move it onto a surface (probe_x, probe_y)."});
    } else {
      const float px = glm::length(f.dx), py = glm::length(f.dy);
      const float pmax = std::max(px, py), pmin = std::min(px, py);
      const float ratio = pmax / std::max(pmin, 1e-8f);
      const float lod = std::log2(std::max(pmax, 1e-8f));
      const int limit = inShader() ? anisotropy() : std::min(anisotropy(), int(std::max(anisotropyLimit_, 1.0f)));
      const int n = std::clamp(int(std::ceil(ratio)), 1, std::max(limit, 1));
      const float anisoLod = std::log2(std::max(pmax, 1e-8f) / float(n));
      panel.items.push_back(PanelTable{{"", "value"},
                                       {{"pixel", std::to_string(f.pixel.x) + ", " + std::to_string(f.pixel.y)},
                                        {"dUV/dx (texels)", formatFixed(f.dx.x, 2) + ", " + formatFixed(f.dx.y, 2)},
                                        {"dUV/dy (texels)", formatFixed(f.dy.x, 2) + ", " + formatFixed(f.dy.y, 2)},
                                        {"long / short axis", formatFixed(pmax, 2) + " / " + formatFixed(pmin, 2)},
                                        {"anisotropy", formatFixed(ratio, 1) + " : 1"},
                                        {"L = log2(long axis)", formatFixed(lod, 2)},
                                        {"probes, their level", std::to_string(n) + ", " + formatFixed(anisoLod, 2)}}});
      // The footprint in texels of level 0 around the sample, the square an isotropic filter
      // reads (one texel of level L), and the anisotropic probes along the long axis.
      PanelPlot plot;
      plot.title = "footprint in texels of level 0";
      plot.xLabel = "u (texels)";
      plot.yLabel = "v (texels)";
      plot.equalAxes = true;
      // Closed outlines of parallelograms centre +- ex/2 +- ey/2, a break (NaN) after each.
      auto outline = [](PanelSeries& series, glm::vec2 centre, glm::vec2 ex, glm::vec2 ey) {
        for (glm::vec2 c :
             {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1), glm::vec2(-1, -1)}) {
          const glm::vec2 q = centre + 0.5f * (c.x * ex + c.y * ey);
          series.x.push_back(q.x);
          series.y.push_back(q.y);
        }
        series.x.push_back(NAN);
        series.y.push_back(NAN);
      };
      auto square = [&](PanelSeries& series, glm::vec2 centre, float side) {
        outline(series, centre, glm::vec2(side, 0.0f), glm::vec2(0.0f, side));
      };
      PanelSeries quad{"pixel footprint", {}, {}};
      outline(quad, glm::vec2(0.0f), f.dx, f.dy);
      PanelSeries iso{"isotropic: one texel of level L", {}, {}};
      square(iso, glm::vec2(0.0f), std::exp2(std::max(lod, 0.0f)));
      PanelSeries probes{"anisotropic probes", {}, {}};
      const glm::vec2 axis = px >= py ? f.dx : f.dy;
      for (int i = 0; i < n && n > 1; ++i)
        square(probes, axis * ((float(i) + 0.5f) / float(n) - 0.5f), std::exp2(std::max(anisoLod, 0.0f)));
      plot.series = {quad, iso};
      if (n > 1) plot.series.push_back(probes);
      panel.items.push_back(plot);
    }
    out.push_back(panel);
  }
  if (shown_ >= 0 && size_t(shown_) < chains_.size()) {
    const ChainTexture& c = chains_[size_t(shown_)];
    LabPanel chain{"Mip chain", {}};
    const glm::ivec2 atlas = c.atlas.size();
    chain.items.push_back(
        PanelImage{&c.atlas,
                   {320, std::max(1, 320 * atlas.y / std::max(atlas.x, 1))},
                   "made by " + std::string(c.builder == MipBuilder::Box      ? "a box filter"
                                            : c.builder == MipBuilder::Kaiser ? "a Kaiser-windowed sinc"
                                                                              : "the driver")});
    PanelTable table{{"level", "size", "contrast"}, {}};
    for (size_t l = 0; l < c.sizes.size(); ++l)
      table.rows.push_back({std::to_string(l), std::to_string(c.sizes[l].x) + " x " + std::to_string(c.sizes[l].y),
                            formatFixed(c.contrast[l], 4)});
    chain.items.push_back(table);
    chain.items.push_back(
        PanelText{"contrast: the standard deviation of each level's luminance (linear). A filter "
                  "that blurs early loses it a level sooner; switch 'Made by' and compare. Images "
                  "decoded: " +
                  std::to_string(imagesDecoded_) +
                  " (only those a drawn material "
                  "uses), chains built: " +
                  std::to_string(chains_.size()) + "."});
    out.push_back(chain);
  }
  return out;
}

std::vector<SweepAxis> FilteringLab::standardSweep() const {
  return {{"filter",
           {"nearest:mipmaps=off", "bilinear:mipmaps=off", "bicubic:mipmaps=off", "nearest:mipmaps=nearest-level",
            "bilinear:mipmaps=nearest-level", "bilinear", "bilinear:in_shader=on", "bilinear:downsampler=kaiser",
            "bicubic", "bilinear:anisotropy=2", "bilinear:anisotropy=4", "bilinear:anisotropy=8",
            "bilinear:anisotropy=16", "bilinear:anisotropy=2:in_shader=on", "bilinear:anisotropy=4:in_shader=on",
            "bilinear:anisotropy=8:in_shader=on", "bilinear:anisotropy=16:in_shader=on"}}};
}

std::vector<StressCase> FilteringLab::stressCases() const {
  const auto edit = [](auto change) { return fromDefaults<FilteringLab>(change); };
  return {
      {"horizon-nearest",
       edit([](FilteringParams& p) { p.filter = TexelFilter::Nearest, p.mipmaps = MipSelection::Off; }), "horizon", "",
       ""},
      {"horizon-trilinear-shader", edit([](FilteringParams& p) { p.inShader = true; }), "horizon", "", ""},
      {"horizon-anisotropic-16", edit([](FilteringParams& p) { p.anisotropy = 16, p.view = FilteringView::MipLevel; }),
       "horizon", "", ""},
      {"horizon-anisotropic-shader",
       edit([](FilteringParams& p) { p.anisotropy = 16, p.inShader = true, p.view = FilteringView::Anisotropy; }),
       "horizon", "", ""},
      {"magnify-10000x", edit([](FilteringParams& p) { p.filter = TexelFilter::Bicubic; }), "magnify",
       "yaw=0,pitch=0,distance=0.0005,target=0.3;0.2;0", ""},
      {"magnify-nearest-close", edit([](FilteringParams& p) { p.filter = TexelFilter::Nearest, p.inShader = true; }),
       "magnify", "yaw=0,pitch=0,distance=0.001", ""},
      {"npot-box", edit([](FilteringParams& p) { p.view = FilteringView::MipLevel; }), "npot", "",
       "not a power of two"},
      {"npot-kaiser-shader", edit([](FilteringParams& p) {
         p.builder = MipBuilder::Kaiser, p.inShader = true, p.filter = TexelFilter::Bicubic;
       }),
       "npot", "", "not a power of two"},
      {"npot-driver", edit([](FilteringParams& p) { p.builder = MipBuilder::Driver; }), "npot", "",
       "not a power of two"},
      {"one-texel", edit([](FilteringParams& p) { p.filter = TexelFilter::Bicubic, p.anisotropy = 16; }), "one-texel",
       "", "1 x 1"},
      {"one-texel-chosen-level", edit([](FilteringParams& p) { p.manualLevel = true, p.level = 14.0f; }), "one-texel",
       "", "past the last level"},
      {"constant-uv", edit([](FilteringParams& p) { p.inShader = true, p.view = FilteringView::MipLevel; }),
       "constant-uv", "", ""},
      {"huge-uv", edit([](FilteringParams& p) { p.inShader = true, p.anisotropy = 16; }), "huge-uv", "", ""},
      {"huge-uv-hardware", edit([](FilteringParams& p) { p.view = FilteringView::Anisotropy; }), "huge-uv", "", ""},
      {"bias-plus-16", edit([](FilteringParams& p) { p.lodBias = 16.0f; }), "", "", "blurs"},
      {"bias-minus-16-shader", edit([](FilteringParams& p) { p.lodBias = -16.0f, p.inShader = true; }), "", "",
       "aliases"},
      {"anisotropy-without-mips", edit([](FilteringParams& p) { p.anisotropy = 16, p.mipmaps = MipSelection::Off; }),
       "", "", "mip levels off"},
      {"edge-on", edit([](FilteringParams& p) { p.inShader = true, p.view = FilteringView::Anisotropy; }), "",
       "yaw=0,pitch=0,distance=6,target=0;0;-4", ""},
  };
}

}  // namespace shadelab
