#include "labs/denoise/denoise_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>

#include "app/scene/mesh_topology.h"

namespace shadelab {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

std::vector<glm::dvec3> toDouble(std::span<const glm::vec3> p) { return {p.begin(), p.end()}; }

// For every render vertex, the widest distance between any two copies of its position (copies
// share a logical vertex), in `unit`s. Zero where a position has one copy, or all agree.
std::vector<float> copyGaps(const WeldedMesh& w, std::span<const glm::dvec3> positions, double unit, double& widest) {
  std::vector<std::vector<uint32_t>> copies(w.vertexCount());
  for (uint32_t v = 0; v < w.logicalOf.size(); ++v) copies[w.logicalOf[v]].push_back(v);
  std::vector<float> gap(positions.size(), 0.0f);
  widest = 0.0;
  for (auto& c : copies) {
    if (c.size() < 2) continue;
    double g = 0.0;
    for (size_t a = 0; a < c.size(); ++a)
      for (size_t b = a + 1; b < c.size(); ++b) g = std::max(g, glm::length(positions[c[a]] - positions[c[b]]));
    g /= unit;
    widest = std::max(widest, g);
    for (uint32_t v : c) gap[v] = float(g);
  }
  return gap;
}

std::vector<float> distances(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b, double unit) {
  std::vector<float> d(a.size());
  for (size_t i = 0; i < a.size(); ++i) d[i] = float(glm::length(a[i] - b[i]) / unit);
  return d;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

std::shared_ptr<const DenoiseModel> buildDenoiseModel(const MeshData& clean, const MeshData* published,
                                                      std::string& error) {
  if (clean.indices.size() < 3) {
    error = "the scene has no triangles to denoise";
    return nullptr;
  }
  auto m = std::make_shared<DenoiseModel>();
  m->render.name = clean.name;
  m->render.positions = clean.positions;
  m->render.uvs = clean.uvs;
  m->render.indices = clean.indices;
  m->welded = weldByPosition(m->render);
  m->weldedAdjacency = buildAdjacency(m->welded.vertexCount(), m->welded.indices);
  m->renderAdjacency = buildAdjacency(m->render.positions.size(), m->render.indices);
  m->clean = toDouble(m->welded.positions);
  m->statistics = meshStatistics(m->render, m->welded, m->weldedAdjacency);
  m->meanEdge = meanEdgeLength(m->clean, m->welded.indices);
  if (!(m->meanEdge > 0.0)) m->meanEdge = 1.0;
  if (published) {
    const WeldedMesh twin = weldByPosition(*published);
    if (twin.indices != m->welded.indices) {
      error = "the published noisy mesh does not share the clean mesh's faces; generated noise is used instead";
    } else {
      m->published = toDouble(twin.positions);
    }
  }
  return m;
}

namespace {

// Smoothing shrinks a closed mesh (each vertex moves towards its neighbours' average); implicit
// fairing's remedy (Desbrun et al. 1999) scales the result about its centroid back to the input's
// volume. Measured on the smoothed surface itself, so the note names what happened.
void measureVolume(const DenoiseModel& m, const DenoiseConfig& c, std::span<const glm::dvec3> start,
                   std::span<const uint32_t> indices, std::vector<glm::dvec3>& result, DenoiseResult& r) {
  if (m.statistics.boundaryEdges != 0) return;  // an open mesh has no volume
  glm::dvec3 centroid(0.0);
  for (const glm::dvec3& p : result) centroid += p;
  centroid /= double(std::max<size_t>(result.size(), 1));
  const double before = signedVolume(start, indices, centroid), after = signedVolume(result, indices, centroid);
  r.smoothingVolumeChangePct = before != 0.0 ? 100.0 * (after - before) / std::abs(before) : 0.0;
  // Below a millionth of its volume the mesh has collapsed to a point: its shape is rounding
  // noise, and scaling that up by more than 100 would only enlarge the noise.
  r.collapsed = !(std::abs(after) >= 1e-6 * std::abs(before));
  if (c.preserveVolume && before * after > 0.0 && !r.collapsed) {
    const double scale = std::cbrt(before / after);
    for (glm::dvec3& p : result) p = centroid + (p - centroid) * scale;
    r.volumeScale = scale;
  }
}

// The smoothing itself, on `start` (welded or per render vertex) with `indices` and `adjacency`.
std::vector<glm::dvec3> smoothPositions(const DenoiseConfig& c, std::span<const glm::dvec3> start,
                                        std::span<const uint32_t> indices, const Adjacency& adjacency, DenoiseResult& r,
                                        JobContext* job) {
  if (c.smoothing.method == SmoothingMethod::Bilateral) {
    BilateralResult b = bilateralNormalFilter(start, indices, c.bilateral, job);
    r.normalChangeDeg = std::move(b.normalChangeDeg);
    return std::move(b.positions);
  }
  SmoothingResult sr = smooth(start, indices, adjacency, c.smoothing, job);
  if (!sr.error.empty()) r.notes.push_back(sr.error);
  r.energy = std::move(sr.energy);
  r.grewAt = sr.grewAt;
  r.stoppedAt = sr.stoppedAt;
  r.factorMs = sr.factorMs;
  r.weights = std::move(sr.weightsUsed);
  return std::move(sr.positions);
}

// The GPU's smoothing against the CPU's of the same input: the reference a student's
// laplacian_step.glsl is held to.
void compareWithCpu(const DenoiseConfig& c, std::span<const glm::dvec3> start, std::span<const uint32_t> indices,
                    const Adjacency& adjacency, const SmoothedElsewhere& gpu, double meanEdge, DenoiseResult& r,
                    JobContext* job) {
  DenoiseResult cpu;
  const std::vector<glm::dvec3> reference = smoothPositions(c, start, indices, adjacency, cpu, job);
  double sum = 0.0;
  for (size_t v = 0; v < reference.size() && v < gpu.positions.size(); ++v) {
    const double d = glm::length(gpu.positions[v] - reference[v]);
    sum += std::isfinite(d) ? d * d : std::numeric_limits<double>::infinity();
  }
  r.referenceDistance = std::sqrt(sum / double(std::max<size_t>(reference.size(), 1))) / meanEdge;
  r.verdictStepsOff = std::abs(gpu.grewAt - cpu.grewAt) + std::abs(gpu.stoppedAt - cpu.stoppedAt);
  double worst = 0.0;  // over the iterations both ran
  for (size_t i = 0; i < std::min(gpu.energy.size(), cpu.energy.size()); ++i) {
    const double d = std::abs(gpu.energy[i] - cpu.energy[i]) / std::max(std::abs(cpu.energy[i]), 1e-300);
    worst = std::max(worst, std::isfinite(d) ? d : std::numeric_limits<double>::infinity());
  }
  r.energyDifference = worst;
}

// Per render vertex: the positions to draw, the offsets along the noisy surface's normals, and
// the errors of the smoothed mesh and of its offsets against the clean mesh.
struct RenderCopies {
  std::vector<glm::dvec3> noisy, clean;
};
RenderCopies offsetsAlongNormals(const DenoiseModel& m, std::span<const glm::dvec3> start,
                                 std::span<const glm::dvec3> result, std::span<const uint32_t> indices,
                                 const std::function<uint32_t(size_t)>& smoothVertex, DenoiseResult& r) {
  const size_t renderCount = m.render.positions.size();
  const std::vector<glm::dvec3> normals = vertexNormals(start, indices, NormalWeighting::Area);
  RenderCopies copies{std::vector<glm::dvec3>(renderCount), std::vector<glm::dvec3>(renderCount)};
  std::vector<glm::dvec3> smoothedR(renderCount), attributeR(renderCount);
  r.noisy.resize(renderCount);
  r.smoothed.resize(renderCount);
  r.noisyNormals.resize(renderCount);
  r.offsets.resize(renderCount);
  for (size_t v = 0; v < renderCount; ++v) {
    const uint32_t s = smoothVertex(v);
    const glm::dvec3 n = normals[s];
    const double offset = glm::dot(result[s] - start[s], n);
    copies.noisy[v] = start[s];
    smoothedR[v] = result[s];
    attributeR[v] = start[s] + n * offset;
    copies.clean[v] = m.clean[m.welded.logicalOf[v]];
    r.noisy[v] = glm::vec3(start[s]);
    r.smoothed[v] = glm::vec3(result[s]);
    r.noisyNormals[v] = glm::vec3(n);
    r.offsets[v] = float(offset);
  }
  const std::span<const uint32_t> faces = m.render.indices;
  r.noisyError = meshError(copies.noisy, copies.clean, faces, m.meanEdge);
  r.smoothedError = meshError(smoothedR, copies.clean, faces, m.meanEdge);
  r.attributeError = meshError(attributeR, copies.clean, faces, m.meanEdge);
  r.errorSmoothed = distances(smoothedR, copies.clean, m.meanEdge);
  r.errorAttribute = distances(attributeR, copies.clean, m.meanEdge);
  r.attributeGap = copyGaps(m.welded, attributeR, m.meanEdge, r.attributeGapMax);
  return copies;
}

// The map of the offsets, and what it gives back at every vertex's UV against the clean mesh.
void bakeAndReadBack(const DenoiseModel& m, const DenoiseConfig& c, const RenderCopies& copies, DenoiseResult& r,
                     JobContext* job) {
  const size_t renderCount = m.render.positions.size();
  BakeSettings bake = c.bake;
  bake.repeat = uvsLeaveUnitSquare(m.render.uvs);
  BakeResult b = bakeDisplacement(m.render.uvs, m.render.indices, r.offsets, bake, job);
  if (job && job->cancelled()) return;
  if (!b.error.empty()) {
    r.notes.push_back(b.error);
    return;
  }
  r.bakeMs = b.ms;
  r.wrongNeighbours = b.wrongNeighbours;
  r.overlappingTexels = b.overlapping;
  r.readBack.resize(renderCount);
  std::vector<glm::dvec3> mappedR(renderCount);
  double sq = 0.0;
  for (size_t v = 0; v < renderCount; ++v) {
    r.readBack[v] = sampleDisplacement(b.map, m.render.uvs[v], c.bilinear);
    mappedR[v] = copies.noisy[v] + glm::dvec3(r.noisyNormals[v]) * double(r.readBack[v]);
    const double e = double(r.readBack[v] - r.offsets[v]) / m.meanEdge;
    sq += e * e;
    r.bakeMax = std::max(r.bakeMax, std::abs(e));
  }
  r.bakeRms = std::sqrt(sq / double(renderCount));
  r.mappedError = meshError(mappedR, copies.clean, m.render.indices, m.meanEdge);
  r.errorMapped = distances(mappedR, copies.clean, m.meanEdge);
  r.seamGap = copyGaps(m.welded, mappedR, m.meanEdge, r.seamGapMax);
  r.map = std::move(b.map);
}

// What the student should know about this result, in the order it matters.
void noteWhatHappened(const DenoiseModel& m, const DenoiseConfig& c, DenoiseResult& r) {
  const double shrinkPct = -r.smoothingVolumeChangePct;
  const SmoothingMethodRow& method = methodRow(c.smoothing.method);
  // A method stable for any lambda still shrinks: said before what the shrinking did.
  const std::string stableButShrinks =
      method.anyLambda ? std::string(method.name) + " smoothing is stable but shrinks: " : "";
  if (r.volumeScale != 1.0)
    r.notes.push_back("the smoothed mesh had lost " + number(shrinkPct) + "% of its volume: scaled by " +
                      number(r.volumeScale) + " about its centroid to restore it (preserve_volume)");
  else if (r.collapsed)
    r.notes.push_back(
        stableButShrinks +
        "the mesh collapsed to a point (under a millionth of its volume left), so nothing is left to "
        "rescale; drawn: the noisy input as a ghost and, in orange, the point it collapsed to. Lower lambda or "
        "the iterations");
  else if (shrinkPct >= 10.0)
    r.notes.push_back((method.anyLambda ? stableButShrinks : std::string("the smoothing shrank the mesh: ")) +
                      "it lost " + number(shrinkPct) + "% of its volume, pulled towards its centroid (" +
                      (c.preserveVolume ? "an open mesh has no volume to restore" : "preserve_volume rescales it") +
                      ")");
  if (r.grewAt > 0 && method.explicitSteps)  // a solve per step is stable for any lambda
    r.notes.push_back("diverging: the smoothing energy grew at iteration " + std::to_string(r.grewAt) + " (lambda " +
                      number(c.smoothing.lambda) + " is beyond the stable explicit step, about " +
                      number(r.stabilityLimit) + " for these weights)");
  if (r.stoppedAt > 0)
    r.notes.push_back(
        "stopped at iteration " + std::to_string(r.stoppedAt) + " of " + std::to_string(c.smoothing.iterations) +
        ": the energy had grown to 100 times its start (or the next step was not finite); that mesh is shown");
  if (r.weights.negativeClamped > 0)
    r.notes.push_back(std::to_string(r.weights.negativeClamped) +
                      " cotangent weights were negative (obtuse angles) and " + "were clamped to 0");
  if (r.weights.uniformFallbacks > 0)
    r.notes.push_back(std::to_string(r.weights.uniformFallbacks) +
                      " vertices had only zero-area neighbours: uniform weights for them");
  if (!c.weld && m.statistics.seamVertices > 0)
    r.notes.push_back("welding is off: the " + std::to_string(m.statistics.seamVertices) +
                      " seam positions were smoothed as " +
                      "separate boundary vertices, and their copies moved apart (cracks, widest " +
                      number(r.attributeGapMax) + " mean edges)");
  if (r.overlappingTexels > 0 && r.map)
    r.notes.push_back("the UV layout overlaps: " + std::to_string(r.overlappingTexels) + " texels (" +
                      number(100.0 * double(r.overlappingTexels) / double(std::max<size_t>(r.map->covered, 1))) +
                      "% of the covered ones) lie in two triangles, and one map cannot hold both offsets there");
  // A filter whose parameters make it a no-op costs time and changes nothing: say so.
  if (c.smoothing.method == SmoothingMethod::Bilateral && r.noisyError.rmsDistance > 0.0 &&
      r.smoothedError.rmsDistance > 0.98 * r.noisyError.rmsDistance)
    r.notes.push_back("bilateral filtering changed almost nothing (distance to the clean mesh " +
                      number(r.smoothedError.rmsDistance) + " against " + number(r.noisyError.rmsDistance) +
                      " for the noisy mesh): sigma_r " + number(c.bilateral.sigmaR) +
                      " is below the noise's normal differences, so no neighbour counts; raise sigma_r");
  if (r.wrongNeighbours > 0)
    r.notes.push_back("the approximate nearest-neighbour search gave " + std::to_string(r.wrongNeighbours) +
                      " texels a vertex that is not the nearest (raise checks)");
}

}  // namespace

SmoothingInput smoothingInput(const DenoiseModel& m, const DenoiseConfig& c, double* noiseMs) {
  const WeldedMesh& w = m.welded;
  // The noisy input, per logical vertex: copies of a position always get the same noise.
  const auto t0 = Clock::now();
  const bool published = c.publishedInput && !m.published.empty();
  std::vector<glm::dvec3> noisyLogical = published ? m.published : addNoise(m.clean, w.indices, c.noise);
  if (noiseMs) *noiseMs = msSince(t0);
  // The vertices smoothing works on: welded, or each render vertex on its own (the homework's bug).
  SmoothingInput in;
  in.indices = c.weld ? std::span<const uint32_t>(w.indices) : m.render.indices;
  in.adjacency = c.weld ? &m.weldedAdjacency : &m.renderAdjacency;
  if (c.weld) {
    in.start = std::move(noisyLogical);
  } else {
    in.start.resize(m.render.positions.size());
    for (size_t v = 0; v < in.start.size(); ++v) in.start[v] = noisyLogical[w.logicalOf[v]];
  }
  return in;
}

DenoiseResult runDenoise(const DenoiseModel& m, const DenoiseConfig& c, JobContext* job,
                         const SmoothedElsewhere* smoothed) {
  DenoiseResult r;
  r.config = c;
  const WeldedMesh& w = m.welded;

  // 1-2. The noisy input and the vertices smoothing works on.
  if (job) job->stage(0.0f, 0.05f);
  if (job) job->progress(0.0f, "adding noise");
  SmoothingInput in = smoothingInput(m, c, &r.noiseMs);
  const std::vector<glm::dvec3>& start = in.start;
  const std::span<const uint32_t> indices = in.indices;
  const Adjacency& adjacency = *in.adjacency;

  // 3. Smoothing (here, or the GPU's result), and what it did to the volume.
  if (job) job->stage(0.05f, 0.8f);
  auto t0 = Clock::now();
  std::vector<glm::dvec3> result;
  if (smoothed) {
    result = smoothed->positions;
    r.energy = smoothed->energy;
    r.grewAt = smoothed->grewAt;
    r.stoppedAt = smoothed->stoppedAt;
    r.weights = edgeWeights(start, indices, adjacency, c.smoothing.weights, c.smoothing.clampNegative);
    if (c.cpuReference) compareWithCpu(c, start, indices, adjacency, *smoothed, m.meanEdge, r, job);
  } else {
    result = smoothPositions(c, start, indices, adjacency, r, job);
  }
  measureVolume(m, c, start, indices, result, r);
  r.solveMs = smoothed ? smoothed->ms : msSince(t0);
  if (job && job->cancelled()) return r;
  if (methodRow(c.smoothing.method).laplacian)
    r.stabilityLimit =
        stabilityLimit(adjacency, r.weights, 200);  // the weights of the start, as the smoothing had them

  // 4. Offsets along the noisy surface's normals, per render vertex.
  if (job) job->stage(0.8f, 0.82f);
  if (job) job->progress(0.0f, "offsets along the normals");
  const auto smoothVertex = [&](size_t renderVertex) {
    return c.weld ? w.logicalOf[renderVertex] : uint32_t(renderVertex);
  };
  const RenderCopies copies = offsetsAlongNormals(m, start, result, indices, smoothVertex, r);

  // 5. The map, and the offsets it gives back at every vertex's UV.
  if (m.hasUvs()) {
    if (job) job->stage(0.82f, 0.98f);
    bakeAndReadBack(m, c, copies, r, job);
    if (job && job->cancelled()) return r;
  }

  // 6. What the student should know.
  noteWhatHappened(m, c, r);
  if (job) {
    job->stage(0.0f, 1.0f);
    job->progress(1.0f, "done");
  }
  r.complete = true;
  return r;
}

}  // namespace shadelab
