#include "app/measure/bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab {
namespace {

struct Box {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};
  void grow(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void grow(const Box& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  bool empty() const { return !(min.x <= max.x); }
  float area() const {
    if (empty()) return 0.0f;
    const glm::vec3 e = max - min;
    return e.x * e.y + e.y * e.z + e.z * e.x;  // half the surface: only ratios matter
  }
};

Box boxOf(const BvhTriangle& t) {
  Box b;
  b.grow(t.a);
  b.grow(t.b);
  b.grow(t.c);
  return b;
}

// Slab test: the entry distance, or infinity when the ray misses the box within (tMin, tMax).
float enterBox(const BvhNode& n, const glm::vec3& origin, const glm::vec3& invDir, float tMin, float tMax) {
  const glm::vec3 t0 = (n.min - origin) * invDir, t1 = (n.max - origin) * invDir;
  const glm::vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
  // fmax/fmin drop a NaN (0 * inf, a ray in a slab's plane) in favour of the other operand.
  const float enter = std::fmax(std::fmax(lo.x, lo.y), std::fmax(lo.z, tMin));
  const float exit = std::fmin(std::fmin(hi.x, hi.y), std::fmin(hi.z, tMax));
  return enter <= exit ? enter : std::numeric_limits<float>::infinity();
}

// The bin of a centroid coordinate along an axis whose centroids span [lo, lo + extent]; a
// coordinate that is not a number goes to bin 0 rather than through an undefined conversion.
int binOf(float x, float lo, float extent) {
  const float f = (x - lo) / extent * float(Bvh::kBins);
  return f >= 0.0f ? std::min(Bvh::kBins - 1, int(std::min(f, float(Bvh::kBins)))) : 0;
}

}  // namespace

std::optional<BvhHit> intersectTriangle(const BvhTriangle& tri, const glm::vec3& origin, const glm::vec3& dir) {
  const glm::vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
  const glm::vec3 p = glm::cross(dir, e2);
  const float det = glm::dot(e1, p);
  if (!(std::abs(det) > 1e-30f)) return std::nullopt;  // parallel, degenerate or NaN
  const float inv = 1.0f / det;
  const glm::vec3 s = origin - tri.a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return std::nullopt;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(dir, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return std::nullopt;
  return BvhHit{glm::dot(e2, q) * inv, 0, u, v};
}

Bvh::Bvh(std::vector<BvhTriangle> triangles, int leafSize) {
  const uint32_t n = uint32_t(triangles.size());
  if (n == 0) return;
  std::vector<glm::vec3> centroids(n);
  for (uint32_t i = 0; i < n; ++i) centroids[i] = (triangles[i].a + triangles[i].b + triangles[i].c) / 3.0f;
  triangles_ = std::move(triangles);
  originalIndex_.resize(n);
  for (uint32_t i = 0; i < n; ++i) originalIndex_[i] = i;
  nodes_.reserve(2 * size_t(n));
  nodes_.emplace_back();
  buildNode(0, 0, n, std::max(leafSize, 1), 1, centroids);
  // Triangles in leaf order: the leaves name ranges of this list.
  std::vector<BvhTriangle> ordered(n);
  for (uint32_t i = 0; i < n; ++i) ordered[i] = triangles_[originalIndex_[i]];
  triangles_ = std::move(ordered);
}

// Fills nodes_[index] for the triangles originalIndex_[first, first + count), and its subtree.
void Bvh::buildNode(uint32_t index, uint32_t first, uint32_t count, int leafSize, int depth,
                    const std::vector<glm::vec3>& centroids) {
  depth_ = std::max(depth_, depth);
  Box bounds, centre;
  for (uint32_t i = first; i < first + count; ++i) {
    bounds.grow(boxOf(triangles_[originalIndex_[i]]));
    centre.grow(centroids[originalIndex_[i]]);
  }
  auto makeLeaf = [&] { nodes_[index] = {bounds.min, first, bounds.max, count}; };
  if (count <= uint32_t(leafSize) || depth >= kMaxDepth) return makeLeaf();  // depth bounds the shader's stack

  // The cheapest binned split over the three axes: cost = area(left) n(left) + area(right) n(right).
  int bestAxis = -1, bestBin = 0;
  float bestCost = std::numeric_limits<float>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const float lo = centre.min[axis], extent = centre.max[axis] - lo;
    if (!(extent > 0.0f)) continue;
    Box binBox[kBins];
    uint32_t binCount[kBins] = {};
    for (uint32_t i = first; i < first + count; ++i) {
      const uint32_t t = originalIndex_[i];
      const int b = binOf(centroids[t][axis], lo, extent);
      ++binCount[b];
      binBox[b].grow(boxOf(triangles_[t]));
    }
    float rightArea[kBins];
    uint32_t rightCount[kBins];
    Box right;
    uint32_t rn = 0;
    for (int b = kBins - 1; b > 0; --b) {
      right.grow(binBox[b]);
      rn += binCount[b];
      rightArea[b] = right.area();
      rightCount[b] = rn;
    }
    Box left;
    uint32_t ln = 0;
    for (int b = 0; b < kBins - 1; ++b) {  // split between bin b and b + 1
      left.grow(binBox[b]);
      ln += binCount[b];
      if (ln == 0 || rightCount[b + 1] == 0) continue;
      const float cost = left.area() * float(ln) + rightArea[b + 1] * float(rightCount[b + 1]);
      if (cost < bestCost) {
        bestCost = cost;
        bestAxis = axis;
        bestBin = b;
      }
    }
  }
  if (bestAxis < 0) return makeLeaf();  // every centroid the same point: nothing tells them apart

  const float lo = centre.min[bestAxis], extent = centre.max[bestAxis] - lo;
  auto* begin = originalIndex_.data() + first;
  auto* middle = std::partition(begin, begin + count,
                                [&](uint32_t t) { return binOf(centroids[t][bestAxis], lo, extent) <= bestBin; });
  const uint32_t leftCount = uint32_t(middle - begin);
  const uint32_t children = uint32_t(nodes_.size());
  nodes_[index] = {bounds.min, children, bounds.max, 0};
  nodes_.emplace_back();
  nodes_.emplace_back();
  buildNode(children, first, leftCount, leafSize, depth + 1, centroids);
  buildNode(children + 1, first + leftCount, count - leftCount, leafSize, depth + 1, centroids);
}

std::optional<BvhHit> Bvh::closestHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const {
  if (nodes_.empty()) return std::nullopt;
  const glm::vec3 invDir = 1.0f / dir;
  std::optional<BvhHit> best;
  uint32_t stack[kMaxDepth + 1];
  int top = 0;
  if (enterBox(nodes_[0], origin, invDir, tMin, tMax) < std::numeric_limits<float>::infinity()) stack[top++] = 0;
  while (top > 0) {
    const BvhNode& node = nodes_[stack[--top]];
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const auto hit = intersectTriangle(triangles_[i], origin, dir);
        if (hit && hit->t > tMin && hit->t < tMax) {
          tMax = hit->t;
          best = *hit;
          best->triangle = originalIndex_[i];
        }
      }
      continue;
    }
    // Nearer child last on the stack, so it is visited first; either only while it can beat tMax.
    const uint32_t a = node.first, b = node.first + 1;
    const float ta = enterBox(nodes_[a], origin, invDir, tMin, tMax),
                tb = enterBox(nodes_[b], origin, invDir, tMin, tMax);
    const bool aFirst = ta <= tb;
    const uint32_t nearer = aFirst ? a : b, farther = aFirst ? b : a;
    const float tNear = aFirst ? ta : tb, tFar = aFirst ? tb : ta;
    if (tFar < std::numeric_limits<float>::infinity()) stack[top++] = farther;
    if (tNear < std::numeric_limits<float>::infinity()) stack[top++] = nearer;
  }
  return best;
}

