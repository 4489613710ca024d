// Bilateral normal filtering (Zheng, Fu, Au and Tai, "Bilateral Normal Filtering for Mesh
// Denoising", IEEE TVCG 2011), the local iterative scheme. Laplacian smoothing averages
// positions and so rounds every edge; this filters the face normals instead, weighting each
// neighbour by how near it is (W_s) and by how alike its normal is (W_r):
//
//   n_i' = normalize( sum_j A_j W_s(|c_i - c_j|) W_r(|n_i - n_j|) n_j ),  W(x) = exp(-x^2 / 2 sigma^2)
//
// over the faces sharing a vertex with face i. Across a sharp edge the normals differ, W_r is
// small, and the edge survives. Then the vertices are moved to fit the filtered normals
// (Sun et al. 2007): x_i += 1/|F_i| sum_{f in F_i} n_f (n_f . (c_f - x_i)).
#pragma once
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "app/util/job_runner.h"

namespace shadelab {

struct BilateralSettings {
  int normalIterations = 20;
  int vertexIterations = 10;
  float sigmaR = 0.35f;      // normal difference (|n_i - n_j|, 0..2) that still counts
  double sigmaSScale = 1.0;  // x the mean distance between neighbouring face centroids
  bool operator==(const BilateralSettings&) const = default;
};

struct BilateralResult {
  std::vector<glm::dvec3> positions;
  std::vector<double> normalChangeDeg;  // mean change of the face normals per normal iteration
};

BilateralResult bilateralNormalFilter(std::span<const glm::dvec3> start, std::span<const uint32_t> indices,
                                      const BilateralSettings& settings, JobContext* job = nullptr);

}  // namespace shadelab
