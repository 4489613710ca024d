// Laplacian smoothing of a triangle mesh, three ways, and how each behaves when pushed.
//
// The umbrella operator of vertex i over its one-ring N(i) with weights w_ij:
//   delta_i = p_i - sum_j w_ij p_j / sum_j w_ij
// uniform weights w_ij = 1 (Taubin 1995), or cotangent weights w_ij = (cot a_ij + cot b_ij) / 2,
// the angles opposite the edge ij (Pinkall and Polthier 1993; Meyer et al. 2003), which follow the
// surface's geometry rather than its triangulation. Obtuse and sliver triangles make cotangent
// weights negative; clamping them to zero keeps every vertex's update a convex combination.
//
//   explicit   p' = p - lambda <delta, n> n        (along the normal: the homework)
//              p' = p - lambda delta               (along_normal off: shrinks and drifts)
//              stable for lambda <= 2 / mu_max, mu_max the largest eigenvalue of the normalised
//              Laplacian: about 1 for uniform weights; stabilityLimit() estimates it per mesh.
//   Taubin     a lambda step, then a mu step with mu = 1 / (k_pb - 1 / lambda) < 0, which
//              un-shrinks: a low-pass filter with pass-band k_pb (Taubin 1995).
//   implicit   (D + lambda L) x' = D x, backward Euler on all three coordinates (Desbrun et al.
//              1999), L = D - W symmetric. The matrix is factorised once (sparse Cholesky, Eigen's
//              SimplicialLDLT) and reused by every iteration; stable for any lambda.
//
// Every method reports an energy per iteration, E = sum_i |<delta_i, n_i>|^2 (or |delta_i|^2),
// and the first iteration where it grew: that is how divergence is detected and shown.
// Pure CPU; tests in tests/unit/denoise_test.cpp.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/lab/technique.h"
#include "app/scene/mesh_topology.h"
#include "app/util/job_runner.h"

namespace shadelab {

enum class LaplacianWeights { Uniform, Cotangent, Count };
inline constexpr Named<LaplacianWeights> kLaplacianWeights[] = {{LaplacianWeights::Uniform, "uniform"},
                                                                {LaplacianWeights::Cotangent, "cotangent"}};
static_assert(coversEnum<LaplacianWeights>(kLaplacianWeights));

// Symmetric edge weights in the layout of an Adjacency (weight[k] belongs to ring[k]).
struct EdgeWeights {
  std::vector<double> weight;
  std::vector<double> rowSum;    // sum of a vertex's weights
  size_t negativeClamped = 0;    // cotangent weights below zero set to zero
  size_t degenerateCorners = 0;  // corners of zero-area triangles, which contribute nothing
  size_t uniformFallbacks = 0;   // vertices whose weights summed to ~0: uniform for them
};
EdgeWeights edgeWeights(std::span<const glm::dvec3> positions, std::span<const uint32_t> indices,
                        const Adjacency& adjacency, LaplacianWeights kind, bool clampNegative);

// delta_i for every vertex with the given weights.
std::vector<glm::dvec3> umbrella(std::span<const glm::dvec3> positions, const Adjacency& adjacency,
                                 const EdgeWeights& weights);

// The lab's smoothing methods, one table for the panel, the CPU, the GPU and the lab's numbers.
// smooth() steps the Laplacian ones; bilateral filters the face normals instead
// (bilateral_normal.h) and only shares the iteration count. A method is its row here, its code
// (smooth(), or its own filter) and its test.
enum class SmoothingMethod { Explicit, Taubin, Implicit, Bilateral, Count };
struct SmoothingMethodRow {
  SmoothingMethod value;
  std::string_view name;  // as --set denoise.method= spells it
  bool laplacian;         // moves vertices by the Laplacian: has weights, an energy and a stable step to report
  bool explicitSteps;     // steps p - lambda L p: stable only for lambda under about 2 / mu_max; along_normal applies
  bool anyLambda;         // each step a linear solve (a factorisation first): stable for any lambda
  bool onGpu;             // the GPU smoother runs it (gpu_smoother.h)
};
inline constexpr SmoothingMethodRow kSmoothingMethods[] = {
    {SmoothingMethod::Explicit, "explicit", true, true, false, true},
    {SmoothingMethod::Taubin, "taubin", true, true, false, true},
    {SmoothingMethod::Implicit, "implicit", true, false, true, false},
    {SmoothingMethod::Bilateral, "bilateral", false, false, false, false},
};
static_assert(coversEnum<SmoothingMethod>(kSmoothingMethods));
constexpr const SmoothingMethodRow& methodRow(SmoothingMethod m) { return rowOf(kSmoothingMethods, m); }

struct SmoothingSettings {
  SmoothingMethod method = SmoothingMethod::Explicit;
  LaplacianWeights weights = LaplacianWeights::Uniform;
  float lambda = 0.5f;
  int iterations = 10;
  bool alongNormal = true;  // explicit and Taubin: move along the vertex normal only
  bool clampNegative = true;
  float passBand = 0.1f;  // Taubin's k_pb
  bool operator==(const SmoothingSettings&) const = default;
};

// Taubin's second, shrink-undoing step: mu = 1 / (k_pb - 1 / lambda), negative for the panel's
// ranges. 0 for every other method (one step per iteration).
double taubinMu(const SmoothingSettings& s);

struct SmoothingResult {
  std::vector<glm::dvec3> positions;
  std::vector<double> energy;  // before each iteration, and after the last: iterations + 1 values
  int grewAt = 0;              // first iteration (1-based) after which the energy grew; 0 = never
  int stoppedAt = 0;           // iterations done before a non-finite or exploding state; 0 = all ran
  EdgeWeights weightsUsed;
  double factorMs = 0, solveMs = 0;  // implicit: factorisation and all solves
  std::string error;                 // a solver failure, in one line
};

// Runs `settings` from `start`. Once the energy reaches 100 times its start (divergence beyond
// doubt: spikes about 10x the noise) or a step would not be finite, it stops there and says where. With a `job`,
// progress per iteration and early return when cancelled.
SmoothingResult smooth(std::span<const glm::dvec3> start, std::span<const uint32_t> indices, const Adjacency& adjacency,
                       const SmoothingSettings& settings, JobContext* job = nullptr);

// The largest stable explicit lambda, 2 / mu_max, for these weights (full-3D update; the
// along-normal update is at least as stable). Power iteration on the normalised Laplacian.
double stabilityLimit(const Adjacency& adjacency, const EdgeWeights& weights, int iterations = 60);

}  // namespace shadelab
