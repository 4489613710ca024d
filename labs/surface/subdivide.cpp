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

MeshData splitEdges(const MeshData& in, int parts) {
  if (parts <= 1) return in;
  const uint32_t n = uint32_t(parts);
  MeshData m;
  m.name = in.name;
  m.material = in.material;
  m.positions = in.positions;  // the corners keep their indices
  m.normals = in.normals;
  m.uvs = in.uvs;
  m.tangents = in.tangents;
  m.sourceTangents = in.sourceTangents;
  // A new vertex at barycentric weights w of corners c (the weights sum to 1).
  auto add = [&](const uint32_t c[3], const float w[3]) {
    const uint32_t v = uint32_t(m.positions.size());
    glm::vec3 p(0.0f), nn(0.0f);
    glm::vec2 uv(0.0f);
    for (int k = 0; k < 3; ++k) {
      p += w[k] * in.positions[c[k]];
      if (!in.normals.empty()) nn += w[k] * in.normals[c[k]];
      if (!in.uvs.empty()) uv += w[k] * in.uvs[c[k]];
    }
    m.positions.push_back(p);
    if (!in.normals.empty()) {
      const float len = glm::length(nn);
      m.normals.push_back(len > 1e-20f ? nn / len : in.normals[c[0]]);
    }
    if (!in.uvs.empty()) m.uvs.push_back(uv);
    for (auto [src, dst] : {std::pair{&in.tangents, &m.tangents}, std::pair{&in.sourceTangents, &m.sourceTangents}}) {
      if (src->empty()) continue;
      glm::vec3 d(0.0f);
      for (int k = 0; k < 3; ++k) d += w[k] * glm::vec3((*src)[c[k]]);
      const float len = glm::length(d);
      dst->push_back(glm::vec4(len > 1e-20f ? d / len : glm::vec3((*src)[c[0]]), (*src)[c[0]].w));
    }
    return v;
  };
  // The k-th of the n-1 inner points of edge (a, b), counted from its lower index: both triangles
  // beside the edge get the same vertex, computed once.
  std::unordered_map<uint64_t, uint32_t> edgeStart;
  auto edgePoint = [&](uint32_t a, uint32_t b, uint32_t k) {
    const uint32_t lo = std::min(a, b), hi = std::max(a, b), step = a == lo ? k : n - k;
    const uint64_t key = uint64_t(lo) << 32 | hi;
    auto [it, added] = edgeStart.emplace(key, uint32_t(m.positions.size()));
    if (added)
      for (uint32_t s = 1; s < n; ++s) {
        const uint32_t c[3] = {lo, hi, lo};
        const float w[3] = {float(n - s) / float(n), float(s) / float(n), 0.0f};
        add(c, w);
      }
    return it->second + step - 1;
  };
  std::vector<uint32_t> grid;
  for (size_t t = 0; t + 2 < in.indices.size(); t += 3) {
    const uint32_t c[3] = {in.indices[t], in.indices[t + 1], in.indices[t + 2]};
    // grid[(i, j)]: the point at weights ((n-i-j)/n, i/n, j/n), i + j <= n, row j of n + 1 - j points.
    grid.assign(size_t(n + 1) * (n + 2) / 2, 0);
    auto at = [&](uint32_t i, uint32_t j) -> uint32_t& { return grid[size_t(j) * (2 * n + 3 - j) / 2 + i]; };
    for (uint32_t j = 0; j <= n; ++j)
      for (uint32_t i = 0; i + j <= n; ++i) {
        const uint32_t r = n - i - j;
        if (r == n)
          at(i, j) = c[0];
        else if (i == n)
          at(i, j) = c[1];
        else if (j == n)
          at(i, j) = c[2];
        else if (j == 0)
          at(i, j) = edgePoint(c[0], c[1], i);
        else if (i == 0)
          at(i, j) = edgePoint(c[0], c[2], j);
        else if (r == 0)
          at(i, j) = edgePoint(c[1], c[2], j);
        else {
          const float w[3] = {float(r) / float(n), float(i) / float(n), float(j) / float(n)};
          at(i, j) = add(c, w);
        }
      }
    for (uint32_t j = 0; j < n; ++j)
      for (uint32_t i = 0; i + j < n; ++i) {
        m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});  // the corners' winding
        if (i + j + 1 < n) m.indices.insert(m.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
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
      const glm::vec3 a = m.positions[i[(k + 1) % 3]] - m.positions[i[k]],
                      b = m.positions[i[(k + 2) % 3]] - m.positions[i[k]];
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
