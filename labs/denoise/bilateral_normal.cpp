#include "labs/denoise/bilateral_normal.h"

#include <algorithm>
#include <cmath>

namespace shadelab {
namespace {

struct Faces {
  std::vector<glm::dvec3> centroid, normal;
  std::vector<double> area;
};

Faces facesOf(std::span<const glm::dvec3> p, std::span<const uint32_t> idx) {
  const size_t n = idx.size() / 3;
  Faces f{std::vector<glm::dvec3>(n), std::vector<glm::dvec3>(n), std::vector<double>(n)};
  for (size_t t = 0; t < n; ++t) {
    const glm::dvec3 a = p[idx[3 * t]], b = p[idx[3 * t + 1]], c = p[idx[3 * t + 2]];
    const glm::dvec3 cr = glm::cross(b - a, c - a);
    const double len = glm::length(cr);
    f.centroid[t] = (a + b + c) / 3.0;
    f.area[t] = 0.5 * len;
    f.normal[t] = len > 0.0 && std::isfinite(len) ? cr / len : glm::dvec3(0.0);
  }
  return f;
}

// Compressed rows: the faces around each vertex, and the faces sharing a vertex with each face.
struct Rings {
  std::vector<uint32_t> vertexOffsets, vertexFaces;
  std::vector<uint32_t> faceOffsets, faceNeighbours;
};

Rings ringsOf(size_t vertices, std::span<const uint32_t> idx) {
  Rings r;
  const size_t faces = idx.size() / 3;
  r.vertexOffsets.assign(vertices + 1, 0);
  for (uint32_t v : idx) ++r.vertexOffsets[v + 1];
  for (size_t v = 0; v < vertices; ++v) r.vertexOffsets[v + 1] += r.vertexOffsets[v];
  r.vertexFaces.resize(idx.size());
  std::vector<uint32_t> fill(r.vertexOffsets.begin(), r.vertexOffsets.end() - 1);
  for (size_t t = 0; t < faces; ++t)
    for (int k = 0; k < 3; ++k) r.vertexFaces[fill[idx[3 * t + size_t(k)]]++] = uint32_t(t);
  r.faceOffsets.push_back(0);
  std::vector<uint32_t> around;
  for (size_t t = 0; t < faces; ++t) {
    around.clear();
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = idx[3 * t + size_t(k)];
      around.insert(around.end(), r.vertexFaces.begin() + r.vertexOffsets[v],
                    r.vertexFaces.begin() + r.vertexOffsets[v + 1]);
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    r.faceNeighbours.insert(r.faceNeighbours.end(), around.begin(), around.end());  // includes t itself
    r.faceOffsets.push_back(uint32_t(r.faceNeighbours.size()));
  }
  return r;
}

}  // namespace

BilateralResult bilateralNormalFilter(std::span<const glm::dvec3> start, std::span<const uint32_t> idx,
                                      const BilateralSettings& s, JobContext* job) {
  BilateralResult out;
  out.positions.assign(start.begin(), start.end());
  const Rings rings = ringsOf(start.size(), idx);
  Faces f = facesOf(out.positions, idx);
  const size_t faces = f.normal.size();

  // sigma_s: the mean distance between the centroids of faces that share a vertex.
  double spacing = 0.0;
  size_t pairs = 0;
  for (size_t t = 0; t < faces; ++t)
    for (uint32_t k = rings.faceOffsets[t]; k < rings.faceOffsets[t + 1]; ++k)
      if (rings.faceNeighbours[k] != t) {
        spacing += glm::length(f.centroid[t] - f.centroid[rings.faceNeighbours[k]]);
        ++pairs;
      }
  const double sigmaS = std::max(s.sigmaSScale * (pairs ? spacing / double(pairs) : 1.0), 1e-300);
  const double sigmaR = std::max(double(s.sigmaR), 1e-6);
  const int total = s.normalIterations + s.vertexIterations;

  std::vector<glm::dvec3> filtered(faces);
  for (int it = 0; it < s.normalIterations; ++it) {
    if (job && !job->progress(float(it) / float(total), "normal filtering " + std::to_string(it + 1) + " of " +
                                                            std::to_string(s.normalIterations)))
      return out;
    double change = 0.0;
    for (size_t t = 0; t < faces; ++t) {
      glm::dvec3 sum(0.0);
      for (uint32_t k = rings.faceOffsets[t]; k < rings.faceOffsets[t + 1]; ++k) {
        const uint32_t j = rings.faceNeighbours[k];
        const double ds = glm::length(f.centroid[t] - f.centroid[j]), dr = glm::length(f.normal[t] - f.normal[j]);
        sum += f.area[j] * std::exp(-ds * ds / (2 * sigmaS * sigmaS)) * std::exp(-dr * dr / (2 * sigmaR * sigmaR)) *
               f.normal[j];
      }
      const double len = glm::length(sum);
      filtered[t] = len > 0.0 && std::isfinite(len) ? sum / len : f.normal[t];
      change += std::acos(std::clamp(glm::dot(filtered[t], f.normal[t]), -1.0, 1.0));
    }
    f.normal.swap(filtered);
    out.normalChangeDeg.push_back(glm::degrees(change / double(std::max<size_t>(faces, 1))));
  }
  // Fit the vertices to the filtered normals; centroids follow the moving vertices.
  for (int it = 0; it < s.vertexIterations; ++it) {
    if (job && !job->progress(float(s.normalIterations + it) / float(total),
                              "vertex update " + std::to_string(it + 1) + " of " + std::to_string(s.vertexIterations)))
      return out;
    for (size_t t = 0; t < faces; ++t)
      f.centroid[t] = (out.positions[idx[3 * t]] + out.positions[idx[3 * t + 1]] + out.positions[idx[3 * t + 2]]) / 3.0;
    std::vector<glm::dvec3> next = out.positions;
    for (size_t v = 0; v < next.size(); ++v) {
      const uint32_t b = rings.vertexOffsets[v], e = rings.vertexOffsets[v + 1];
      if (b == e) continue;
      glm::dvec3 move(0.0);
      for (uint32_t k = b; k < e; ++k) {
        const uint32_t t = rings.vertexFaces[k];
        move += f.normal[t] * glm::dot(f.normal[t], f.centroid[t] - out.positions[v]);
      }
      next[v] += move / double(e - b);
    }
    out.positions.swap(next);
  }
  return out;
}

}  // namespace shadelab
