// A bounding volume hierarchy over triangles, built on the CPU with a binned surface area
// heuristic (Wald 2007: sort centroids into bins along each axis, sweep the bins for the split
// whose children's areas times triangle counts are smallest), traversed here for closest and any
// hits, and flattened into arrays of vec4 texels that a fragment shader can walk with a stack
// (GLSL 3.30 / 4.10 and GLSL ES 3.00 read them with texelFetch and floatBitsToUint).
//
// A truth that traces rays on the GPU (shadows: visibility of a point or an area light) builds it
// once per geometry, checks it against brute force and against Embree on the CPU, and uploads it.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace shadelab {

struct BvhTriangle {
  glm::vec3 a, b, c;
};

// 32 bytes: a box and, for a leaf (count > 0), its triangles [first, first + count) of the
// reordered list; for an inner node (count == 0), its children at `first` and `first + 1`.
struct BvhNode {
  glm::vec3 min{0.0f};
  uint32_t first = 0;
  glm::vec3 max{0.0f};
  uint32_t count = 0;
};

struct BvhHit {
  float t = 0.0f;            // distance along the ray in units of |dir|
  uint32_t triangle = 0;     // index into the triangles as given to build()
  float u = 0.0f, v = 0.0f;  // barycentric coordinates of the hit (b and c's weights)
};

class Bvh {
 public:
  static constexpr int kBins = 12;
  static constexpr int kMaxDepth = 48;  // traversal stacks are sized by this (GLSL arrays are fixed)

  Bvh() = default;
  // At most `leafSize` triangles per leaf unless they cannot be told apart (identical centroids).
  explicit Bvh(std::vector<BvhTriangle> triangles, int leafSize = 4);

  // Closest hit of origin + t dir with t in (tMin, tMax); dir need not be unit.
  std::optional<BvhHit> closestHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const;
  // Whether anything is hit for t in (tMin, tMax): the shadow ray's question, stopping at the first.
  bool anyHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const;

  const std::vector<BvhNode>& nodes() const { return nodes_; }
  // The triangles in leaf order, and for each its index in the list given to the constructor.
  const std::vector<BvhTriangle>& triangles() const { return triangles_; }
  const std::vector<uint32_t>& originalIndex() const { return originalIndex_; }
  int depth() const { return depth_; }

  // For a shader, a stackless walk: the nodes in depth-first order, two texels each, (min, first
  // triangle) and (max, skip | count << 24), ints as float bits. A ray that enters a node's box goes
  // on to the next node (an inner node's first child) after testing the node's `count` triangles; a
  // ray that misses it, or has tested them, goes to `skip`, the node after its subtree; the walk ends
  // at the node count. Leaves of more than 255 triangles become runs of leaves. Triangles: three
  // texels each (a, b, c; w = the original index as float bits).
  std::vector<glm::vec4> nodeTexels() const;
  std::vector<glm::vec4> triangleTexels() const;

 private:
  void buildNode(uint32_t index, uint32_t first, uint32_t count, int leafSize, int depth,
                 const std::vector<glm::vec3>& centroids);
  void appendThreaded(uint32_t index, std::vector<glm::vec4>& out) const;

  std::vector<BvhNode> nodes_;
  std::vector<BvhTriangle> triangles_;
  std::vector<uint32_t> originalIndex_;
  int depth_ = 0;
};

// Möller and Trumbore 1997: t and the barycentric (u, v) of the ray's crossing with the triangle,
// or nothing when it misses or runs parallel. Shared by the traversal and the brute-force check.
std::optional<BvhHit> intersectTriangle(const BvhTriangle& tri, const glm::vec3& origin, const glm::vec3& dir);

}  // namespace shadelab
