// The denoising lab against its truth, the clean mesh: metrics, what the panels show, what the
// student is warned about, the standard sweep and the stress cases.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/util/format.h"
#include "labs/denoise/denoise_lab.h"
#include "labs/denoise/denoise_scenes.h"

namespace shadelab {
namespace {

std::vector<std::string> errorRow(const char* what, const MeshError& e) {
  return {what, formatFixed(e.angleDeg, 2), formatFixed(e.rmsDistance), formatFixed(e.maxDistance),
          formatFixed(e.volumeChangePct, 2)};
}

}  // namespace

ReferenceSpec DenoiseLab::reference() const {
  ReferenceSpec spec;
  spec.kind = TruthKind::Mesh;
  spec.truth = "clean mesh";
  spec.description =
      "the clean mesh the noise was added to (or the published original), vertex for vertex and face "
      "for face; distances in mean edge lengths of the clean mesh";
  spec.cheap = true;  // the metrics come with every result
  return spec;
}

Metrics DenoiseLab::meshMetrics() const {
  if (!result_) return {};
  const DenoiseResult& r = *result_;
  Metrics m = {{"angle_error_deg", r.smoothedError.angleDeg},
               {"rms_distance", r.smoothedError.rmsDistance},
               {"max_distance", r.smoothedError.maxDistance},
               {"volume_change_pct", r.smoothedError.volumeChangePct},
               {"noisy_angle_deg", r.noisyError.angleDeg},
               {"attribute_angle_deg", r.attributeError.angleDeg},
               {"solve_ms", r.solveMs}};
  const SmoothingMethodRow& method = methodRow(r.config.smoothing.method);
  if (method.anyLambda) m.push_back({"factor_ms", r.factorMs});
  if (method.laplacian) {
    m.push_back({"grew_at", double(r.grewAt)});
    m.push_back({"stability_limit", r.stabilityLimit});
  }
  if (r.map) {
    m.push_back({"map_angle_deg", r.mappedError.angleDeg});
    m.push_back({"bake_rms", r.bakeRms});
    m.push_back({"bake_max", r.bakeMax});
    m.push_back({"seam_gap_max", r.seamGapMax});
    m.push_back({"bake_ms", r.bakeMs});
  }
  m.push_back({"attribute_gap_max", r.attributeGapMax});
  if (r.referenceDistance) {
    m.push_back({"reference_distance", *r.referenceDistance});
    m.push_back({"verdict_steps_off", double(r.verdictStepsOff)});
    m.push_back({"energy_difference", r.energyDifference});
  }
  return m;
}

std::vector<PlotSpec> DenoiseLab::plots() const {
  return {{"angle_error_deg", "solve_ms"}, {"rms_distance", "solve_ms"}, {"bake_rms", "bake_ms"}};
}

std::vector<std::string> DenoiseLab::warnings() const {
  std::vector<std::string> w;
  if (!modelNote_.empty()) w.push_back(modelNote_);
  if (!missingPairs_.empty())
    w.push_back("the published noisy/clean pairs are not here (" + missingPairs_ + "): " + kGetDataCommand +
                " fetches them");
  if (!model_) {
    w.push_back("nothing to denoise: the scene has no triangles");
    return w;
  }
  const auto& p = params;
  // Whose noise is on screen: a warning whenever it is not the file's own.
  const bool ownNoise = p.input.source == NoiseSource::Published && !model_->published.empty();
  const std::string generated =
      "generated " + std::string(p.input.noise.kind == NoiseKind::Gaussian ? "gaussian" : "impulsive") +
      " noise (level " + formatFixed(p.input.noise.level, 2) + ", seed " + std::to_string(p.input.noise.seed) + ")";
  if (!ownNoise && !model_->published.empty())
    w.push_back("the noise shown is " + generated + ", not the mesh's own: input = published shows " +
                (pairNote_.empty() ? "the data set's noisy twin" : "the scene file's own noise"));
  else if (!ownNoise && p.input.source == NoiseSource::Published)
    w.push_back("this scene has no noisy twin, so the noise shown is " + generated +
                "; for a noisy mesh of your own "
                "with its clean reference: --scene NOISY --set denoise.clean=CLEAN");
  if (!ownNoise && sceneIsFile_ && p.input.clean.empty())
    w.push_back(std::filesystem::path(modelScene_).filename().string() +
                " is taken as the clean mesh and noise is "
                "generated on it; if it is a noisy mesh, give its clean reference with denoise.clean=CLEAN");
  if (!pairNote_.empty() && pairMoveEdges_ > 2.0)
    w.push_back("the paired vertices lie " + formatFixed(pairMoveEdges_, 1) +
                " mean edges apart on average (noise "
                "is usually well under one): check that the clean file is this mesh's reference");
  const SmoothingMethodRow& method = methodRow(p.smoothing.settings.method);
  if (method.onGpu && p.smoothing.device == SmoothingDevice::Gpu && !gpuUnavailable_.empty())
    w.push_back("smoothing on the CPU: " + gpuUnavailable_);
  if (result_) {
    for (auto& n : result_->notes) w.push_back(n);
    if (method.explicitSteps && result_->stabilityLimit > 0 && p.smoothing.settings.lambda > result_->stabilityLimit &&
        result_->grewAt == 0)
      w.push_back("lambda is above the stable explicit step (about " + formatFixed(result_->stabilityLimit, 2) +
                  "): expect the energy to grow with more iterations");
  }
  if ((p.view.show == DenoiseShow::Map || p.view.show == DenoiseShow::Compare) && !model_->hasUvs())
    w.push_back(
        "this mesh has no UVs: no map can be baked, so the offsets go in as a vertex attribute (the "
        "attribute path) instead");
  if (method.laplacian && !method.explicitSteps && !p.smoothing.settings.alongNormal)
    w.push_back(std::string(method.name) +
                " smoothing moves all three coordinates; along_normal applies to explicit steps only");
  if (p.smoothing.settings.weights == LaplacianWeights::Cotangent && !p.smoothing.settings.clampNegative)
    w.push_back(
        "negative cotangent weights are not clamped: updates are no longer convex combinations and may diverge");
  if (!lastAction_.empty()) w.push_back(lastAction_);
  return w;
}

std::vector<LabPanel> DenoiseLab::panels() const {
  std::vector<LabPanel> out;
  if (!model_) return out;
  const MeshStatistics& s = model_->statistics;
  LabPanel mesh{"Mesh", {}};
  mesh.items.push_back(PanelTable{{"", "count"},
                                  {{"render vertices", std::to_string(s.renderVertices)},
                                   {"positions (welded)", std::to_string(s.logicalVertices)},
                                   {"seam positions", std::to_string(s.seamVertices)},
                                   {"triangles", std::to_string(s.triangles)},
                                   {"boundary edges", std::to_string(s.boundaryEdges)},
                                   {"non-manifold edges", std::to_string(s.nonManifoldEdges)},
                                   {"zero-area faces", std::to_string(s.zeroAreaFaces)},
                                   {"isolated vertices", std::to_string(s.isolatedVertices)},
                                   {"mean edge length", formatFixed(s.meanEdgeLength, 5)}}});
  out.push_back(std::move(mesh));
  if (!result_) return out;
  const DenoiseResult& r = *result_;
  LabPanel result{"Against the clean mesh", {}};
  const bool published = r.config.publishedInput && !model_->published.empty();
  result.items.push_back(PanelText{
      (published
           ? (pairNote_.empty() ? std::string("Input: the published noisy twin. ") : "Input: " + pairNote_ + ". ")
           : "Input: generated " + std::string(r.config.noise.kind == NoiseKind::Gaussian ? "Gaussian" : "impulsive") +
                 " noise, level " + formatFixed(r.config.noise.level, 2) + ", seed " +
                 std::to_string(r.config.noise.seed) +
                 (r.config.publishedInput ? " (this mesh has no published twin). " : ". ")) +
      "Angles in degrees; distances in mean edge lengths of the clean mesh."});
  PanelTable errors{{"", "angle", "RMS", "max", "volume %"}, {}};
  errors.rows.push_back(errorRow("noisy input", r.noisyError));
  errors.rows.push_back(errorRow("smoothed", r.smoothedError));
  errors.rows.push_back(errorRow("attribute path", r.attributeError));
  if (r.map) errors.rows.push_back(errorRow("map path", r.mappedError));
  result.items.push_back(std::move(errors));
  const SmoothingMethodRow& method = methodRow(r.config.smoothing.method);
  const bool gpu = r.config.device == SmoothingDevice::Gpu && method.onGpu;
  PanelTable cost{{"", "value"}, {{gpu ? "smoothing ms (GPU)" : "smoothing ms", formatFixed(r.solveMs, 1)}}};
  if (r.referenceDistance) {
    cost.rows.push_back({"GPU vs CPU, RMS (edges)", formatNumber(*r.referenceDistance)});
    cost.rows.push_back({"GPU vs CPU, verdict steps apart", std::to_string(r.verdictStepsOff)});
    cost.rows.push_back({"GPU vs CPU, energy (largest relative difference)", formatNumber(r.energyDifference)});
  }
  if (method.anyLambda) cost.rows.push_back({"  of which factorisation ms", formatFixed(r.factorMs, 1)});
  if (method.laplacian) cost.rows.push_back({"stable explicit lambda (about)", formatFixed(r.stabilityLimit, 3)});
  if (r.map) {
    cost.rows.push_back({"bake ms", formatFixed(r.bakeMs, 1)});
    cost.rows.push_back({"bake RMS / max (edges)", formatFixed(r.bakeRms, 4) + " / " + formatFixed(r.bakeMax, 4)});
    cost.rows.push_back({"seam gap, map path (edges)", formatFixed(r.seamGapMax, 4)});
  }
  cost.rows.push_back({"seam gap, attribute path (edges)", formatFixed(r.attributeGapMax, 4)});
  result.items.push_back(std::move(cost));
  out.push_back(std::move(result));

  LabPanel trace{"Convergence", {}};
  if (!r.energy.empty()) {
    PanelPlot plot{"smoothing energy per iteration", "iteration", "sum <delta, n>^2", true, {}, {}};
    PanelSeries e{"energy", {}, {}};
    for (size_t i = 0; i < r.energy.size(); ++i) {
      e.x.push_back(float(i));
      e.y.push_back(float(r.energy[i]));
    }
    plot.series.push_back(std::move(e));
    if (r.grewAt > 0) plot.markX.push_back(float(r.grewAt));
    trace.items.push_back(std::move(plot));
    if (r.grewAt > 0) trace.items.push_back(PanelText{"The dashed line: the iteration where the energy grew."});
  } else if (!r.normalChangeDeg.empty()) {
    PanelPlot plot{"mean face-normal change per filtering pass", "pass", "degrees", true, {}, {}};
    PanelSeries c{"change", {}, {}};
    for (size_t i = 0; i < r.normalChangeDeg.size(); ++i) {
      c.x.push_back(float(i + 1));
      c.y.push_back(float(r.normalChangeDeg[i]));
    }
    plot.series.push_back(std::move(c));
    trace.items.push_back(std::move(plot));
  }
  out.push_back(std::move(trace));

  if (r.map && mapPreview_) {
    LabPanel map{"Displacement map", {}};
    const std::string caption = std::to_string(r.map->size.x) + "^2, offset = stored x " +
                                formatFixed(r.map->scale, 5) + " + " + formatFixed(r.map->bias, 5) +
                                "; grey = its own range; " +
                                (r.map->repeat ? "repeats (the UVs leave [0, 1])" : "clamps (the UVs stay in [0, 1])");
    map.items.push_back(PanelImage{&mapPreview_, {256, 256}, caption});
    if (params.view.show == DenoiseShow::Compare)
      map.items.push_back(
          PanelText{"Compare: the map path, the attribute path, the smoothed mesh (left to right in a wide "
                    "view, top to bottom in a tall one)."});
    out.push_back(std::move(map));
  }
  return out;
}

std::vector<SweepAxis> DenoiseLab::standardSweep() const {
  // Each method over its main knob; lambda for the Laplacian ones (iterations fixed at 10).
  return {{"method",
           {"explicit:lambda=0.1", "explicit:lambda=0.3", "explicit:lambda=0.6", "explicit:lambda=0.9",
            "taubin:lambda=0.3", "taubin:lambda=0.6", "implicit:lambda=0.3", "implicit:lambda=1", "implicit:lambda=3",
            "bilateral:sigma_r=0.2", "bilateral:sigma_r=0.35", "bilateral:sigma_r=0.6"}},
          {"iterations", {"3", "10", "30"}}};
}

std::vector<StressCase> DenoiseLab::stressCases() const {
  const auto edit = [](auto change) { return fromDefaults<DenoiseLab>(change); };
  std::vector<StressCase> cases = {
      {"explicit-lambda-2", edit([](DenoiseParams& p) {
         p.smoothing.settings.lambda = 2.0f, p.smoothing.settings.iterations = 30,
         p.smoothing.settings.alongNormal = false;
       }),
       "", "", "diverging"},
      {"explicit-lambda-2-along-normal",
       edit([](DenoiseParams& p) { p.smoothing.settings.lambda = 2.0f, p.smoothing.settings.iterations = 30; }), "", "",
       "diverging"},
      {"cotangent-beyond-its-limit", edit([](DenoiseParams& p) {
         p.smoothing.settings.weights = LaplacianWeights::Cotangent, p.smoothing.settings.lambda = 1.25f,
         p.smoothing.settings.iterations = 60, p.smoothing.settings.alongNormal = false;
       }),
       "", "", "diverging"},
      {"explicit-lambda-huge",
       edit([](DenoiseParams& p) { p.smoothing.settings.lambda = 100000.0f, p.smoothing.settings.iterations = 50; }),
       "", "", "stopped at iteration"},
      {"explicit-lambda-1.5-runs-away", edit([](DenoiseParams& p) {
         p.smoothing.settings.lambda = 1.5f, p.smoothing.settings.iterations = 200,
         p.smoothing.settings.alongNormal = false;
       }),
       "", "", "stopped at iteration"},
      // Implicit steps never diverge, but a large lambda pulls a closed mesh to a point: the lab says
      // so (not "diverging"), and preserve_volume scales it back.
      {"implicit-1000x-limit", edit([](DenoiseParams& p) {
         p.smoothing.settings.method = SmoothingMethod::Implicit, p.smoothing.settings.lambda = 1000.0f,
         p.smoothing.settings.iterations = 20;
       }),
       "denoise-cube", "", "stable but shrinks"},
      {"implicit-lambda-1e5-cotangent", edit([](DenoiseParams& p) {
         p.smoothing.settings.method = SmoothingMethod::Implicit,
         p.smoothing.settings.weights = LaplacianWeights::Cotangent, p.smoothing.settings.lambda = 100000.0f;
       }),
       "denoise-cube", "", "stable but shrinks"},
      {"implicit-lambda-10-volume-preserved", edit([](DenoiseParams& p) {
         p.smoothing.settings.method = SmoothingMethod::Implicit, p.smoothing.settings.lambda = 10.0f,
         p.smoothing.preserveVolume = true;
       }),
       "denoise-cube", "", "to restore it"},
      {"implicit-lambda-1e5-collapses-volume-preserved", edit([](DenoiseParams& p) {
         p.smoothing.settings.method = SmoothingMethod::Implicit, p.smoothing.settings.lambda = 100000.0f,
         p.smoothing.preserveVolume = true;
       }),
       "denoise-cube", "", "collapsed to a point"},
      {"taubin-unclamped-cotangent", edit([](DenoiseParams& p) {
         p.smoothing.settings.method = SmoothingMethod::Taubin,
         p.smoothing.settings.weights = LaplacianWeights::Cotangent, p.smoothing.settings.clampNegative = false;
       }),
       "", "", "not clamped"},
      {"slivers-cotangent", edit([](DenoiseParams& p) {
         p.smoothing.settings.weights = LaplacianWeights::Cotangent, p.input.source = NoiseSource::Generated;
       }),
       "denoise-degenerate", "", "were negative"},
      {"slivers-unclamped", edit([](DenoiseParams& p) {
         p.smoothing.settings.weights = LaplacianWeights::Cotangent, p.smoothing.settings.clampNegative = false,
         p.input.source = NoiseSource::Generated;
       }),
       "denoise-degenerate", "", "not clamped"},
      {"slivers-implicit", edit([](DenoiseParams& p) {
         p.smoothing.settings.method = SmoothingMethod::Implicit,
         p.smoothing.settings.weights = LaplacianWeights::Cotangent, p.input.source = NoiseSource::Generated;
       }),
       "denoise-degenerate", "", ""},
      {"slivers-bilateral", edit([](DenoiseParams& p) {
         p.smoothing.settings.method = SmoothingMethod::Bilateral, p.input.source = NoiseSource::Generated;
       }),
       "denoise-degenerate", "", ""},
      {"noise-level-2",
       edit([](DenoiseParams& p) { p.input.source = NoiseSource::Generated, p.input.noise.level = 2.0f; }), "", "", ""},
      {"impulsive-everything", edit([](DenoiseParams& p) {
         p.input.source = NoiseSource::Generated, p.input.noise.kind = NoiseKind::Impulsive,
         p.input.noise.impulsiveFraction = 1.0f;
       }),
       "", "", ""},
      {"no-noise", edit([](DenoiseParams& p) { p.input.source = NoiseSource::Generated, p.input.noise.level = 0.0f; }),
       "", "", ""},
      {"bilateral-sigma-tiny", edit([](DenoiseParams& p) {
         p.smoothing.settings.method = SmoothingMethod::Bilateral, p.smoothing.bilateral.sigmaR = 0.02f;
       }),
       "", "", "changed almost nothing"},
      {"weld-off-cracks", edit([](DenoiseParams& p) {
         p.smoothing.weld = false, p.input.source = NoiseSource::Generated, p.view.show = DenoiseShow::Attribute,
         p.view.mode = DenoiseView::SeamGap;
       }),
       "denoise-cube", "", "welding is off"},
      {"map-4096-nearest", edit([](DenoiseParams& p) {
         p.input.source = NoiseSource::Generated, p.map.sizeIndex = DenoiseParams::Map::sizeIndexOf(4096),
         p.map.bake.method = BakeMethod::NearestExact, p.view.show = DenoiseShow::Map;
       }),
       "denoise-cube", "", ""},
      {"approx-one-check", edit([](DenoiseParams& p) {
         p.input.source = NoiseSource::Generated, p.map.bake.method = BakeMethod::NearestApprox, p.map.bake.checks = 1,
         p.view.show = DenoiseShow::Compare;
       }),
       "denoise-cube", "", "not the nearest"},
      {"map-without-uvs", edit([](DenoiseParams& p) { p.view.show = DenoiseShow::Map; }), "denoise-sphere-no-uvs", "",
       "no UVs"},
      {"empty-scene", {}, "empty", "", "nothing to denoise"},
  };
  // The explicit and Taubin cases again with their steps on the GPU: the same verdicts, named alike.
  for (const char* name : {"explicit-lambda-2", "explicit-lambda-2-along-normal", "cotangent-beyond-its-limit",
                           "explicit-lambda-huge", "explicit-lambda-1.5-runs-away", "taubin-unclamped-cotangent",
                           "slivers-cotangent", "slivers-unclamped", "weld-off-cracks"}) {
    auto it = std::find_if(cases.begin(), cases.end(), [&](const StressCase& c) { return c.name == name; });
    if (it == cases.end()) continue;  // a name above that the list lost: the test's count of cases says so
    StressCase onGpu = *it;
    onGpu.name += "-gpu";
    onGpu.settings.emplace_back("device", "gpu");
    cases.push_back(std::move(onGpu));
  }
  return cases;
}

}  // namespace shadelab
