#include "labs/denoise/mesh_metrics.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace shadelab {

static bool unitNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, glm::dvec3& n) {
  n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  if (!(len > 0.0) || !std::isfinite(len)) return false;
  n /= len;
  return true;
}

double meanFaceNormalAngleDeg(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b,
                              std::span<const uint32_t> idx, size_t* degenerate) {
  double sum = 0.0;
  size_t faces = 0, skipped = 0;
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    glm::dvec3 na, nb;
    if (!unitNormal(a[idx[t]], a[idx[t + 1]], a[idx[t + 2]], na) ||
        !unitNormal(b[idx[t]], b[idx[t + 1]], b[idx[t + 2]], nb)) {
      ++skipped;
      continue;
    }
    sum += std::acos(std::clamp(glm::dot(na, nb), -1.0, 1.0));
    ++faces;
  }
  if (degenerate) *degenerate = skipped;
  return faces ? glm::degrees(sum / double(faces)) : 0.0;
}

double signedVolume(std::span<const glm::dvec3> p, std::span<const uint32_t> idx, const glm::dvec3& o) {
  double v = 0.0;
  for (size_t t = 0; t + 2 < idx.size(); t += 3)
    v += glm::dot(p[idx[t]] - o, glm::cross(p[idx[t + 1]] - o, p[idx[t + 2]] - o));
  return v / 6.0;
}

MeshError meshError(std::span<const glm::dvec3> result, std::span<const glm::dvec3> clean,
                    std::span<const uint32_t> idx, double unit) {
  MeshError e;
  e.angleDeg = meanFaceNormalAngleDeg(result, clean, idx, &e.degenerateFaces);
  double sq = 0.0;
  glm::dvec3 centroid(0.0);
  for (size_t v = 0; v < clean.size(); ++v) {
    const double d = glm::length(result[v] - clean[v]);
    sq += d * d;
    e.maxDistance = std::max(e.maxDistance, d);
    centroid += clean[v];
  }
  const double n = double(std::max<size_t>(clean.size(), 1));
  centroid /= n;
  unit = unit > 0.0 ? unit : 1.0;
  e.rmsDistance = std::sqrt(sq / n) / unit;
  e.maxDistance /= unit;
  const double v0 = signedVolume(clean, idx, centroid), v1 = signedVolume(result, idx, centroid);
  e.volumeChangePct = std::abs(v0) > 0.0 ? 100.0 * (v1 - v0) / std::abs(v0) : 0.0;
  return e;
}

}  // namespace shadelab
