#include "labs/denoise/denoise_lab.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <nlohmann/json.hpp>

#include "app/measure/report.h"
#include "app/scene/loaders.h"
#include "app/util/output_files.h"
#include "labs/denoise/denoise_scenes.h"
#include "labs/denoise/mesh_pair.h"

namespace shadelab {
namespace {

// The files a clean reference may be, and the map's sizes (64 << index): lists of values, not
// names of an enum's values (those are the technique tables beside each enum).
constexpr std::string_view kMeshFiles[] = {".obj", ".off", ".ply"};
constexpr std::string_view kMapSizes[] = {"64", "128", "256", "512", "1024", "2048", "4096"};
static_assert(std::size(kMapSizes) == size_t(DenoiseParams::Map::sizeIndexOf(4096)) + 1);

// One mesh of every instance, in world space: the lab denoises what the scene shows.
MeshData mergeInstances(const Scene& scene) {
  MeshData out;
  out.name = scene.name;
  bool uvs = !scene.instances.empty(), numbered = !scene.instances.empty();
  for (auto& inst : scene.instances) {
    uvs &= !scene.meshes[size_t(inst.mesh)].uvs.empty();
    numbered &= !scene.meshes[size_t(inst.mesh)].sourceVertex.empty();  // OBJ: numbers across the file
  }
  for (auto& inst : scene.instances) {
    const MeshData& m = scene.meshes[size_t(inst.mesh)];
    const uint32_t base = uint32_t(out.positions.size());
    for (auto& p : m.positions) out.positions.push_back(glm::vec3(inst.model * glm::vec4(p, 1.0f)));
    if (uvs) out.uvs.insert(out.uvs.end(), m.uvs.begin(), m.uvs.end());
    if (numbered) out.sourceVertex.insert(out.sourceVertex.end(), m.sourceVertex.begin(), m.sourceVertex.end());
    for (uint32_t i : m.indices) out.indices.push_back(base + i);
  }
  return out;
}

}  // namespace

DenoiseLab::DenoiseLab() = default;
DenoiseLab::~DenoiseLab() = default;

std::string_view DenoiseLab::summary() const {
  return "Noise moves vertices along their normals; Laplacian smoothing moves each one back towards the mean of its "
         "neighbours, p' = p - lambda <delta, n> n. Drag lambda past the stable step and watch the energy plot; "
         "switch to implicit and it never diverges (a large lambda shrinks the mesh instead: preserve_volume); "
         "switch to bilateral and the sharp edges survive. On a mesh with UVs (the cube's six charts) the offsets "
         "are baked into a displacement map: show 'compare' and the seam-gap view to see where a map cracks and "
         "the attribute path does not. Every number is against the clean mesh: a data set's (fandisk-0.3 and the "
         "other published pairs, from tools/get_data.sh) or your own (--scene NOISY --set denoise.clean=CLEAN).";
}

std::string_view DenoiseLab::defaultScene() const { return denoiseDefaultScene(); }

std::vector<SceneRecipe> DenoiseLab::scenes() const { return denoiseScenes(); }

// One function per section of the panel, each given its own part of the parameters.
namespace {

void visitInput(ParamVisitor& v, DenoiseParams::Input& input) {
  v.enumParam({"input", "Input", "",
               "published: the mesh's own noise (the data set's noisy twin, or the scene's file "
               "when a clean reference is given); generated: noise added to the clean mesh here with the settings "
               "below."},
              input.source, namesOf<kNoiseSources>());
  v.fileParam({"clean", "Clean reference", "",
               "Your own pair: the scene (--scene NOISY) is the noisy mesh and this file "
               "its clean reference, with the same vertices in the same order or the same faces in the same order. "
               "Every error is then against it."},
              input.clean, kMeshFiles);
  v.enumParam({"noise", "Noise", "",
               "gaussian: every vertex moves along its normal; impulsive: only a random "
               "fraction does."},
              input.noise.kind, namesOf<kNoiseKinds>());
  v.floatParam({"noise_level", "Noise level", "edges",
                "Standard deviation of the move, in mean edge lengths of the "
                "clean mesh."},
               input.noise.level, 0.0f, 2.0f);
  v.floatParam({"impulsive_fraction", "Impulsive fraction", "", "Share of the vertices impulsive noise moves."},
               input.noise.impulsiveFraction, 0.0f, 1.0f);
  v.intParam({"seed", "Seed", "", "Random seed of the generated noise: the same seed, the same noise everywhere."},
             input.noise.seed, 0, 1000000);
  v.action({"add_noise", "Add new noise", "", "Draws fresh generated noise (seed + 1) and switches the input to it."},
           [&input] {
             ++input.noise.seed;
             input.source = NoiseSource::Generated;
           });
}

void visitSmoothing(ParamVisitor& v, DenoiseParams::Smoothing& smoothing) {
  v.enumParam({"method", "Method", "",
               "explicit: p' = p - lambda <delta,n> n, stable only for small steps; taubin: a "
               "lambda step then a shrink-undoing mu step; implicit: (D + lambda L) x' = D x, stable for any lambda; "
               "bilateral: filters face normals, keeping sharp edges (Zheng et al. 2011)."},
              smoothing.settings.method, namesOf<kSmoothingMethods>());
  v.enumParam({"weights", "Laplacian weights", "",
               "uniform: every neighbour alike; cotangent: by the angles opposite "
               "each edge, following the geometry rather than the triangulation."},
              smoothing.settings.weights, namesOf<kLaplacianWeights>());
  v.floatParam({"lambda", "Lambda", "",
                "Step size. Explicit and Taubin: stable up to 2 / mu_max (the panel shows it, "
                "about 1); implicit: any value, larger = smoother."},
               smoothing.settings.lambda, 1e-3f, 1e5f, true);
  v.intParam({"iterations", "Iterations", "", "Smoothing steps (bilateral: vertex updates)."},
             smoothing.settings.iterations, 1, 200);
  v.boolParam({"along_normal", "Along the normal", "",
               "Explicit and Taubin move each vertex along its normal only "
               "(the homework); off: the full umbrella vector, which also slides vertices along the surface."},
              smoothing.settings.alongNormal);
  v.boolParam({"clamp_cotangent", "Clamp negative weights", "",
               "Obtuse triangles make cotangent weights negative; "
               "clamped to 0, every update stays a convex combination."},
              smoothing.settings.clampNegative);
  v.floatParam({"pass_band", "Taubin pass band", "", "k_pb: mu = 1 / (k_pb - 1 / lambda)."},
               smoothing.settings.passBand, 0.01f, 0.3f);
  if (const SmoothingMethodRow& method = methodRow(smoothing.settings.method); !method.onGpu)
    v.unavailable(std::string(method.name) + " smoothing runs on the CPU");
  v.enumParam({"device", "Device", "",
               "Where explicit and Taubin steps run. gpu: one fragment per vertex, "
               "shaders/denoise/smooth_step.frag with your laplacian_step.glsl, positions in float textures; "
               "the same weights, normals and divergence checks as the CPU, in float rather than double."},
              smoothing.device, namesOf<kSmoothingDevices>());
  if (smoothing.device != SmoothingDevice::Gpu) v.unavailable("only with device gpu");
  v.boolParam({"cpu_reference", "CPU reference", "",
               "With device gpu, smooth on the CPU too and report how far the GPU's mesh lies from it "
               "(reference_distance, in mean edges) and by how many steps their divergence verdicts differ "
               "(verdict_steps_off). Off for a mesh too large for the CPU to keep up."},
              smoothing.cpuReference);
  v.floatParam({"sigma_r", "Bilateral sigma_r", "",
                "How different two face normals (|n_i - n_j|) may be and still "
                "be averaged: small keeps more edges."},
               smoothing.bilateral.sigmaR, 0.02f, 2.0f, true);
  v.intParam({"normal_iterations", "Bilateral normal passes", "",
              "Passes of the normal filter before the vertices "
              "are fitted."},
             smoothing.bilateral.normalIterations, 1, 100);
  v.boolParam({"weld", "Weld seams", "",
               "Smooth the welded surface (one vertex per position). Off: copies of a "
               "position split by UV seams are smoothed apart, the homework's crack."},
              smoothing.weld);
  v.boolParam({"preserve_volume", "Preserve volume", "",
               "Every smoothing shrinks a closed mesh (implicit with a large "
               "lambda, to a point). Implicit fairing's remedy (Desbrun et al. 1999): scale the result about its "
               "centroid back to the input's volume. The volume % column shows the effect."},
              smoothing.preserveVolume);
}

void visitMap(ParamVisitor& v, DenoiseParams::Map& map, const std::function<void()>& saveMap) {
  v.choiceParam({"map_size", "Map size", "texels", "Resolution of the baked map (square)."}, map.sizeIndex, kMapSizes);
  v.enumParam(
      {"bake", "Bake", "",
       "nearest-exact: each texel takes its nearest vertex's offset (FLANN kd-tree): exact "
       "at the vertices, where a vertex shader reads it; nearest-approx: FLANN's randomised trees with a budget "
       "of checks; raster: interpolated inside each UV triangle and dilated into the gutter: smooth between "
       "vertices (what tessellation or a per-fragment read wants), but a bilinear read at a vertex blends it "
       "with its neighbours."},
      map.bake.method, namesOf<kBakeMethods>());
  v.intParam({"checks", "FLANN checks", "",
              "nearest-approx: leaves visited per query. Fewer: faster, more often "
              "not the nearest."},
             map.bake.checks, 1, 512);
  v.intParam({"gutter", "Gutter", "texels",
              "raster: texels of dilation around each UV chart, so bilinear lookups "
              "near a seam read their own chart."},
             map.bake.gutter, 0, 16);
  v.enumParam({"map_format", "Map format", "bits", "8 or 16-bit normalised with a bias and scale, or float."},
              map.bake.format, namesOf<kMapFormats>());
  v.boolParam({"bilinear", "Bilinear lookup", "",
               "The vertex shader samples the map bilinearly (off: nearest "
               "texel)."},
              map.bilinear);
  v.action({"bake_files", "Save the map", "",
            "Writes the map as out/bakes/<scene>-*.png (+ .raw texels, + .json with "
            "bias, scale and format)."},
           saveMap);
}

void visitView(ParamVisitor& v, DenoiseParams::View& view) {
  v.enumParam({"show", "Show", "",
               "smoothed: the method's mesh; noisy; clean; map: the noisy mesh displaced by the map "
               "in the vertex shader; attribute: displaced by the same offsets as a vertex attribute; compare: map, "
               "attribute and smoothed side by side."},
              view.show, namesOf<kDenoiseShows>());
  v.enumParam({"view", "View", "",
               "shaded (flat, so noise shows); error: distance to the clean mesh; offset: the "
               "signed offset along the normal; seam-gap: how far copies of a position moved apart."},
              view.mode, namesOf<kDenoiseViews>());
  v.floatParam({"heat_scale", "Heat scale", "edges",
                "Mean edge lengths at full colour in the error and seam-gap views "
                "(offsets: +-2x this)."},
               view.heatScale, 1e-3f, 10.0f, true);
}

}  // namespace

void DenoiseLab::visitParams(ParamVisitor& v) {
  v.section("Noisy input");
  visitInput(v, params.input);
  v.section("Smoothing");
  visitSmoothing(v, params.smoothing);
  v.section("Displacement map");
  visitMap(v, params.map, [this] { lastAction_ = saveMap(); });
  v.section("View");
  visitView(v, params.view);
}

SceneNeeds DenoiseLab::needs() const {
  SceneNeeds n;
  n.uvs = true;  // the bake reads them; a mesh without them uses the attribute path
  return n;
}

DenoiseConfig DenoiseLab::config() const {
  const auto& p = params;
  DenoiseConfig c;
  c.publishedInput = p.input.source == NoiseSource::Published;
  c.noise = p.input.noise;
  c.smoothing = p.smoothing.settings;
  c.bilateral = p.smoothing.bilateral;
  c.bilateral.vertexIterations = p.smoothing.settings.iterations;  // one iterations slider serves both
  c.weld = p.smoothing.weld;
  c.preserveVolume = p.smoothing.preserveVolume;
  c.device = p.smoothing.device;
  c.cpuReference = p.smoothing.cpuReference;
  c.bake = p.map.bake;
  c.bake.resolution = 64 << p.map.sizeIndex;
  c.bilinear = p.map.bilinear;
  return c;
}

ProgramSpec DenoiseLab::programSpec(DenoiseView view, Path path) {
  ProgramSpec spec;
  spec.stages = {{GL_VERTEX_SHADER, "denoise/mesh.vert"}, {GL_FRAGMENT_SHADER, "denoise/mesh.frag"}};
  const NamedDefine<Path>& row = rowOf(kPaths, path);
  spec.name = "denoise/" + std::string(row.name);
  if (!row.define.empty()) spec.defines.emplace_back(std::string(row.define), "1");
  if (view == DenoiseView::Offset)
    spec.defines.emplace_back("VIEW_SIGNED", "1");
  else if (view != DenoiseView::Shaded)
    spec.defines.emplace_back("VIEW_HEAT", "1");
  return spec;
}

std::vector<ProgramSpec> DenoiseLab::allPrograms() const {
  std::vector<ProgramSpec> all;
  for (int view = 0; view < 4; ++view)
    for (Path path : {Path::Plain, Path::Map, Path::Attribute, Path::SmoothedOnGpu})
      all.push_back(programSpec(DenoiseView(view), path));
  for (ProgramSpec& spec : GpuSmoother::programSpecs()) all.push_back(std::move(spec));
  return all;
}

std::string DenoiseLab::setup(LabContext& ctx) {
  shaders_ = &ctx.shaders;
  jobs_ = &ctx.jobs;
  gpuUnavailable_ = GpuSmoother::unavailableReason();
  return {};
}

void DenoiseLab::rebuildModel(const Scene& scene) {
  modelRevision_ = scene.revision;
  gpuInput_.reset();  // another model (the same scene with another clean file, too): upload its mesh again
  modelScene_ = scene.name;
  modelNote_.clear();
  result_.reset();
  requested_.reset();
  plainMesh_ = GpuMesh();
  mapMesh_ = GpuMesh();
  attributeMesh_ = GpuMesh();
  modelClean_ = params.input.clean;
  missingPairs_.clear();
  for (auto& id : missingDenoisePairs()) missingPairs_ += (missingPairs_.empty() ? "" : ", ") + id;
  const auto builtIn = scenes();
  sceneIsFile_ = std::none_of(builtIn.begin(), builtIn.end(), [&](const SceneRecipe& r) { return r.id == scene.name; });
  pairNote_.clear();
  pairMoveEdges_ = 0.0;
  MeshData clean = mergeInstances(scene);
  MeshData twin;
  bool hasTwin = false;
  if (!modelClean_.empty()) {
    // A user's pair: the scene is the noisy mesh, the file its clean reference.
    Scene reference;
    MeshPair pair;
    MeshData referenceMesh;
    std::string err = loadSceneFile(modelClean_, reference);
    if (err.empty()) {
      referenceMesh = mergeInstances(reference);
      err = pairWithClean(clean, referenceMesh, scene.name, modelClean_, pair);
    }
    if (!err.empty()) {
      modelNote_ = "denoise.clean: " + err + "; the scene is taken as the clean mesh instead";
    } else {
      pairNote_ = std::filesystem::path(scene.name).filename().string() + " paired with " +
                  std::filesystem::path(modelClean_).filename().string() + " (" + pair.how + ")";
      pairMoveEdges_ = pair.meanMoveEdges;
      clean = std::move(referenceMesh);
      twin = std::move(pair.twin);
      hasTwin = true;
    }
  } else {
    std::string twinError;
    hasTwin = loadPublishedTwin(scene.name, twin, twinError);
    if (!twinError.empty()) modelNote_ = twinError;
  }
  std::string error;
  model_ = buildDenoiseModel(clean, hasTwin ? &twin : nullptr, error);
  if (!error.empty()) modelNote_ = error;
  if (!model_) return;
  // The render topology once; results replace positions, normals and scalars in place. Until
  // the first result arrives the plain mesh shows the noisy input (noise takes milliseconds).
  MeshData base = model_->render;
  base.normals.assign(base.positions.size(), glm::vec3(0, 0, 1));
  const DenoiseConfig c = config();
  const bool published = c.publishedInput && !model_->published.empty();
  const std::vector<glm::dvec3> noisy =
      published ? model_->published : addNoise(model_->clean, model_->welded.indices, c.noise);
  MeshData input = base;
  for (size_t v = 0; v < input.positions.size(); ++v)
    input.positions[v] = glm::vec3(noisy[model_->welded.logicalOf[v]]);
  plainMesh_ = GpuMesh::upload(input);
  attributeMesh_ = GpuMesh::upload(base);
  if (model_->hasUvs()) mapMesh_ = GpuMesh::upload(base);
}

void DenoiseLab::update(const Scene& scene, float) {
  if (scene.revision != modelRevision_ || params.input.clean != modelClean_) rebuildModel(scene);
  if (!model_) return;
  if (result_ && (params.view.show != uploadedShow_ || params.view.mode != uploadedView_)) uploadViewData();
  const DenoiseConfig want = config();
  if (requested_ && *requested_ == want) return;  // computed, or being computed
  requested_ = want;
  // Steps on the GPU run here, on the GL thread (a change of settings, not a frame, asks for them:
  // headless runs settle() on update() alone); the job takes their result and does the rest.
  if (!smoothsOnGpu(want)) gpuDrawn_ = false;  // the GPU's texture is not what this job computes
  submit(want, smoothsOnGpu(want) ? std::make_shared<const SmoothedElsewhere>(smoothOnGpu(want)) : nullptr);
}

void DenoiseLab::submit(const DenoiseConfig& want, std::shared_ptr<const SmoothedElsewhere> smoothed) {
  const std::string label = std::string(methodRow(want.smoothing.method).name) + " on " + modelScene_ + " (" +
                            std::to_string(model_->statistics.logicalVertices) + " vertices)" +
                            (smoothed ? ", smoothed on the GPU" : "");
  // The job owns what it reads: the model (shared, const), the settings (a copy), the GPU's result.
  jobs_->submit(
      "denoise", label,
      [model = model_, want, smoothed](JobContext& job) {
        return std::make_shared<DenoiseResult>(runDenoise(*model, want, &job, smoothed.get()));
      },
      [this, revision = modelRevision_](std::shared_ptr<DenoiseResult> r) {
        if (revision == modelRevision_ && r->complete) upload(std::move(*r));
      });
}

void DenoiseLab::upload(DenoiseResult r) {
  result_ = std::make_unique<DenoiseResult>(std::move(r));
  gpuDrawn_ = false;  // the result's own positions, from here on
  const DenoiseResult& res = *result_;
  attributeMesh_.updatePositions(res.noisy);
  attributeMesh_.updateNormals(res.noisyNormals);
  attributeMesh_.setScalars(kScalar0, res.offsets);
  if (mapMesh_ && res.map) {
    mapMesh_.updatePositions(res.noisy);
    mapMesh_.updateNormals(res.noisyNormals);
    const DisplacementMap& m = *res.map;
    std::vector<uint8_t> texels = encodeMap(m, false);
    GLenum internal = m.format == MapFormat::Unorm8 ? GL_R8 : m.format == MapFormat::Unorm16 ? GL_R16 : GL_R32F;
    GLenum type = m.format == MapFormat::Unorm8    ? GL_UNSIGNED_BYTE
                  : m.format == MapFormat::Unorm16 ? GL_UNSIGNED_SHORT
                                                   : GL_FLOAT;
    if (internal == GL_R16 && !gl::hasNorm16Textures()) {
      // WebGL2 has no 16-bit normalized textures: the values a GL_R16 lookup returns, v / 65535, held
      // as 32-bit floats (exactly: 16 bits fit the mantissa), filtered alike.
      std::vector<float> values(texels.size() / 2);
      for (size_t i = 0; i < values.size(); ++i) {
        uint16_t v = 0;
        std::memcpy(&v, &texels[2 * i], 2);
        values[i] = float(v) / 65535.0f;
      }
      texels.resize(values.size() * 4);
      std::memcpy(texels.data(), values.data(), texels.size());
      internal = GL_R32F;
      type = GL_FLOAT;
    }
    gl::SamplerState s;
    s.minFilter = s.magFilter = GL_NEAREST;                       // the lookup filter is set per draw (bilinear or not)
    s.wrapS = s.wrapT = m.repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;  // as the bake and the read-back
    mapTexture_ = gl::Texture2D::fromData(m.size, internal, GL_RED, type, texels.data(), s);
    // A small grey preview for the panel: the stored values over the map's own range.
    float lo = INFINITY, hi = -INFINITY;
    for (float v : m.stored) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    const int side = std::min(256, m.size.x);
    std::vector<uint8_t> rgba(size_t(side) * side * 4);
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        const float v = m.stored[size_t(y * m.size.y / side) * size_t(m.size.x) + size_t(x * m.size.x / side)];
        const uint8_t g = uint8_t(std::clamp(hi > lo ? (v - lo) / (hi - lo) : 0.5f, 0.0f, 1.0f) * 255.0f + 0.5f);
        uint8_t* px = &rgba[size_t(y * side + x) * 4];
        px[0] = px[1] = px[2] = g;
        px[3] = 255;
      }
    gl::SamplerState linear;
    linear.minFilter = GL_LINEAR;
    mapPreview_ = gl::Texture2D::fromRgba8({side, side}, rgba.data(), linear, false);
  }
  uploadViewData();
}

