#include "labs/denoise/mesh_pair.h"

#include <algorithm>
#include <optional>

namespace shadelab {
namespace {

uint32_t fileVertexOf(const MeshData& m, size_t v) { return m.sourceVertex.empty() ? uint32_t(v) : m.sourceVertex[v]; }

// Positions by the file's vertex number; a number no face used stays empty.
std::vector<std::optional<glm::vec3>> byFileVertex(const MeshData& m) {
  size_t count = m.positions.size();
  if (!m.sourceVertex.empty()) count = size_t(*std::max_element(m.sourceVertex.begin(), m.sourceVertex.end())) + 1;
  std::vector<std::optional<glm::vec3>> out(count);
  for (size_t v = 0; v < m.positions.size(); ++v) out[fileVertexOf(m, v)] = m.positions[v];
  return out;
}

double meanEdge(const MeshData& m) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      sum += glm::length(m.positions[m.indices[t + size_t(k)]] - m.positions[m.indices[t + size_t((k + 1) % 3)]]);
      ++n;
    }
  return n ? sum / double(n) : 0.0;
}

// How far the pair's vertices lie apart, on average, in mean edge lengths of the clean mesh.
double meanMove(const MeshData& twin, const MeshData& clean) {
  const double edge = meanEdge(clean);
  if (clean.positions.empty() || !(edge > 0.0)) return 0.0;
  double move = 0.0;
  for (size_t v = 0; v < clean.positions.size(); ++v) move += glm::length(twin.positions[v] - clean.positions[v]);
  return move / double(clean.positions.size()) / edge;
}

}  // namespace

std::string pairWithClean(const MeshData& noisy, const MeshData& clean, const std::string& noisyName,
                          const std::string& cleanName, MeshPair& pair) {
  if (!noisy.sourceVertex.empty() && noisy.sourceVertex.size() != noisy.positions.size())
    return noisyName + ": the mesh's vertex numbering is inconsistent";
  if (!clean.sourceVertex.empty() && clean.sourceVertex.size() != clean.positions.size())
    return cleanName + ": the mesh's vertex numbering is inconsistent";
  pair.twin = clean;
  pair.twin.normals.clear();
  pair.twin.tangents.clear();
  pair.twin.sourceTangents.clear();

  // The same vertices in the same order: each clean vertex takes the noisy file's vertex of its number.
  const auto noisyVertices = byFileVertex(noisy), cleanVertices = byFileVertex(clean);
  if (noisyVertices.size() == cleanVertices.size()) {
    bool all = true;
    for (size_t v = 0; v < clean.positions.size() && all; ++v) {
      const auto& p = noisyVertices[fileVertexOf(clean, v)];
      if (p) pair.twin.positions[v] = *p;
      all = p.has_value();
    }
    if (all) {
      pair.how = "vertices in the same order";
      pair.meanMoveEdges = meanMove(pair.twin, clean);
      return {};
    }
  }
  // The same faces in the same order: corner k of face t is the same vertex in both.
  if (noisy.indices.size() == clean.indices.size() && !clean.indices.empty()) {
    std::vector<int64_t> noisyOf(clean.positions.size(), -1);
    for (size_t c = 0; c < clean.indices.size(); ++c) {
      const uint32_t cv = clean.indices[c], nv = noisy.indices[c];
      if (noisyOf[cv] < 0) {
        noisyOf[cv] = nv;
      } else if (noisy.positions[size_t(noisyOf[cv])] != noisy.positions[nv]) {
        return cleanName + " and " + noisyName + " list " + std::to_string(clean.indices.size() / 3) +
               " faces each, but corner " + std::to_string(c % 3) + " of face " + std::to_string(c / 3) +
               " is another vertex than the same corner of an earlier face: the faces are not in the same order";
      }
    }
    for (size_t v = 0; v < clean.positions.size(); ++v)
      if (noisyOf[v] >= 0) pair.twin.positions[v] = noisy.positions[size_t(noisyOf[v])];  // else in no face: kept
    pair.meanMoveEdges = meanMove(pair.twin, clean);
    pair.how = "faces in the same order";
    return {};
  }
  return noisyName + " (" + std::to_string(noisyVertices.size()) + " vertices, " +
         std::to_string(noisy.indices.size() / 3) + " triangles) and " + cleanName + " (" +
         std::to_string(cleanVertices.size()) + " vertices, " + std::to_string(clean.indices.size() / 3) +
         " triangles) are not a pair: a noisy mesh and its clean reference need the same vertices in the same order, "
         "or the same faces in the same order";
}

}  // namespace shadelab
