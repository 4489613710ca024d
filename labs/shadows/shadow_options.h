// The shadows lab's technique tables and option names (as the CLI and presets spell them), and the
// rules that turn its parameters into what is drawn: shared by the lab (shadows_lab.cpp) and its programs
// (shadows_programs.cpp).
#pragma once
#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "app/lab/technique.h"
#include "labs/shadows/shadows_lab.h"

namespace shadelab {

inline constexpr Named<LightType> kLightTypes[] = {
    {LightType::Directional, "directional"}, {LightType::Spot, "spot"}, {LightType::Point, "point"}};
static_assert(coversEnum<LightType>(kLightTypes));

// A filter's own parameters: each shapes its program, so check-shaders walks their values.
enum class FilterSettings { None, PcfSize, PoissonDisk, PcssSamples, Count };

// One value of a filter's own settings, as the variant space walks them: two numbers that the
// settings' row reads (N for pcf; a tap count's index and whether the disk turns; ...).
struct FilterVariant {
  int a = 0, b = 0;
};
// A kind of settings: the #defines they put in the lit program, every value of theirs the variant
// space covers, and how one of those is set. A filter with settings of its own is a row here
// and its row in kShadowFilters naming it.
struct FilterSettingsRow {
  FilterSettings value;
  void (*defines)(const ShadowsParams::Filter& f, Defines& out);
  std::vector<FilterVariant> (*variants)();
  void (*apply)(FilterVariant v, ShadowsParams::Filter& f);
};
inline constexpr FilterSettingsRow kFilterSettings[] = {
    {FilterSettings::None, [](const ShadowsParams::Filter&, Defines&) {}, [] { return std::vector<FilterVariant>{{}}; },
     [](FilterVariant, ShadowsParams::Filter&) {}},
    {FilterSettings::PcfSize,  // N x N taps
     [](const ShadowsParams::Filter& f, Defines& out) { out.emplace_back("PCF_SIZE", std::to_string(f.pcfSize)); },
     [] {
       std::vector<FilterVariant> out;
       for (int n = 1; n <= 15; ++n) out.push_back({n});
       return out;
     },
     [](FilterVariant v, ShadowsParams::Filter& f) { f.pcfSize = v.a; }},
    {FilterSettings::PoissonDisk,  // 8 << i taps, rotated or not
     [](const ShadowsParams::Filter& f, Defines& out) {
       out.emplace_back("POISSON_COUNT", std::to_string(8 << f.poissonIndex));
       if (f.rotateSamples) out.emplace_back("ROTATE_SAMPLES", "1");
     },
     [] {
       std::vector<FilterVariant> out;
       for (int i = 0; i < 4; ++i)
         for (int rotate = 0; rotate < 2; ++rotate) out.push_back({i, rotate});
       return out;
     },
     [](FilterVariant v, ShadowsParams::Filter& f) { f.poissonIndex = v.a, f.rotateSamples = v.b == 1; }},
    {FilterSettings::PcssSamples,  // 8 << i blocker-search and 8 << j filter taps
     [](const ShadowsParams::Filter& f, Defines& out) {
       out.emplace_back("BLOCKER_COUNT", std::to_string(8 << f.blockerIndex));
       out.emplace_back("PCSS_COUNT", std::to_string(8 << f.pcssIndex));
     },
     [] {
       std::vector<FilterVariant> out;
       for (int i = 0; i < 4; ++i)
         for (int j = 0; j < 4; ++j) out.push_back({i, j});
       return out;
     },
     [](FilterVariant v, ShadowsParams::Filter& f) { f.blockerIndex = v.a, f.pcssIndex = v.b; }},
};
static_assert(coversEnum<FilterSettings>(kFilterSettings));

// The shadow filters: a new filter is its row here, its branch in shadow_filters.glsl (under its
// define) and its test.
struct ShadowFilterRow {
  ShadowFilter value;
  std::string_view name;    // --set shadows.filter=NAME
  std::string_view define;  // what lit.frag tests (and, for a filtered map, moments.frag)
  GLenum momentFormat = 0;  // a filtered map: the moments texture the depth pass writes; 0: depth only
  FilterSettings settings = FilterSettings::None;
  std::string_view help;                    // what it does, for the panel's tooltip and `shadelab list`
  std::array<std::string_view, 2> sweep{};  // the standard sweep's values for it; none given: its name
};
inline constexpr ShadowFilterRow kShadowFilters[] = {
    {ShadowFilter::Hard, "hard", "FILTER_HARD", 0, FilterSettings::None, "one tap"},
    {ShadowFilter::HardwarePcf, "hardware-pcf", "FILTER_HW_PCF", 0, FilterSettings::None,
     "sampler2DShadow, 2x2 bilinear"},
    {ShadowFilter::Pcf,
     "pcf",
     "FILTER_PCF",
     0,
     FilterSettings::PcfSize,
     "N x N taps",
     {"pcf:pcf_size=3", "pcf:pcf_size=5"}},
    {ShadowFilter::Poisson, "poisson", "FILTER_POISSON", 0, FilterSettings::PoissonDisk, "a Poisson disk"},
    {ShadowFilter::Pcss, "pcss", "FILTER_PCSS", 0, FilterSettings::PcssSamples, "blocker search + penumbra-sized PCF"},
    {ShadowFilter::Vsm, "vsm", "FILTER_VSM", GL_RG32F, FilterSettings::None, "variance (two moments)"},
    {ShadowFilter::Esm, "esm", "FILTER_ESM", GL_R32F, FilterSettings::None, "exponential (one warp)"},
    {ShadowFilter::Evsm, "evsm", "FILTER_EVSM", GL_RGBA32F, FilterSettings::None,
     "exponential variance (two warps, four moments)"},
    {ShadowFilter::PcfBilinear, "pcf-bilinear", "FILTER_PCF_BILINEAR", 0, FilterSettings::None,
     "hardware-pcf written out: four taps, bilinear weights"},
};
static_assert(coversEnum<ShadowFilter>(kShadowFilters));

inline std::string filterName(ShadowFilter f) { return std::string(rowOf(kShadowFilters, f).name); }

// The filter parameter's help, from the rows: "hard: one tap; ...", and what filtered maps are.
inline const std::string& filterHelp() {
  static const std::string help = [] {
    std::string text, filtered;
    for (const ShadowFilterRow& row : kShadowFilters) {
      text += std::string(text.empty() ? "" : "; ") + std::string(row.name) + ": " + std::string(row.help);
      if (row.momentFormat) filtered += std::string(filtered.empty() ? "" : ", ") + std::string(row.name);
    }
    return text + ". Filtered maps (" + filtered +
           ") store moments of depth, blurred and mipmapped; a point light "
           "falls back to pcf.";
  }();
  return help;
}
// Filtered maps (VSM, ESM, EVSM): the depth pass writes moments, blurred and mipmapped.
inline GLenum momentFormat(ShadowFilter f) { return rowOf(kShadowFilters, f).momentFormat; }
inline bool isMomentFilter(ShadowFilter f) { return momentFormat(f) != 0; }

// The views. The depth-map views are drawn by their own program: the lit pass under them shades.
inline constexpr NamedDefine<ShadowView> kShadowViews[] = {
    {ShadowView::Shaded, "shaded", "VIEW_SHADED"},
    {ShadowView::Visibility, "visibility", "VIEW_VISIBILITY"},
    {ShadowView::BiasHeat, "bias-heat", "VIEW_BIAS_HEAT"},
    {ShadowView::TexelDensity, "texel-density", "VIEW_TEXEL_DENSITY"},
    {ShadowView::PcssBlocker, "pcss-blocker", "VIEW_PCSS_BLOCKER"},
    {ShadowView::PcssPenumbra, "pcss-penumbra", "VIEW_PCSS_PENUMBRA"},
    {ShadowView::Cascades, "cascades", "VIEW_CASCADES"},
    {ShadowView::DepthRaw, "depth-raw", "VIEW_SHADED"},
    {ShadowView::DepthLinear, "depth-linear", "VIEW_SHADED"},
};
static_assert(coversEnum<ShadowView>(kShadowViews));

inline constexpr Named<MapFit> kFits[] = {{MapFit::Scene, "scene"},
                                          {MapFit::View, "view"},
                                          {MapFit::Cascades, "cascades"},
                                          {MapFit::DepthRange, "depth-range"}};
static_assert(coversEnum<MapFit>(kFits));
inline constexpr std::string_view kCascadeIndices[] = {"1", "2", "3", "4"};
// The depth formats: the name --set takes and the texture format the map is made with.
struct DepthFormatRow {
  DepthFormat value;
  std::string_view name;
  GLenum internalFormat;
};
inline constexpr DepthFormatRow kDepthFormats[] = {
    {DepthFormat::D16, "16", GL_DEPTH_COMPONENT16},
    {DepthFormat::D24, "24", GL_DEPTH_COMPONENT24},
    {DepthFormat::D32F, "32f", GL_DEPTH_COMPONENT32F},
};
static_assert(coversEnum<DepthFormat>(kDepthFormats));
inline constexpr std::string_view kMapSizes[] = {"256", "512", "1024", "2048", "4096", "8192"};
inline constexpr std::string_view kSampleCounts[] = {"8", "16", "32", "64"};
inline constexpr std::string_view kDepthLights[] = {"key", "fill"};

inline ShadowFilter effectiveFilterOf(const ShadowsParams& p) {
  return isMomentFilter(p.filter.type) && p.key.type == LightType::Point ? ShadowFilter::Pcf : p.filter.type;
}

// The views that show a light's depth map itself instead of the lit scene.
inline bool viewIsDepthMap(ShadowView v) { return v == ShadowView::DepthRaw || v == ShadowView::DepthLinear; }

// The directional key light is split (or fitted to the view) only when auto-fit is on.
inline int cascadeCountOf(const ShadowsParams& p) {
  if (p.key.type != LightType::Directional || !p.map.autoFit) return 0;  // 0: the scene-fitted map
  const bool split = p.map.fit == MapFit::Cascades || p.map.fit == MapFit::DepthRange;
  return split ? std::clamp(p.map.cascadeCount, 2, 4) : p.map.fit == MapFit::View ? 1 : 0;
}

}  // namespace shadelab