void DenoiseLab::uploadViewData() {
  if (!result_) return;
  const DenoiseResult& r = *result_;
  uploadedShow_ = params.view.show;
  uploadedView_ = params.view.mode;
  // The plain mesh draws the smoothed, noisy or clean positions.
  const std::vector<glm::vec3>& plain = params.view.show == DenoiseShow::Noisy   ? r.noisy
                                        : params.view.show == DenoiseShow::Clean ? model_->render.positions
                                                                                 : r.smoothed;
  plainMesh_.updatePositions(plain);
  // Heat: the distance of what is drawn to the clean mesh, the offset, or the gap between copies.
  std::vector<float> plainHeat(plain.size(), 0.0f);
  if (params.view.mode == DenoiseView::Offset) {
    plainHeat = r.offsets;
  } else if (params.view.mode == DenoiseView::Error) {
    if (params.view.show == DenoiseShow::Noisy)
      for (size_t v = 0; v < plain.size(); ++v)
        plainHeat[v] = glm::length(plain[v] - model_->render.positions[v]) / float(model_->meanEdge);
    else if (params.view.show != DenoiseShow::Clean)
      plainHeat = r.errorSmoothed;
  }
  plainMesh_.setScalars(kScalar1, plainHeat);
  auto heat = [&](const std::vector<float>& offsets, const std::vector<float>& error, const std::vector<float>& gap) {
    return params.view.mode == DenoiseView::Offset ? offsets : params.view.mode == DenoiseView::SeamGap ? gap : error;
  };
  attributeMesh_.setScalars(kScalar1, heat(r.offsets, r.errorAttribute, r.attributeGap));
  if (mapMesh_ && r.map) mapMesh_.setScalars(kScalar1, heat(r.readBack, r.errorMapped, r.seamGap));
}

