// The BVH a GPU truth traces: every triangle in exactly one leaf, every box holding what is under
// it, a depth the shader's stack can hold, and the same first hit as testing every triangle, on
// random soups, on a mesh of one huge and many tiny triangles, and on degenerate input.
#include <gtest/gtest.h>

#include <random>

#include "app/measure/bvh.h"
#include "app/scene/scene_catalog.h"
#include "labs/shadows/gpu_tracer.h"
#include "labs/shadows/ray_visibility.h"

using namespace shadelab;

namespace {

std::vector<BvhTriangle> randomSoup(size_t n, unsigned seed, float size) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-1.0f, 1.0f), off(-size, size);
  std::vector<BvhTriangle> out;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 c(pos(rng), pos(rng), pos(rng));
    out.push_back({c + glm::vec3(off(rng), off(rng), off(rng)), c + glm::vec3(off(rng), off(rng), off(rng)),
                   c + glm::vec3(off(rng), off(rng), off(rng))});
  }
  return out;
}

std::optional<BvhHit> bruteForce(const std::vector<BvhTriangle>& tris, glm::vec3 o, glm::vec3 d, float tMin,
                                 float tMax) {
  std::optional<BvhHit> best;
  for (uint32_t i = 0; i < tris.size(); ++i) {
    auto hit = intersectTriangle(tris[i], o, d);
    if (hit && hit->t > tMin && hit->t < tMax) {
      tMax = hit->t;
      best = *hit;
      best->triangle = i;
    }
  }
  return best;
}

bool contains(const BvhNode& n, glm::vec3 p) {
  return glm::all(glm::lessThanEqual(n.min, p)) && glm::all(glm::lessThanEqual(p, n.max));
}

// The structure: each triangle in one leaf, boxes holding their triangles and children.
void checkStructure(const Bvh& bvh, size_t triangles) {
  std::vector<int> seen(triangles, 0);
  const auto& nodes = bvh.nodes();
  for (const BvhNode& n : nodes) {
    if (n.count > 0) {
      for (uint32_t i = n.first; i < n.first + n.count; ++i) {
        ++seen.at(bvh.originalIndex().at(i));
        const BvhTriangle& t = bvh.triangles()[i];
        EXPECT_TRUE(contains(n, t.a) && contains(n, t.b) && contains(n, t.c));
      }
    } else {
      for (uint32_t c : {n.first, n.first + 1}) {
        ASSERT_LT(c, nodes.size());
        EXPECT_TRUE(contains(n, nodes[c].min) && contains(n, nodes[c].max));
      }
    }
  }
  for (size_t i = 0; i < triangles; ++i) EXPECT_EQ(seen[i], 1) << "triangle " << i;
  EXPECT_LE(bvh.depth(), Bvh::kMaxDepth);
}

void checkAgainstBruteForce(const std::vector<BvhTriangle>& tris, const Bvh& bvh, unsigned seed, int rays) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  int hits = 0;
  for (int r = 0; r < rays; ++r) {
    const glm::vec3 o(u(rng), u(rng), u(rng)), d = glm::vec3(u(rng), u(rng), u(rng)) - o;
    const auto want = bruteForce(tris, o, d, 1e-4f, 1.0f), got = bvh.closestHit(o, d, 1e-4f, 1.0f);
    ASSERT_EQ(bool(want), bool(got)) << "ray " << r;
    EXPECT_EQ(bvh.anyHit(o, d, 1e-4f, 1.0f), bool(want)) << "ray " << r;
    if (!want) continue;
    ++hits;
    EXPECT_EQ(got->t, want->t) << "ray " << r;  // the same test on the same triangle: the same float
    if (got->triangle != want->triangle) EXPECT_EQ(got->t, want->t) << "a tie between two triangles at one distance";
  }
  EXPECT_GT(hits, rays / 10) << "the test needs rays that hit";
}

}  // namespace

TEST(Bvh, EveryTriangleIsInOneLeafAndTheBoxesHoldTheirContents) {
  const auto tris = randomSoup(5000, 1, 0.05f);
  const Bvh bvh(tris);
  checkStructure(bvh, tris.size());
  EXPECT_LT(bvh.nodes().size(), 2 * tris.size());
  size_t leaves = 0, inLeaves = 0;
  for (auto& n : bvh.nodes())
    if (n.count > 0) ++leaves, inLeaves += n.count;
  EXPECT_LE(double(inLeaves) / double(leaves), 4.0);
}

