// Triangle meshes on the CPU, and the attribute work done only when a lab needs it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shadelab {

struct Bounds {
  glm::vec3 min{1e30f}, max{-1e30f};
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  bool empty() const { return min.x > max.x; }
  glm::vec3 center() const { return empty() ? glm::vec3(0) : (min + max) * 0.5f; }
  // Corner c of the eight: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
  glm::vec3 corner(int c) const { return {(c & 1) ? max.x : min.x, (c & 2) ? max.y : min.y, (c & 4) ? max.z : min.z}; }
  float radius() const { return empty() ? 1.0f : glm::length(max - min) * 0.5f; }
};

struct MeshData {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;         // empty until present or computed
  std::vector<glm::vec2> uvs;             // empty when the source has none
  std::vector<glm::vec4> tangents;        // xyz tangent, w = handedness; built only on request
  std::vector<glm::vec4> sourceTangents;  // the file's own (glTF TANGENT), in our UV convention, or empty
  std::vector<uint32_t> indices;          // triangles
  // The vertex of the file each vertex came from, where loading split or reordered them (OBJ
  // indexes positions, UVs and normals apart); empty: vertex i is the file's vertex i. Pairs two
  // files' vertices (a noisy scan and its clean mesh) by the order the files list them.
  std::vector<uint32_t> sourceVertex;
  int material = 0;

  size_t triangleCount() const { return indices.size() / 3; }
  Bounds bounds() const;
};

// Angle-weighted vertex normals of the welded surface (scene/mesh_topology.h): copies of a position
// split by UV get the same normal, so no seam shows. Degenerate triangles contribute nothing; a
// vertex left with a zero normal gets +Z, so shading never divides by zero.
void computeNormals(MeshData& mesh);

// Per-vertex tangent frames in the manner of MikkTSpace (Mikkelsen 2008): each triangle's tangent
// and bitangent from its UV derivatives (Lengyel), summed per vertex weighted by the triangle's
// angle there (so the frame does not depend on how a region happens to be triangulated), made
// orthogonal to the normal (Gram-Schmidt), w = +-1 the handedness of the UV map. A vertex shared
// by triangles of opposite UV handedness (mirrored UVs meeting at a line) is split, so each side
// keeps its own frame. Zero-area UV triangles give no direction; a vertex left with none gets any
// unit vector perpendicular to its normal. Vertices are assumed split at UV seams already.
struct TangentReport {
  int fallbacks = 0;     // vertices given an arbitrary perpendicular (degenerate UVs)
  int mirrorSplits = 0;  // vertices duplicated where mirrored UVs meet
  int degenerateUvTriangles = 0;
};
TangentReport computeTangents(MeshData& mesh);

// Rejects what would crash or poison the renderer: out-of-range indices, NaN/Inf positions,
// attribute arrays of the wrong length. Returns "" or a one-line reason.
std::string validateMesh(const MeshData& mesh);

}  // namespace shadelab