void DenoiseLab::drawPanel(Frame& frame, Path path, const GpuMesh& mesh, glm::ivec4 vp, Style style) {
  glViewport(vp.x, vp.y, vp.z, vp.w);
  Program& prog = programs_[int(path)].get(*shaders_, programSpec(params.view.mode, path));
  prog.use();
  const float aspect = float(vp.z) / float(std::max(vp.w, 1));
  const glm::vec2 shift = -2.0f * frame.jitter / glm::vec2(vp.z, vp.w);
  const glm::mat4 proj =
      glm::translate(glm::mat4(1.0f), glm::vec3(shift.x, -shift.y, 0.0f)) * frame.camera.projection(aspect);
  prog.set("u_viewProj", proj * frame.camera.view());
  prog.set("u_eye", frame.camera.eye());
  const glm::mat4 view = frame.camera.view();
  const glm::vec3 right(view[0][0], view[1][0], view[2][0]), up(view[0][1], view[1][1], view[2][1]);
  const glm::vec3 back = glm::normalize(frame.camera.eye() - frame.camera.target);
  prog.set("u_keyDir", glm::normalize(-0.55f * right + 0.75f * up + 0.45f * back));
  prog.set("u_heatScale", params.view.heatScale);
  prog.set("u_style", int(style));
  prog.set("u_pointSize", 9.0f);
  if (path == Path::Map && mapTexture_) {
    mapTexture_.bind(0);
    const GLint filter = params.map.bilinear ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    prog.set("u_displacement", 0);
    prog.set("u_bias", result_->map->bias);
    prog.set("u_scale", result_->map->scale);
  }
  if (path == Path::SmoothedOnGpu) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, gpu_.positionTexture());
    prog.set("u_smoothed", 0);
    prog.set("u_centre", glm::vec3(gpu_.centre()));
  }
  if (style == Style::Marker) {
    if (!gl::esContext()) glEnable(GL_PROGRAM_POINT_SIZE);  // WebGL2 always takes gl_PointSize
    glDisable(GL_DEPTH_TEST);
    mesh.draw(Primitive::Points);
    glEnable(GL_DEPTH_TEST);
  } else {
    mesh.draw();
  }
}