TEST(Bvh, FindsTheSameFirstHitAsTestingEveryTriangle) {
  const auto tris = randomSoup(2000, 2, 0.1f);
  checkAgainstBruteForce(tris, Bvh(tris), 3, 4000);
}

// One triangle spanning the scene over a thousand tiny ones, coplanar sheets and zero-area
// triangles: the split heuristic's hard cases.
TEST(Bvh, OneHugeAndManyTinyTrianglesAndDegenerateOnes) {
  auto tris = randomSoup(1000, 4, 0.002f);
  tris.push_back({{-10, -10, 0.01f}, {10, -10, 0.01f}, {0, 10, 0.01f}});
  for (int i = 0; i < 50; ++i)
    tris.push_back({{-1, -1, 0.3f}, {1, -1, 0.3f}, {-1, 1, 0.3f}});              // the same triangle 50 times
  tris.push_back({{0.2f, 0.2f, 0.2f}, {0.2f, 0.2f, 0.2f}, {0.2f, 0.2f, 0.2f}});  // a point
  tris.push_back({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});                             // a line
  const Bvh bvh(tris);
  checkStructure(bvh, tris.size());
  checkAgainstBruteForce(tris, bvh, 5, 3000);
}

namespace {

// The shader's walk (shaders/shadows/trace.frag's blockedRays()) over the texels, step for step:
// the rays from one origin walked together; bit k of the result is set when ray k is blocked.
uint32_t walkTexels(const std::vector<glm::vec4>& nodes, const std::vector<glm::vec4>& triangles, glm::vec3 o,
                    const std::vector<glm::vec3>& dirs, float tMin, float tMax, int* visits) {
  const uint32_t count = uint32_t(nodes.size() / 2);
  uint32_t pending = (1u << dirs.size()) - 1u, blocked = 0;
  *visits = 0;
  for (uint32_t node = 0; node < count && pending != 0;) {
    ++*visits;
    const glm::vec4 lo = nodes[2 * node], hi = nodes[2 * node + 1];
    const uint32_t link = glm::floatBitsToUint(hi.w), skip = link & 0xFFFFFFu, n = link >> 24;
    EXPECT_GT(skip, node) << "indices only grow";
    uint32_t entering = 0;
    for (size_t k = 0; k < dirs.size(); ++k) {
      const glm::vec3 invDir = 1.0f / dirs[k];
      const glm::vec3 t0 = (glm::vec3(lo) - o) * invDir, t1 = (glm::vec3(hi) - o) * invDir;
      const glm::vec3 nearT = glm::min(t0, t1), farT = glm::max(t0, t1);
      const float enter = std::max(std::max(nearT.x, nearT.y), std::max(nearT.z, 0.0f));
      const float exit = std::min(std::min(farT.x, farT.y), std::min(farT.z, tMax));
      if ((pending >> k & 1u) && enter <= exit) entering |= 1u << k;
    }
    if (entering == 0) {
      node = skip;
      continue;
    }
    if (n == 0) {
      ++node;
      continue;
    }
    for (uint32_t i = glm::floatBitsToUint(lo.w); i < glm::floatBitsToUint(lo.w) + n; ++i) {
      const BvhTriangle t{glm::vec3(triangles[3 * i]), glm::vec3(triangles[3 * i + 1]),
                          glm::vec3(triangles[3 * i + 2])};
      for (size_t k = 0; k < dirs.size(); ++k) {
        if (!(entering >> k & 1u)) continue;
        const auto hit = intersectTriangle(t, o, dirs[k]);
        if (hit && hit->t > tMin && hit->t < tMax) blocked |= 1u << k, entering &= ~(1u << k);
      }
    }
    pending &= ~blocked;
    node = skip;
  }
  return blocked;
}

}  // namespace