bool Bvh::anyHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const {
  if (nodes_.empty()) return false;
  const glm::vec3 invDir = 1.0f / dir;
  uint32_t stack[kMaxDepth + 1];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& node = nodes_[stack[--top]];
    if (enterBox(node, origin, invDir, tMin, tMax) == std::numeric_limits<float>::infinity()) continue;
    if (node.count == 0) {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const auto hit = intersectTriangle(triangles_[i], origin, dir);
      if (hit && hit->t > tMin && hit->t < tMax) return true;
    }
  }
  return false;
}

void Bvh::appendThreaded(uint32_t index, std::vector<glm::vec4>& out) const {
  const BvhNode& node = nodes_[index];
  auto here = [&] { return uint32_t(out.size() / 2); };
  if (node.count > 0) {  // a leaf's skip is the next node, whatever follows its subtree
    for (uint32_t first = node.first; first < node.first + node.count; first += 255) {
      const uint32_t count = std::min(255u, node.first + node.count - first);
      out.emplace_back(node.min, glm::uintBitsToFloat(first));
      out.emplace_back(node.max, glm::uintBitsToFloat((here() + 1) | (count << 24)));
    }
    return;
  }
  const size_t at = out.size();
  out.emplace_back(node.min, 0.0f);
  out.emplace_back(node.max, 0.0f);
  appendThreaded(node.first, out);
  appendThreaded(node.first + 1, out);
  out[at + 1].w = glm::uintBitsToFloat(here());  // count 0: an inner node
}

std::vector<glm::vec4> Bvh::nodeTexels() const {
  // 24 bits of node index: 16 M nodes, far above the 2.5 M triangles a scene may have.
  std::vector<glm::vec4> out;
  out.reserve(2 * nodes_.size());
  if (!nodes_.empty()) appendThreaded(0, out);
  return out;
}

std::vector<glm::vec4> Bvh::triangleTexels() const {
  std::vector<glm::vec4> out;
  out.reserve(3 * triangles_.size());
  for (size_t i = 0; i < triangles_.size(); ++i) {
    out.emplace_back(triangles_[i].a, glm::uintBitsToFloat(originalIndex_[i]));
    out.emplace_back(triangles_[i].b, 0.0f);
    out.emplace_back(triangles_[i].c, 0.0f);
  }
  return out;
}

}  // namespace shadelab