void DenoiseLab::render(Frame& frame) {
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(0.02f, 0.02f, 0.025f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!model_) return;
  const bool fromGpu = gpuDrawn_ && params.view.show == DenoiseShow::Smoothed;
  if (!result_ || fromGpu) {
    // The first result is on its way (the jobs bar shows it): the input meanwhile, or what the
    // GPU smoothed, straight from its texture, while the job measures it.
    auto pass =
        frame.pass(fromGpu ? "draw: smoothed (from the GPU's texture)" : "draw: noisy input (smoothing in progress)");
    drawPanel(frame, fromGpu ? Path::SmoothedOnGpu : Path::Plain, plainMesh_, {0, 0, frame.size().x, frame.size().y});
    return;
  }
  const glm::ivec2 size = frame.size();
  const bool uvs = model_->hasUvs() && mapMesh_;
  DenoiseShow show = params.view.show;
  if ((show == DenoiseShow::Map) && !uvs) show = DenoiseShow::Attribute;  // warnings() says why
  if (show == DenoiseShow::Compare) {
    auto pass = frame.pass(uvs ? "draw: map | attribute | smoothed" : "draw: attribute | smoothed");
    // Side by side in a wide frame, stacked in a tall one, 4 px apart: map, attribute, smoothed
    // (left to right, or top to bottom; the panel text names them).
    const int panels = uvs ? 3 : 2, gap = 4;
    const bool columns = size.x >= size.y;
    const int along = columns ? size.x : size.y, cell = (along - gap * (panels - 1)) / panels;
    auto viewport = [&](int k) {
      const int start = k * (cell + gap);
      return columns ? glm::ivec4(start, 0, cell, size.y) : glm::ivec4(0, size.y - start - cell, size.x, cell);
    };
    int k = 0;
    if (uvs) drawPanel(frame, Path::Map, mapMesh_, viewport(k++));
    drawPanel(frame, Path::Attribute, attributeMesh_, viewport(k++));
    drawPanel(frame, Path::Plain, plainMesh_, viewport(k));
    glViewport(0, 0, size.x, size.y);
    return;
  }
  const bool collapsed = show == DenoiseShow::Smoothed && result_->collapsed;
  auto pass = frame.pass(collapsed ? "draw: noisy input (ghost) and the point it collapsed to"
                                   : std::string(rowOf(kDenoiseShows, show).pass));
  if (show == DenoiseShow::Map) {
    drawPanel(frame, Path::Map, mapMesh_, {0, 0, size.x, size.y});
  } else if (show == DenoiseShow::Attribute) {
    drawPanel(frame, Path::Attribute, attributeMesh_, {0, 0, size.x, size.y});
  } else if (collapsed) {
    // Collapsed to a point: a speck on its own. The noisy input as a ghost (the attribute mesh's
    // positions, undisplaced by the plain program) and the point it went to, in orange.
    const glm::ivec4 full{0, 0, size.x, size.y};
    drawPanel(frame, Path::Plain, attributeMesh_, full, Style::Ghost);
    drawPanel(frame, Path::Plain, plainMesh_, full, Style::Marker);
  } else {
    drawPanel(frame, Path::Plain, plainMesh_, {0, 0, size.x, size.y});  // holds what `show` asks (update())
  }
}