// The texels a shader walks without a stack: every triangle reachable, the same answer as testing
// every triangle on random rays, fewer node visits than the tree has, and a leaf of more than 255
// triangles (identical ones) split into a run of leaves the 8-bit count can hold.
TEST(Bvh, TexelsCarryTheTreeForAStacklessWalk) {
  auto tris = randomSoup(2000, 6, 0.1f);
  for (int i = 0; i < 300; ++i) tris.push_back({{-1, -1, 0.3f}, {1, -1, 0.3f}, {-1, 1, 0.3f}});
  const Bvh bvh(tris);
  const auto nodes = bvh.nodeTexels(), triangles = bvh.triangleTexels();
  ASSERT_GE(nodes.size(), 2 * bvh.nodes().size()) << "every node, and runs for the big leaf";
  ASSERT_EQ(triangles.size(), 3 * tris.size());
  std::vector<int> seen(tris.size(), 0);
  for (size_t k = 0; k < nodes.size(); k += 2) {
    const uint32_t link = glm::floatBitsToUint(nodes[k + 1].w), n = link >> 24;
    for (uint32_t i = glm::floatBitsToUint(nodes[k].w); n > 0 && i < glm::floatBitsToUint(nodes[k].w) + n; ++i)
      ++seen.at(glm::floatBitsToUint(triangles[3 * i].w));
  }
  for (size_t i = 0; i < tris.size(); ++i) ASSERT_EQ(seen[i], 1) << "triangle " << i;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  int hits = 0;
  double visits = 0, packetVisits = 0, apartVisits = 0;
  for (int r = 0; r < 3000; ++r) {
    const glm::vec3 o(u(rng), u(rng), u(rng)), d = glm::vec3(u(rng), u(rng), u(rng)) - o;
    int v = 0;
    const bool want = bool(bruteForce(tris, o, d, 1e-4f, 1.0f));
    ASSERT_EQ(walkTexels(nodes, triangles, o, {d}, 1e-4f, 1.0f, &v), want ? 1u : 0u) << "ray " << r;
    hits += want;
    visits += v;
    // Nine rays from the same origin to points of a small disk around the target, as a pixel's
    // pass traces them: each one's answer is its own walk's, for fewer node visits than nine walks.
    std::vector<glm::vec3> dirs;
    uint32_t wantBits = 0;
    int apart = 0;
    for (int k = 0; k < 9; ++k) {
      const glm::vec3 dk = d + 0.05f * glm::vec3(u(rng), u(rng), u(rng));
      if (bruteForce(tris, o, dk, 1e-4f, 1.0f)) wantBits |= 1u << k;
      dirs.push_back(dk);
      walkTexels(nodes, triangles, o, {dk}, 1e-4f, 1.0f, &v);
      apart += v;
    }
    ASSERT_EQ(walkTexels(nodes, triangles, o, dirs, 1e-4f, 1.0f, &v), wantBits) << "rays from origin " << r;
    packetVisits += v;
    apartVisits += apart;
  }
  EXPECT_GT(hits, 300) << "the test needs rays that hit";
  EXPECT_LT(visits / 3000.0, 0.2 * double(nodes.size() / 2)) << "the walk skips what a ray misses";
  EXPECT_LT(packetVisits, 0.5 * apartVisits) << "rays walked together share their nodes";
  EXPECT_TRUE(Bvh(std::vector<BvhTriangle>{}).nodeTexels().empty()) << "an empty scene: a walk that ends at once";
  EXPECT_FALSE(Bvh(std::vector<BvhTriangle>{}).anyHit({0, 0, 0}, {1, 0, 0}, 0.0f, 1.0f))
      << "an empty scene hits nothing";
}

// Against Embree on the shadows lab's own scene: shadow rays from points over the scene towards
// a light above it agree but for rays that graze an edge (the two round the hit test differently).
TEST(Bvh, AgreesWithEmbreeOnTheShadowScene) {
  Scene scene;
  ASSERT_EQ(buildScene("shadow-test", {}, scene), "");
  const Bvh bvh(sceneTriangles(scene));
  const RayScene embree(scene);
  const Bounds b = scene.computeBounds();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const glm::vec3 light = b.center() + glm::vec3(0.3f, 2.0f, 0.2f) * b.radius();
  int differ = 0, blocked = 0;
  const int rays = 20000;
  for (int r = 0; r < rays; ++r) {
    const glm::vec3 p = glm::mix(b.min, b.max, glm::vec3(u(rng), u(rng), u(rng)));
    const glm::vec3 d = light - p;
    const bool a = bvh.anyHit(p, d, 0.0f, 1.0f), e = embree.occluded(p, d, 1.0f);  // Embree: t in [0, 1]
    differ += a != e;
    blocked += e;
  }
  EXPECT_GT(blocked, rays / 20) << "the test needs rays that are blocked";
  RecordProperty("disagree", differ);
  EXPECT_LE(differ, rays * 5 / 10000) << differ << " of " << rays << " shadow rays disagree";
}
