#include "labs/surface/subdivide.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace shadelab {

MeshData subdivide(const MeshData& in, int levels) {
  MeshData m = in;
  m.sourceVertex.clear();  // new vertices come from no file vertex
  for (int level = 0; level < levels; ++level) {
    std::unordered_map<uint64_t, uint32_t> midpoint;
    midpoint.reserve(m.indices.size());
    auto mid = [&](uint32_t a, uint32_t b) {
      const uint64_t key = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
      auto [it, added] = midpoint.emplace(key, uint32_t(m.positions.size()));
      if (!added) return it->second;
      m.positions.push_back(0.5f * (m.positions[a] + m.positions[b]));
      if (!m.normals.empty()) {
        const glm::vec3 n = m.normals[a] + m.normals[b];
        const float len = glm::length(n);
        m.normals.push_back(len > 1e-20f ? n / len : m.normals[a]);
      }
      if (!m.uvs.empty()) m.uvs.push_back(0.5f * (m.uvs[a] + m.uvs[b]));
      for (auto* t : {&m.tangents, &m.sourceTangents}) {
        if (t->empty()) continue;
        const glm::vec3 d = glm::vec3((*t)[a]) + glm::vec3((*t)[b]);
        const float len = glm::length(d);
        t->push_back(glm::vec4(len > 1e-20f ? d / len : glm::vec3((*t)[a]), (*t)[a].w));
      }
      return it->second;
    };
    std::vector<uint32_t> next;
    next.reserve(m.indices.size() * 4);
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      const uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
      const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      next.insert(next.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    m.indices = std::move(next);
  }
  return m;
}

std::vector<glm::vec2> uvScale(const MeshData& m) {
  std::vector<glm::vec2> sum(m.positions.size(), glm::vec2(0.0f));
  std::vector<float> weight(m.positions.size(), 0.0f);
  if (m.uvs.size() != m.positions.size()) return std::vector<glm::vec2>(m.positions.size(), glm::vec2(1.0f));
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const uint32_t i[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
    const glm::vec3 e1 = m.positions[i[1]] - m.positions[i[0]], e2 = m.positions[i[2]] - m.positions[i[0]];
    const glm::vec2 d1 = m.uvs[i[1]] - m.uvs[i[0]], d2 = m.uvs[i[2]] - m.uvs[i[0]];
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 1e-12f)) continue;
    const glm::vec2 scale(glm::length((e1 * d2.y - e2 * d1.y) / det), glm::length((e2 * d1.x - e1 * d2.x) / det));
    if (!std::isfinite(scale.x + scale.y)) continue;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 a = m.positions[i[(k + 1) % 3]] - m.positions[i[k]], b = m.positions[i[(k + 2) % 3]] - m.positions[i[k]];
      const float la = glm::length(a), lb = glm::length(b);
      if (!(la > 0.0f && lb > 0.0f)) continue;
      const float angle = std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
      sum[i[k]] += scale * angle;
      weight[i[k]] += angle;
    }
  }
  for (size_t v = 0; v < sum.size(); ++v) sum[v] = weight[v] > 0.0f ? sum[v] / weight[v] : glm::vec2(1.0f);
  return sum;
}

std::vector<float> uvShearDegrees(const MeshData& m) {
  std::vector<float> out;
  if (m.uvs.size() != m.positions.size()) return out;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const uint32_t i[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
    const glm::vec3 e1 = m.positions[i[1]] - m.positions[i[0]], e2 = m.positions[i[2]] - m.positions[i[0]];
    const glm::vec2 d1 = m.uvs[i[1]] - m.uvs[i[0]], d2 = m.uvs[i[2]] - m.uvs[i[0]];
    const float det = d1.x * d2.y - d2.x * d1.y;
    const glm::vec3 n = glm::cross(e1, e2);
    if (!(std::abs(det) > 1e-12f) || !(glm::length(n) > 0.0f)) continue;
    const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
    // grad u: the vector g in the plane with g.e1 = d1.u and g.e2 = d2.u (up to a positive factor).
    const glm::vec3 grad = glm::cross(e2, n) * d1.x + glm::cross(n, e1) * d2.x;
    const float la = glm::length(dpdu), lb = glm::length(grad);
    if (!(la > 0.0f && lb > 0.0f) || !std::isfinite(la + lb)) continue;
    out.push_back(glm::degrees(std::acos(std::clamp(std::abs(glm::dot(dpdu, grad)) / (la * lb), 0.0f, 1.0f))));
  }
  return out;
}

int levelsForTexelSize(const MeshData& m, int texels, int maxLevels) {
  const std::vector<glm::vec2> scale = uvScale(m);
  double edgeUv = 0.0;
  size_t count = 0;
  for (size_t t = 0; t + 2 < m.indices.size() && !m.uvs.empty(); t += 3)
    for (int e = 0; e < 3; ++e) {
      edgeUv += glm::length(m.uvs[m.indices[t + size_t(e)]] - m.uvs[m.indices[t + size_t((e + 1) % 3)]]);
      ++count;
    }
  if (!count) return 0;
  const double texel = 1.0 / double(std::max(texels, 1)), mean = edgeUv / double(count);
  int levels = 0;
  for (double e = mean; e > texel && levels < maxLevels; e *= 0.5) ++levels;
  return levels;
}

}  // namespace shadelab