std::vector<ProgramRef> DenoiseLab::activePrograms() const { return heldPrograms(programs_); }

std::string DenoiseLab::saveMap() {
  if (!result_ || !result_->map) return "no map to save: the mesh has no UVs, or no result yet";
  const DisplacementMap& m = *result_->map;
  const std::string stem = modelScene_ + "-" + std::to_string(m.size.x) + "-" +
                           std::string(rowOf(kBakeMethods, params.map.bake.method).name);
  const auto png = freshName("bakes", stem, ".png");
  ImageF preview;
  preview.size = m.size;
  preview.rgba.resize(size_t(m.size.x) * size_t(m.size.y) * 4);
  for (int y = 0; y < m.size.y; ++y)
    for (int x = 0; x < m.size.x; ++x) {
      const float v = m.stored[size_t(y) * size_t(m.size.x) + size_t(x)];
      float* px = preview.at(x, m.size.y - 1 - y);  // images are top-down, the map bottom-up
      px[0] = px[1] = px[2] = m.format == MapFormat::Float32 ? (v - result_->map->bias) : v;
      px[3] = 1.0f;
    }
  if (auto err = writePng(png.string(), preview); !err.empty()) return err;
  const std::vector<uint8_t> raw = encodeMap(m, true);
  auto rawPath = png;
  rawPath.replace_extension(".raw");
  if (auto err = writeTextFile(rawPath.string(), std::string(raw.begin(), raw.end())); !err.empty()) return err;
  nlohmann::json meta = {{"width", m.size.x},
                         {"height", m.size.y},
                         {"format", std::string(rowOf(kMapFormats, m.format).name)},
                         {"bias", m.bias},
                         {"scale", m.scale},
                         {"offset", "stored * scale + bias, along the vertex normal"},
                         {"rows", "top-down in .png and .raw"},
                         {"bake", std::string(rowOf(kBakeMethods, params.map.bake.method).name)},
                         {"raw", m.format == MapFormat::Unorm8    ? "uint8"
                                 : m.format == MapFormat::Unorm16 ? "uint16 little-endian"
                                                                  : "float32 little-endian"}};
  auto jsonPath = png;
  jsonPath.replace_extension(".json");
  if (auto err = writeTextFile(jsonPath.string(), meta.dump(2) + "\n"); !err.empty()) return err;
  return "saved " + png.string() + " (+ .raw, .json)";
}

}  // namespace shadelab
