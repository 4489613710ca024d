// The shadows lab's option names (as the CLI and presets spell them) and the rules that turn its
// parameters into what is drawn: shared by the lab (shadows_lab.cpp) and its programs
// (shadows_programs.cpp).
#pragma once
#include <algorithm>
#include <string_view>

#include "labs/shadows/shadows_lab.h"

namespace shadelab {

inline constexpr std::string_view kLightTypes[] = {"directional", "spot", "point"};
inline constexpr std::string_view kFilters[] = {"hard", "hardware-pcf", "pcf", "poisson", "pcss", "vsm", "esm", "evsm"};
inline constexpr std::string_view kViews[] = {"shaded", "visibility", "bias-heat", "texel-density", "pcss-blocker",
                                              "pcss-penumbra", "cascades", "depth-raw", "depth-linear"};
inline constexpr std::string_view kFits[] = {"scene", "view", "cascades"};
inline constexpr std::string_view kCascadeIndices[] = {"1", "2", "3", "4"};
inline constexpr std::string_view kFormats[] = {"16", "24", "32f"};
inline constexpr std::string_view kMapSizes[] = {"256", "512", "1024", "2048", "4096", "8192"};
inline constexpr std::string_view kSampleCounts[] = {"8", "16", "32", "64"};
inline constexpr std::string_view kDepthLights[] = {"key", "fill"};
inline const GLenum kFormatEnums[] = {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32F};

inline GLenum momentFormat(ShadowFilter f) {
  return f == ShadowFilter::Esm ? GL_R32F : f == ShadowFilter::Vsm ? GL_RG32F : f == ShadowFilter::Evsm ? GL_RGBA32F : 0;
}

inline ShadowFilter effectiveFilterOf(const ShadowsParams& p) {
  return isMomentFilter(p.filter) && p.keyType == LightType::Point ? ShadowFilter::Pcf : p.filter;
}

// The directional key light is split (or fitted to the view) only when auto-fit is on.
inline int cascadeCountOf(const ShadowsParams& p) {
  if (p.keyType != LightType::Directional || !p.autoFit) return 0;  // 0: the scene-fitted map
  return p.fit == MapFit::Cascades ? std::clamp(p.cascadeCount, 2, 4) : p.fit == MapFit::View ? 1 : 0;
}

}  // namespace shadelab
