// The shadows lab's programs: which shader files and #defines each configuration draws with, and
// the variant space check-shaders compiles.
#include <functional>
#include <set>

#include "app/lab/variants.h"
#include "labs/shadows/shadow_options.h"
#include "labs/shadows/shadows_lab.h"

namespace shadelab {

ProgramSpec ShadowsLab::litSpec(const ShadowsParams& p, InternalView internal) {
  ProgramSpec spec;
  spec.stages = {{GL_VERTEX_SHADER, "shadows/lit.vert"}, {GL_FRAGMENT_SHADER, "shadows/lit.frag"}};
  spec.defines.emplace_back("KEY_TYPE", std::to_string(int(p.key.type)));
  const bool gbuffer = internal != InternalView::None;
  if (p.key.casts && !gbuffer) spec.defines.emplace_back("KEY_CASTS", "1");
  if (p.fill.on && !gbuffer) {
    spec.defines.emplace_back("FILL_LIGHT", "1");
    if (p.fill.casts) spec.defines.emplace_back("FILL_CASTS", "1");
  }
  if (p.map.farFix) spec.defines.emplace_back("FAR_FIX", "1");
  if (p.bias.receiverPlane) spec.defines.emplace_back("RECEIVER_PLANE", "1");
  const ShadowFilter filter = effectiveFilterOf(p);
  spec.defines.emplace_back(rowOf(kShadowFilters, filter).define, "1");
  rowOf(kFilterSettings, rowOf(kShadowFilters, filter).settings).defines(p.filter, spec.defines);
  if (const int cascades = cascadeCountOf(p); cascades >= 2 && p.key.casts && !gbuffer)
    spec.defines.emplace_back("CASCADE_COUNT", std::to_string(cascades));
  spec.defines.emplace_back(internal == InternalView::Position ? "VIEW_POSITION"
                            : internal == InternalView::Normal ? "VIEW_NORMAL"
                                                               : rowOf(kShadowViews, p.view.mode).define,
                            "1");
  spec.name = "shadows/lit " + std::string(rowOf(kLightTypes, p.key.type).name) + " " + filterName(filter);
  return spec;
}

ProgramSpec ShadowsLab::depthSpec(bool cube, bool sixPasses, ShadowFilter filter) {
  ProgramSpec spec;
  const bool oneCubePass = cube && !sixPasses;
  const bool moments = !cube && isMomentFilter(filter);
  spec.name = oneCubePass ? "shadows/depth cube" : cube ? "shadows/depth cube face" : "shadows/depth";
  spec.stages.push_back({GL_VERTEX_SHADER, "shadows/depth.vert"});
  if (oneCubePass) spec.stages.push_back({GL_GEOMETRY_SHADER, "shadows/depth_cube.geom"});
  spec.stages.push_back({GL_FRAGMENT_SHADER, moments ? "shadows/moments.frag" : "shadows/depth.frag"});
  if (cube) spec.defines.emplace_back(oneCubePass ? "CUBE_MAP" : "CUBE_FACE", "1");
  if (moments) {
    spec.defines.emplace_back("MOMENTS", "1");
    spec.defines.emplace_back(rowOf(kShadowFilters, filter).define, "1");
    spec.name += " " + filterName(filter) + " moments";
  }
  return spec;
}

ProgramSpec ShadowsLab::blurSpec() {
  ProgramSpec spec;
  spec.name = "shadows/moment blur";
  spec.stages = {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadows/blur.frag"}};
  return spec;
}

ProgramSpec ShadowsLab::linesSpec() {
  ProgramSpec spec;
  spec.name = "shadows/lines";
  spec.stages = {{GL_VERTEX_SHADER, "shadows/lines.vert"}, {GL_FRAGMENT_SHADER, "shadows/lines.frag"}};
  return spec;
}

ProgramSpec ShadowsLab::depthViewSpec(const ShadowsParams& p) {
  ProgramSpec spec;
  spec.name = "shadows/depth view";
  spec.stages = {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadows/depth_view.frag"}};
  const LightType shown = p.view.depthLight == 1 ? LightType::Spot : p.key.type;  // the fill light is a spot
  spec.defines.emplace_back("KEY_TYPE", std::to_string(int(shown)));
  if (p.view.mode == ShadowView::DepthLinear) spec.defines.emplace_back("LINEAR_DEPTH", "1");
  return spec;
}

std::vector<ProgramSpec> ShadowsLab::allPrograms() const {
  std::vector<ProgramSpec> all = {depthSpec(false, false, ShadowFilter::Hard),
                                  depthSpec(true, false, ShadowFilter::Hard),
                                  depthSpec(true, true, ShadowFilter::Hard),
                                  linesSpec(),
                                  blurSpec(),
                                  GpuShadowTracer::programSpec(false),
                                  GpuShadowTracer::programSpec(true),
                                  GpuShadowTracer::resolveSpec(),
                                  DepthRange::programSpec(true),
                                  DepthRange::programSpec(false)};
  for (const ShadowFilterRow& row : kShadowFilters)
    if (isMomentFilter(row.value)) all.push_back(depthSpec(false, false, row.value));
  ShadowsParams p;
  for (int type = 0; type < 3; ++type) {
    p.key.type = LightType(type);
    for (ShadowView view : {ShadowView::DepthRaw, ShadowView::DepthLinear}) {
      p.view.mode = view;
      all.push_back(depthViewSpec(p));
    }
  }
  p.view.depthLight = 1;
  all.push_back(depthViewSpec(p));

  // The lit program: every value of every parameter that shapes it, and every pair of values of
  // any two of them (app/lab/variants.h), each a named dimension that sets its parameter. A filter
  // and its own settings form one dimension: pcf_size means nothing to pcss.
  struct Filtered {
    ShadowFilter filter;
    FilterVariant settings;
  };
  std::vector<Filtered> filters;  // the filters without settings of their own first
  for (const ShadowFilterRow& row : kShadowFilters)
    if (row.settings == FilterSettings::None) filters.push_back({row.value, {}});
  for (const ShadowFilterRow& row : kShadowFilters)
    if (row.settings != FilterSettings::None)
      for (FilterVariant v : rowOf(kFilterSettings, row.settings).variants()) filters.push_back({row.value, v});
  constexpr ShadowView kLitViews[] = {ShadowView::Shaded,       ShadowView::Visibility,  ShadowView::BiasHeat,
                                      ShadowView::TexelDensity, ShadowView::PcssBlocker, ShadowView::PcssPenumbra,
                                      ShadowView::Cascades};
  constexpr int kViewCount = int(std::size(kLitViews));
  struct Dimension {
    const char* name;
    int size;
    std::function<void(int value, ShadowsParams& q, InternalView& internal)> set;
  };
  const Dimension dimensions[] = {
      {"light type", 3, [](int v, ShadowsParams& q, InternalView&) { q.key.type = LightType(v); }},
      {"filter and its settings", int(filters.size()),
       [&](int v, ShadowsParams& q, InternalView&) {
         const Filtered& f = filters[size_t(v)];
         q.filter.type = f.filter;
         rowOf(kFilterSettings, rowOf(kShadowFilters, f.filter).settings).apply(f.settings, q.filter);
       }},
      {"view, and the reference's g-buffer views", kViewCount + 2,
       [&](int v, ShadowsParams& q, InternalView& internal) {
         if (v < kViewCount)
           q.view.mode = kLitViews[v];
         else
           internal = v == kViewCount ? InternalView::Position : InternalView::Normal;
       }},
      {"fill light: off, on, casting", 3,
       [](int v, ShadowsParams& q, InternalView&) { q.fill.on = v > 0, q.fill.casts = v == 2; }},
      {"key light casts", 2, [](int v, ShadowsParams& q, InternalView&) { q.key.casts = v == 1; }},
      {"far-plane fix", 2, [](int v, ShadowsParams& q, InternalView&) { q.map.farFix = v == 1; }},
      {"receiver-plane bias", 2, [](int v, ShadowsParams& q, InternalView&) { q.bias.receiverPlane = v == 1; }},
      {"map fit: scene, view, cascades x 2, 3, 4", 5,
       [](int v, ShadowsParams& q, InternalView&) {
         q.map.fit = v == 0 ? MapFit::Scene : v == 1 ? MapFit::View : MapFit::Cascades;
         q.map.cascadeCount = std::max(v, 2);
       }},
  };
  std::vector<int> sizes;
  for (const Dimension& d : dimensions) sizes.push_back(d.size);
  for (const auto& row : pairwiseCover(sizes)) {
    ShadowsParams q;
    InternalView internal = InternalView::None;
    for (size_t d = 0; d < std::size(dimensions); ++d) dimensions[d].set(row[d], q, internal);
    all.push_back(litSpec(q, internal));
  }

  // ... and the defaults with any one selectable parameter changed, found from the parameter
  // list itself, so a parameter added later is covered without being named here.
  struct Knobs final : ParamVisitor {
    std::vector<std::function<void(int)>> set;  // set(value) for each value 0..count-1
    std::vector<int> counts;
    void floatParam(const ParamInfo&, float&, float, float, bool) override {}
    void intParam(const ParamInfo&, int& v, int lo, int hi) override {
      if (hi - lo > 16) return;  // a count, not a switch (tessellation): no define depends on it
      set.push_back([&v, lo](int k) { v = lo + k; });
      counts.push_back(hi - lo + 1);
    }
    void boolParam(const ParamInfo&, bool& v) override {
      set.push_back([&v](int k) { v = k != 0; });
      counts.push_back(2);
    }
    void choiceParam(const ParamInfo&, int& v, std::span<const std::string_view> names) override {
      set.push_back([&v](int k) { v = k; });
      counts.push_back(int(names.size()));
    }
  };
  ShadowsParams knobbed;
  Knobs knobs;
  visitParamsOf(knobs, knobbed, false);
  for (size_t k = 0; k < knobs.set.size(); ++k)
    for (int value = 0; value < knobs.counts[k]; ++value) {
      knobbed = ShadowsParams{};
      knobs.set[k](value);
      for (auto& spec : programsOf(knobbed, knobbed.map.sixCubePasses)) all.push_back(std::move(spec));
    }
  // One of each: the library compiles a key once, but a shorter list is a faster check.
  std::set<std::string> seen;
  std::erase_if(all, [&](const ProgramSpec& spec) { return !seen.insert(spec.key()).second; });
  return all;
}

std::vector<ProgramSpec> ShadowsLab::currentPrograms() const { return programsOf(params, sixCubePasses()); }

std::vector<ProgramSpec> ShadowsLab::programsOf(const ShadowsParams& p, bool sixPasses) {
  const ShadowFilter filter = effectiveFilterOf(p);
  std::vector<ProgramSpec> out = {litSpec(p, InternalView::None), litSpec(p, InternalView::Position),
                                  depthSpec(p.key.type == LightType::Point, sixPasses, filter),
                                  depthSpec(false, false, filter), depthViewSpec(p)};
  if (isMomentFilter(filter)) out.push_back(blurSpec());
  if (p.map.fit == MapFit::DepthRange)
    out.insert(out.end(), {DepthRange::programSpec(true), DepthRange::programSpec(false)});
  return out;
}

}  // namespace shadelab
