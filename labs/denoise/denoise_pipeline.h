// The denoising lab's work, start to end, as one pure-CPU function a job runs:
//
//   clean mesh -> noise (or the published noisy twin) -> smoothing -> per-vertex offsets along
//   the noisy normals -> displacement map (when the mesh has UVs) -> offsets read back from the
//   map -> errors against the clean mesh, the smoothed mesh and between copies of a position.
//
// The model is built once per scene and weld setting; runs share it (shared_ptr to const) with
// the job that reads it, so the lab may change or go while a job still runs.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/scene/mesh.h"
#include "app/scene/mesh_topology.h"
#include "labs/denoise/bilateral_normal.h"
#include "labs/denoise/displacement_bake.h"
#include "labs/denoise/laplacian.h"
#include "labs/denoise/mesh_metrics.h"
#include "labs/denoise/mesh_noise.h"

namespace shadelab {

struct DenoiseModel {
  MeshData render;    // the clean mesh as drawn: render vertices, UVs if any
  WeldedMesh welded;  // one logical vertex per position
  Adjacency weldedAdjacency;
  Adjacency renderAdjacency;          // the render vertices as they are: seams are boundaries
  std::vector<glm::dvec3> clean;      // per logical vertex
  std::vector<glm::dvec3> published;  // per logical vertex: a published noisy twin, or empty
  MeshStatistics statistics;
  double meanEdge = 1.0;  // of the clean mesh: the unit of every distance reported
  bool hasUvs() const { return !render.uvs.empty(); }
};

// `published`: a noisy twin with the same connectivity (Noisy.obj beside Original.obj), or null.
// Returns null with `error` set when the mesh cannot be denoised (no triangles).
std::shared_ptr<const DenoiseModel> buildDenoiseModel(const MeshData& clean, const MeshData* published,
                                                      std::string& error);

enum class SmoothingDevice { Cpu, Gpu, Count };
inline constexpr Named<SmoothingDevice> kSmoothingDevices[] = {{SmoothingDevice::Cpu, "cpu"},
                                                               {SmoothingDevice::Gpu, "gpu"}};
static_assert(coversEnum<SmoothingDevice>(kSmoothingDevices));

struct DenoiseConfig {
  bool publishedInput = false;  // the published noisy twin instead of generated noise
  NoiseSettings noise;
  SmoothingSettings smoothing;  // the method (bilateral: `bilateral` below) and the Laplacian steps' settings
  // Explicit and Taubin steps on the GPU (gpu_smoother.h), where the lab can run them; the rest of
  // the pipeline takes the smoothed positions from there.
  SmoothingDevice device = SmoothingDevice::Cpu;
  // With the steps on the GPU, smooth on the CPU as well and report how far the two results lie
  // apart (off: a mesh too large for the CPU to keep up with the GPU).
  bool cpuReference = true;
  BilateralSettings bilateral;
  bool weld = true;             // smoothing and normals on the welded surface (off: the homework's bug)
  bool preserveVolume = false;  // rescale the smoothed mesh about its centroid to the input's volume
  BakeSettings bake;
  bool bilinear = true;  // how the vertex shader (and the read-back) samples the map
  bool operator==(const DenoiseConfig&) const = default;
};

struct DenoiseResult {
  DenoiseConfig config;
  // Per render vertex, for drawing:
  std::vector<glm::vec3> noisy, smoothed;
  std::vector<glm::vec3> noisyNormals;  // the direction offsets move along (welded, or split without weld)
  std::vector<float> offsets;           // along noisyNormals: smoothed - noisy, projected (the attribute path)
  std::vector<float> readBack;          // offsets as the map gives them back (the map path); empty without a map
  std::vector<float> seamGap;           // map path: widest gap between copies of this position, in mean edges
  std::vector<float> attributeGap;      // the same for the attribute path (0 when welded)
  std::vector<float> errorSmoothed, errorMapped, errorAttribute;  // distance to the clean mesh, in mean edges
  std::optional<DisplacementMap> map;

  // Against the clean mesh (distances in mean edge lengths of the clean mesh).
  MeshError noisyError, smoothedError, attributeError, mappedError;
  // The map against the offsets it stores, in mean edges: what the bake itself loses.
  double bakeRms = 0, bakeMax = 0, seamGapMax = 0, attributeGapMax = 0;
  size_t wrongNeighbours = 0;
  size_t overlappingTexels = 0;
  // Smoothing's story: energy per iteration, where it grew or stopped, the explicit limit.
  std::vector<double> energy;
  std::vector<double> normalChangeDeg;  // bilateral: per normal iteration
  int grewAt = 0, stoppedAt = 0;
  double stabilityLimit = 0;
  double smoothingVolumeChangePct = 0;  // the smoothed surface against its input, before any rescale (closed meshes)
  double volumeScale = 1;               // the rescale preserve_volume applied (1: none)
  bool collapsed = false;               // smoothed to a point: under a millionth of the input's volume
  EdgeWeights weights;
  double noiseMs = 0, solveMs = 0, factorMs = 0, bakeMs = 0;
  // Smoothed on the GPU with the CPU's reference beside it: the root mean square distance between
  // the two meshes, in mean edges; by how many steps their verdicts (grew at, stopped at) differ;
  // and the largest relative difference between their energies, iteration by iteration.
  std::optional<double> referenceDistance;
  int verdictStepsOff = 0;
  double energyDifference = 0.0;
  std::vector<std::string> notes;  // what the student should know about this result
  bool complete = false;           // false when the job was cancelled part way
};

// The positions smoothing starts from (noisy; welded, or per render vertex without weld) and the
// faces and one-rings it works on.
struct SmoothingInput {
  std::vector<glm::dvec3> start;
  std::span<const uint32_t> indices;
  const Adjacency* adjacency = nullptr;
};
SmoothingInput smoothingInput(const DenoiseModel& model, const DenoiseConfig& config, double* noiseMs = nullptr);

// Smoothing done elsewhere (the GPU), handed to the rest of the pipeline.
struct SmoothedElsewhere {
  std::vector<glm::dvec3> positions;  // per vertex of smoothingInput()
  std::vector<double> energy;
  int grewAt = 0, stoppedAt = 0;
  double ms = 0.0;
};

// `smoothed`: the smoothing's result for `config`, from the GPU; null: smooth here.
DenoiseResult runDenoise(const DenoiseModel& model, const DenoiseConfig& config, JobContext* job = nullptr,
                         const SmoothedElsewhere* smoothed = nullptr);

}  // namespace shadelab
