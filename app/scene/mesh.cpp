#include "scene/mesh.h"

#include "scene/mesh_topology.h"

#include <cmath>

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

int computeTangents(MeshData& mesh) {
  if (mesh.normals.size() != mesh.positions.size()) computeNormals(mesh);
  std::vector<glm::vec3> tan(mesh.positions.size(), glm::vec3(0)), bit(mesh.positions.size(), glm::vec3(0));
  if (mesh.uvs.size() == mesh.positions.size()) {
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
      const glm::vec3 e1 = mesh.positions[i[1]] - mesh.positions[i[0]], e2 = mesh.positions[i[2]] - mesh.positions[i[0]];
      const glm::vec2 d1 = mesh.uvs[i[1]] - mesh.uvs[i[0]], d2 = mesh.uvs[i[2]] - mesh.uvs[i[0]];
      const float det = d1.x * d2.y - d2.x * d1.y;
      if (!(std::abs(det) > 1e-12f)) continue;  // zero-area (or NaN) in UV space: no information
      const float r = 1.0f / det;
      const glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) * r, tdir = (e2 * d1.x - e1 * d2.x) * r;
      for (uint32_t v : i) {
        tan[v] += sdir;
        bit[v] += tdir;
      }
    }
  }
  int fallbacks = 0;
  mesh.tangents.resize(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 n = mesh.normals[v];
    glm::vec3 t = tan[v] - n * glm::dot(n, tan[v]);
    const float len = glm::length(t);
    if (!(len > 1e-12f)) {
      t = anyPerpendicular(n);
      ++fallbacks;
    } else {
      t /= len;
    }
    const float w = glm::dot(glm::cross(n, t), bit[v]) < 0.0f ? -1.0f : 1.0f;  // mirrored UVs
    mesh.tangents[v] = glm::vec4(t, w);
  }
  return fallbacks;
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
