#include "app/scene/mesh.h"

#include "app/scene/mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace shadelab {

Bounds MeshData::bounds() const {
  Bounds b;
  for (auto& p : positions) b.extend(p);
  return b;
}

void computeNormals(MeshData& mesh) {
  const WeldedMesh welded = weldByPosition(mesh);
  const std::vector<glm::vec3> n = vertexNormals(welded.positions, welded.indices, NormalWeighting::Angle);
  mesh.normals.resize(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) mesh.normals[v] = n[welded.logicalOf[v]];
}

static glm::vec3 anyPerpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(axis, n));
}

TangentReport computeTangents(MeshData& mesh) {
  TangentReport report;
  if (mesh.normals.size() != mesh.positions.size()) computeNormals(mesh);
  const bool hasUvs = mesh.uvs.size() == mesh.positions.size();
  const size_t triangles = mesh.indices.size() / 3;
  // 1. Each triangle's UV handedness: the sign of its UV area (0: degenerate in UV).
  std::vector<int> sign(triangles, 0);
  for (size_t t = 0; hasUvs && t < triangles; ++t) {
    const glm::vec2 d1 = mesh.uvs[mesh.indices[3 * t + 1]] - mesh.uvs[mesh.indices[3 * t]];
    const glm::vec2 d2 = mesh.uvs[mesh.indices[3 * t + 2]] - mesh.uvs[mesh.indices[3 * t]];
    const float det = d1.x * d2.y - d2.x * d1.y;
    sign[t] = det > 1e-12f ? 1 : det < -1e-12f ? -1 : 0;
    report.degenerateUvTriangles += sign[t] == 0;
  }
  // 2. Split vertices where triangles of both handednesses meet: the negative side gets a copy.
  if (hasUvs) {
    std::vector<uint8_t> seen(mesh.positions.size(), 0);  // bit 1: a positive triangle, bit 2: a negative one
    for (size_t t = 0; t < triangles; ++t)
      for (int k = 0; k < 3; ++k) seen[mesh.indices[3 * t + size_t(k)]] |= sign[t] > 0 ? 1 : sign[t] < 0 ? 2 : 0;
    std::vector<uint32_t> copyOf(mesh.positions.size(), UINT32_MAX);
    for (size_t t = 0; t < triangles; ++t) {
      if (sign[t] >= 0) continue;
      for (int k = 0; k < 3; ++k) {
        uint32_t& v = mesh.indices[3 * t + size_t(k)];
        if (seen[v] != 3) continue;
        if (copyOf[v] == UINT32_MAX) {
          copyOf[v] = uint32_t(mesh.positions.size());
          mesh.positions.push_back(mesh.positions[v]);
          mesh.normals.push_back(mesh.normals[v]);
          mesh.uvs.push_back(mesh.uvs[v]);
          if (!mesh.sourceTangents.empty()) mesh.sourceTangents.push_back(mesh.sourceTangents[v]);
          if (!mesh.sourceVertex.empty()) mesh.sourceVertex.push_back(mesh.sourceVertex[v]);
          ++report.mirrorSplits;
        }
        v = copyOf[v];
      }
    }
  }
  // 3. Angle-weighted sums of each triangle's tangent and bitangent.
  std::vector<glm::vec3> tan(mesh.positions.size(), glm::vec3(0)), bit(mesh.positions.size(), glm::vec3(0));
  for (size_t t = 0; hasUvs && t < triangles; ++t) {
    if (sign[t] == 0) continue;  // zero area in UV space (or NaN): no information
    const uint32_t i[3] = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
    const glm::vec3 e1 = mesh.positions[i[1]] - mesh.positions[i[0]], e2 = mesh.positions[i[2]] - mesh.positions[i[0]];
    const glm::vec2 d1 = mesh.uvs[i[1]] - mesh.uvs[i[0]], d2 = mesh.uvs[i[2]] - mesh.uvs[i[0]];
    const float r = 1.0f / (d1.x * d2.y - d2.x * d1.y);
    glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) * r, tdir = (e2 * d1.x - e1 * d2.x) * r;
    const float sl = glm::length(sdir), tl = glm::length(tdir);
    if (!(sl > 0.0f) || !(tl > 0.0f) || !std::isfinite(sl + tl)) continue;
    sdir /= sl;  // directions only: the angle is the weight
    tdir /= tl;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 a = mesh.positions[i[(k + 1) % 3]] - mesh.positions[i[k]],
                      b = mesh.positions[i[(k + 2) % 3]] - mesh.positions[i[k]];
      const float la = glm::length(a), lb = glm::length(b);
      if (!(la > 0.0f && lb > 0.0f)) continue;
      const float angle = std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
      tan[i[k]] += sdir * angle;
      bit[i[k]] += tdir * angle;
    }
  }
  // 4. Orthogonal to the normal; handedness from the bitangent; a fallback where nothing points.
  mesh.tangents.resize(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 n = mesh.normals[v];
    glm::vec3 t = tan[v] - n * glm::dot(n, tan[v]);
    const float len = glm::length(t);
    if (!(len > 1e-12f) || !std::isfinite(len)) {
      t = anyPerpendicular(n);
      ++report.fallbacks;
    } else {
      t /= len;
    }
    const float w = glm::dot(glm::cross(n, t), bit[v]) < 0.0f ? -1.0f : 1.0f;  // mirrored UVs
    mesh.tangents[v] = glm::vec4(t, w);
  }
  return report;
}

std::string validateMesh(const MeshData& m) {
  const size_t n = m.positions.size();
  if (m.indices.size() % 3) return "index count " + std::to_string(m.indices.size()) + " is not a multiple of 3";
  for (uint32_t i : m.indices)
    if (i >= n) return "index " + std::to_string(i) + " out of range (" + std::to_string(n) + " vertices)";
  for (auto& p : m.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return "a vertex position is NaN or Inf";
  if (!m.normals.empty() && m.normals.size() != n) return "normal count differs from vertex count";
  if (!m.uvs.empty() && m.uvs.size() != n) return "UV count differs from vertex count";
  return {};
}

}  // namespace shadelab
