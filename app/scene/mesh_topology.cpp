#include "app/scene/mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

namespace shadelab {
namespace {

struct PositionKey {
  uint32_t bits[3];
  bool operator==(const PositionKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};
struct PositionHash {
  size_t operator()(const PositionKey& k) const {
    return (size_t(k.bits[0]) * 73856093u) ^ (size_t(k.bits[1]) * 19349663u) ^ (size_t(k.bits[2]) * 83492791u);
  }
};

PositionKey keyOf(const glm::vec3& p) {
  PositionKey k;
  for (int i = 0; i < 3; ++i) {
    const float f = p[i] == 0.0f ? 0.0f : p[i];  // -0 and +0 are one position
    std::memcpy(&k.bits[i], &f, sizeof f);
  }
  return k;
}

bool degenerateIndices(const uint32_t* t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

}  // namespace

WeldedMesh weldByPosition(std::span<const glm::vec3> positions, std::span<const uint32_t> indices) {
  WeldedMesh w;
  w.logicalOf.resize(positions.size());
  std::unordered_map<PositionKey, uint32_t, PositionHash> first;
  first.reserve(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    auto [it, added] = first.emplace(keyOf(positions[v]), uint32_t(w.positions.size()));
    if (added) w.positions.push_back(positions[v]);
    w.logicalOf[v] = it->second;
  }
  w.indices.resize(indices.size());
  for (size_t i = 0; i < indices.size(); ++i) w.indices[i] = w.logicalOf[indices[i]];
  return w;
}

Adjacency buildAdjacency(size_t vertexCount, std::span<const uint32_t> indices) {
  // Every undirected edge once per triangle that has it, as (low, high); sorted, runs of equal
  // edges count the triangles sharing it.
  std::vector<uint64_t> edges;
  edges.reserve(indices.size());
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    if (degenerateIndices(&indices[t])) continue;
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = indices[t + size_t(e)], b = indices[t + size_t((e + 1) % 3)];
      edges.push_back(uint64_t(std::min(a, b)) << 32 | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  Adjacency adj;
  adj.boundary.assign(vertexCount, 0);
  std::vector<uint32_t> degree(vertexCount, 0);
  std::vector<uint64_t> unique;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    const uint32_t a = uint32_t(edges[i] >> 32), b = uint32_t(edges[i]);
    const size_t sharing = j - i;
    if (sharing == 1) {
      ++adj.boundaryEdges;
      adj.boundary[a] = adj.boundary[b] = 1;
    } else if (sharing > 2) {
      ++adj.nonManifoldEdges;
    }
    ++degree[a];
    ++degree[b];
    unique.push_back(edges[i]);
    i = j;
  }
  adj.offsets.assign(vertexCount + 1, 0);
  for (size_t v = 0; v < vertexCount; ++v) adj.offsets[v + 1] = adj.offsets[v] + degree[v];
  adj.ring.resize(adj.offsets.back());
  std::vector<uint32_t> fill(adj.offsets.begin(), adj.offsets.end() - 1);
  for (uint64_t e : unique) {
    const uint32_t a = uint32_t(e >> 32), b = uint32_t(e);
    adj.ring[fill[a]++] = b;
    adj.ring[fill[b]++] = a;
  }
  for (size_t v = 0; v < vertexCount; ++v) {
    adj.isolatedVertices += degree[v] == 0;
    std::sort(adj.ring.begin() + adj.offsets[v], adj.ring.begin() + adj.offsets[v + 1]);
  }
  return adj;
}

std::vector<glm::vec3> faceNormals(std::span<const glm::vec3> p, std::span<const uint32_t> indices) {
  std::vector<glm::vec3> n(indices.size() / 3);
  for (size_t f = 0; f < n.size(); ++f) {
    const glm::vec3 c =
        glm::cross(p[indices[3 * f + 1]] - p[indices[3 * f]], p[indices[3 * f + 2]] - p[indices[3 * f]]);
    const float len = glm::length(c);
    n[f] = len > 0.0f && std::isfinite(len) ? c / len : glm::vec3(0.0f);
  }
  return n;
}

namespace {

template <class Vec>
std::vector<Vec> vertexNormalsT(std::span<const Vec> p, std::span<const uint32_t> indices, NormalWeighting weighting) {
  using T = typename Vec::value_type;
  std::vector<Vec> n(p.size(), Vec(0));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t i[3] = {indices[t], indices[t + 1], indices[t + 2]};
    const Vec c = glm::cross(p[i[1]] - p[i[0]], p[i[2]] - p[i[0]]);  // |c| = twice the area
    const T len = glm::length(c);
    if (!std::isfinite(len)) continue;  // a NaN position must not spoil its neighbours
    if (weighting == NormalWeighting::Area) {
      for (uint32_t v : i) n[v] += c;
      continue;
    }
    if (!(len > T(0))) continue;
    const Vec unit = c / len;
    for (int k = 0; k < 3; ++k) {
      const Vec e1 = p[i[(k + 1) % 3]] - p[i[k]], e2 = p[i[(k + 2) % 3]] - p[i[k]];
      const T l1 = glm::length(e1), l2 = glm::length(e2);
      if (!(l1 > T(0) && l2 > T(0))) continue;
      n[i[k]] += unit * std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), T(-1), T(1)));
    }
  }
  const T tiny = std::numeric_limits<T>::min() * T(1e8);  // about 1e-30 in float, 1e-300 in double
  for (auto& v : n) {
    const T len = glm::length(v);
    v = len > tiny && std::isfinite(len) ? v / len : Vec(0, 0, 1);
  }
  return n;
}

template <class Vec>
double meanEdgeLengthT(std::span<const Vec> p, std::span<const uint32_t> indices) {
  double sum = 0;
  size_t count = 0;
  for (size_t t = 0; t + 2 < indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      sum += double(glm::length(p[indices[t + size_t(e)]] - p[indices[t + size_t((e + 1) % 3)]]));
      ++count;
    }
  return count ? sum / double(count) : 0.0;
}

}  // namespace

std::vector<glm::vec3> vertexNormals(std::span<const glm::vec3> p, std::span<const uint32_t> indices,
                                     NormalWeighting weighting) {
  return vertexNormalsT(p, indices, weighting);
}
std::vector<glm::dvec3> vertexNormals(std::span<const glm::dvec3> p, std::span<const uint32_t> indices,
                                      NormalWeighting weighting) {
  return vertexNormalsT(p, indices, weighting);
}
double meanEdgeLength(std::span<const glm::vec3> p, std::span<const uint32_t> indices) {
  return meanEdgeLengthT(p, indices);
}
double meanEdgeLength(std::span<const glm::dvec3> p, std::span<const uint32_t> indices) {
  return meanEdgeLengthT(p, indices);
}

MeshStatistics meshStatistics(const MeshData& mesh, const WeldedMesh& w, const Adjacency& a) {
  MeshStatistics s;
  s.renderVertices = mesh.positions.size();
  s.logicalVertices = w.vertexCount();
  s.triangles = w.triangleCount();
  std::vector<uint32_t> copies(w.vertexCount(), 0);
  for (uint32_t l : w.logicalOf) ++copies[l];
  for (uint32_t c : copies) s.seamVertices += c > 1;
  s.boundaryEdges = a.boundaryEdges;
  s.nonManifoldEdges = a.nonManifoldEdges;
  s.isolatedVertices = a.isolatedVertices;
  for (auto& n : faceNormals(w.positions, w.indices)) s.zeroAreaFaces += n == glm::vec3(0.0f);
  s.meanEdgeLength = meanEdgeLength(w.positions, w.indices);
  return s;
}

}  // namespace shadelab
