// The surface behind a render mesh. Render vertices are split wherever an attribute differs (a UV
// seam, a crease's normals), but the surface they describe is one: algorithms that look at
// neighbours (smoothing, vertex normals, tangents) must see every triangle around a position,
// or copies of one position drift apart and the mesh cracks along its seams.
//
//   WeldedMesh w = weldByPosition(mesh);          // one logical vertex per position
//   Adjacency a = buildAdjacency(w.vertexCount(), w.indices);
//   auto n = vertexNormals(w.positions, w.indices, NormalWeighting::Angle);
//   for (size_t v = 0; v < mesh.positions.size(); ++v) mesh.normals[v] = n[w.logicalOf[v]];
//
// Pure CPU, no GL; unit-tested in tests/unit/mesh_topology_test.cpp.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "app/scene/mesh.h"

namespace shadelab {

struct WeldedMesh {
  std::vector<glm::vec3> positions;  // one per logical vertex, in order of first appearance
  std::vector<uint32_t> indices;     // the render triangles, same order, over logical vertices
  std::vector<uint32_t> logicalOf;   // render vertex -> logical vertex
  size_t vertexCount() const { return positions.size(); }
  size_t triangleCount() const { return indices.size() / 3; }
};

// Render vertices with bit-identical positions (-0 and +0 alike) become one logical vertex.
WeldedMesh weldByPosition(std::span<const glm::vec3> positions, std::span<const uint32_t> indices);
inline WeldedMesh weldByPosition(const MeshData& m) { return weldByPosition(m.positions, m.indices); }

// One-ring neighbours in compressed rows: neighbours of v are ring[offsets[v] .. offsets[v+1]),
// sorted by index (so an edge's slot is found by binary search).
struct Adjacency {
  std::vector<uint32_t> offsets;
  std::vector<uint32_t> ring;
  std::vector<uint8_t> boundary;  // v touches an edge with one triangle
  size_t boundaryEdges = 0;       // edges with exactly one triangle
  size_t nonManifoldEdges = 0;    // edges with three or more
  size_t isolatedVertices = 0;    // in no triangle
  std::span<const uint32_t> neighbours(uint32_t v) const {
    return {ring.data() + offsets[v], ring.data() + offsets[v + 1]};
  }
  size_t degree(uint32_t v) const { return offsets[v + 1] - offsets[v]; }
};
// Triangles with a repeated index are skipped (they have no edges worth the name).
Adjacency buildAdjacency(size_t vertexCount, std::span<const uint32_t> indices);

// Unit face normals; a zero-area face gets (0, 0, 0), never NaN.
std::vector<glm::vec3> faceNormals(std::span<const glm::vec3> positions, std::span<const uint32_t> indices);

enum class NormalWeighting {
  Area,   // each face counts by its area: big faces dominate
  Angle,  // by the face's angle at the vertex (Thuermer and Wuethrich 1998): independent of how the
          // surface around the vertex happens to be triangulated
};
// Unit vertex normals; a vertex no face gives a direction to gets +Z. In float for drawing, in
// double for the denoising lab's solvers.
std::vector<glm::vec3> vertexNormals(std::span<const glm::vec3> positions, std::span<const uint32_t> indices,
                                     NormalWeighting weighting);
std::vector<glm::dvec3> vertexNormals(std::span<const glm::dvec3> positions, std::span<const uint32_t> indices,
                                      NormalWeighting weighting);

// Counts a student can read in a mesh-statistics table.
struct MeshStatistics {
  size_t renderVertices = 0, logicalVertices = 0, triangles = 0;
  size_t seamVertices = 0;  // logical vertices with more than one render copy
  size_t boundaryEdges = 0, nonManifoldEdges = 0, isolatedVertices = 0, zeroAreaFaces = 0;
  double meanEdgeLength = 0;
};
MeshStatistics meshStatistics(const MeshData& mesh, const WeldedMesh& welded, const Adjacency& adjacency);
double meanEdgeLength(std::span<const glm::vec3> positions, std::span<const uint32_t> indices);
double meanEdgeLength(std::span<const glm::dvec3> positions, std::span<const uint32_t> indices);

}  // namespace shadelab
