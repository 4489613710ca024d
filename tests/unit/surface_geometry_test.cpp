// The surface lab's geometry without GL: midpoint subdivision shares its midpoints (no cracks) and
// keeps the surface, the world size of a UV unit, the subdivision level for a texel size, and the
// UV shear that separates generated from screen-space tangents.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "labs/surface/subdivide.h"
#include "scene/mesh_topology.h"
#include "scene/procedural.h"

using namespace shadelab;

namespace {

MeshData triangle(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2) {
  MeshData m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals.assign(3, glm::vec3(0, 0, 1));
  m.uvs = {uv0, uv1, uv2};
  m.indices = {0, 1, 2};
  return m;
}

}  // namespace

TEST(SurfaceGeometry, SubdivisionSharesMidpointsSoAClosedMeshStaysClosed) {
  // The UV sphere has a seam (vertices repeated with other UVs); welded by position it is closed.
  const MeshData sphere = makeUvSphere(1.0f, 12);
  const WeldedMesh coarse = weldByPosition(sphere);
  EXPECT_EQ(buildAdjacency(coarse.vertexCount(), coarse.indices).boundaryEdges, 0u);
  const MeshData fine = subdivide(sphere, 2);
  EXPECT_EQ(fine.triangleCount(), sphere.triangleCount() * 16);
  const WeldedMesh welded = weldByPosition(fine);
  EXPECT_EQ(buildAdjacency(welded.vertexCount(), welded.indices).boundaryEdges, 0u)
      << "a midpoint not shared (or placed differently on the two sides of the seam) leaves a crack";
  // Every new vertex is the midpoint of an edge of the level before: on or inside the sphere.
  for (const glm::vec3& p : fine.positions) EXPECT_LE(glm::length(p), 1.0f + 1e-5f);
  for (const glm::vec3& n : fine.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

TEST(SurfaceGeometry, SubdivisionInterpolatesUvsLinearly) {
  const MeshData fine = subdivide(triangle({0, 0}, {1, 0}, {0, 1}), 3);
  ASSERT_EQ(fine.uvs.size(), fine.positions.size());
  for (size_t v = 0; v < fine.positions.size(); ++v) {  // on this triangle uv = (x, y) exactly
    EXPECT_NEAR(fine.uvs[v].x, fine.positions[v].x, 1e-6f);
    EXPECT_NEAR(fine.uvs[v].y, fine.positions[v].y, 1e-6f);
  }
}

TEST(SurfaceGeometry, UvScaleIsTheWorldLengthOfAUvUnit) {
  for (const glm::vec2 s : uvScale(makePlane(2.0f, 4, 2.0f))) {  // 2 m spanned by 2 UV units
    EXPECT_NEAR(s.x, 1.0f, 1e-5f);
    EXPECT_NEAR(s.y, 1.0f, 1e-5f);
  }
  for (const glm::vec2 s : uvScale(makePlane(3.0f, 1, 0.5f))) EXPECT_NEAR(s.x, 6.0f, 1e-4f);
}

TEST(SurfaceGeometry, LevelsBringEdgesDownToATexel) {
  const MeshData wall = makePlane(2.0f, 1, 2.0f);  // mean UV edge (2 + 2 + 2 sqrt 2) / 3 = 2.28
  EXPECT_EQ(levelsForTexelSize(wall, 64, 20), 8);   // 2.28 / 2^8 = 0.0089 <= 1/64
  EXPECT_EQ(levelsForTexelSize(wall, 512, 20), 11);
  EXPECT_EQ(levelsForTexelSize(wall, 512, 10), 10) << "capped";
  MeshData noUvs = wall;
  noUvs.uvs.clear();
  EXPECT_EQ(levelsForTexelSize(noUvs, 512, 10), 0);
}

TEST(SurfaceGeometry, UvShearIsTheAngleBetweenTangentAndGradient) {
  // uv = (x + a y, y): dp/du = (1, 0, 0), grad u = (1, a, 0): atan(a) apart.
  const float a = std::tan(glm::radians(30.0f));
  auto shear = uvShearDegrees(triangle({0, 0}, {1, 0}, {a, 1}));
  ASSERT_EQ(shear.size(), 1u);
  EXPECT_NEAR(shear[0], 30.0f, 1e-3f);
  shear = uvShearDegrees(triangle({0, 0}, {-1, 0}, {-a, 1}));  // mirrored: same shear, other handedness
  ASSERT_EQ(shear.size(), 1u);
  EXPECT_NEAR(shear[0], 30.0f, 1e-3f);
  shear = uvShearDegrees(triangle({0, 0}, {2, 0}, {0, 0.5f}));  // stretched but orthogonal: none
  ASSERT_EQ(shear.size(), 1u);
  EXPECT_NEAR(shear[0], 0.0f, 1e-3f);
  EXPECT_TRUE(uvShearDegrees(triangle({0, 0}, {1, 1}, {2, 2})).empty()) << "zero area in UV: skipped";
}
