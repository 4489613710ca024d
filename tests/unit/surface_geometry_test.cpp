// The surface lab's geometry without GL: midpoint subdivision shares its midpoints (no cracks) and
// keeps the surface, the world size of a UV unit, the subdivision level for a texel size, and the
// UV shear that separates generated from screen-space tangents.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "app/scene/mesh_topology.h"
#include "app/scene/procedural.h"
#include "labs/surface/brick_textures.h"
#include "labs/surface/subdivide.h"
#include "labs/surface/surface_scenes.h"

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

// Tessellation done on the CPU (no tessellation stages): parts^2 triangles per triangle, shared edge
// points (the sphere stays closed, and on its own the mesh has no vertex twice), UVs linear, the
// winding kept, normals unit length.
TEST(SurfaceGeometry, SplitEdgesIsATessellatorsGridWithoutCracks) {
  const MeshData sphere = makeUvSphere(1.0f, 12);
  for (int parts : {2, 3, 7}) {
    const MeshData fine = splitEdges(sphere, parts);
    EXPECT_EQ(fine.triangleCount(), sphere.triangleCount() * size_t(parts * parts));
    const WeldedMesh welded = weldByPosition(fine);
    EXPECT_EQ(buildAdjacency(welded.vertexCount(), welded.indices).boundaryEdges, 0u) << parts;
    for (const glm::vec3& n : fine.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    for (const glm::vec3& p : fine.positions) EXPECT_LE(glm::length(p), 1.0f + 1e-5f);
  }
  const MeshData tri = triangle({0, 0}, {1, 0}, {0, 1});
  const MeshData fine = splitEdges(tri, 5);
  EXPECT_EQ(fine.positions.size(), 21u);  // (5 + 1)(5 + 2) / 2 grid points, none twice
  double area = 0;
  for (size_t t = 0; t < fine.indices.size(); t += 3) {
    const glm::vec3 a = fine.positions[fine.indices[t]], b = fine.positions[fine.indices[t + 1]],
                    c = fine.positions[fine.indices[t + 2]];
    const float z = glm::cross(b - a, c - a).z;
    EXPECT_GT(z, 0.0f) << "triangle " << t / 3 << " turned over";
    area += 0.5 * z;
  }
  EXPECT_NEAR(area, 0.5, 1e-6);
  for (size_t v = 0; v < fine.positions.size(); ++v) {
    EXPECT_NEAR(fine.uvs[v].x, fine.positions[v].x, 1e-6f);
    EXPECT_NEAR(fine.uvs[v].y, fine.positions[v].y, 1e-6f);
  }
  EXPECT_EQ(splitEdges(tri, 1).indices, tri.indices);
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
  EXPECT_EQ(levelsForTexelSize(wall, 64, 20), 8);  // 2.28 / 2^8 = 0.0089 <= 1/64
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

namespace {

// How a normal map's normals agree with the slopes of a height field, per axis, in the frame the
// shaders read them in (the upload flips rows: +u right, +v up the image; an OpenGL-convention map
// has its green along +v). Positive: the normals lean against the slopes, as a surface's do.
glm::dvec2 normalsAgainstSlopes(const ImageSource& normal, bool greenDown, const ImageSource& height, bool depth) {
  std::vector<unsigned char> n, h;
  glm::ivec2 ns, hs;
  EXPECT_EQ(decodeImage(normal, n, ns), "");
  EXPECT_EQ(decodeImage(height, h, hs), "");
  if (n.empty() || h.empty()) return glm::dvec2(0.0);
  auto heightAt = [&](int x, int y) {  // rows top-down; wraps like the sampler
    x = ((x % hs.x) + hs.x) % hs.x, y = ((y % hs.y) + hs.y) % hs.y;
    const double v = h[4 * (size_t(y) * size_t(hs.x) + size_t(x))] / 255.0;
    return depth ? 1.0 - v : v;
  };
  glm::dvec2 sum(0.0);
  for (int y = 0; y < ns.y; ++y)
    for (int x = 0; x < ns.x; ++x) {
      const int hx = x * hs.x / ns.x, hy = y * hs.y / ns.y;
      const double dhdu = heightAt(hx + 1, hy) - heightAt(hx - 1, hy);
      const double dhdv = heightAt(hx, hy - 1) - heightAt(hx, hy + 1);  // +v runs up the image
      const unsigned char* p = &n[4 * (size_t(y) * size_t(ns.x) + size_t(x))];
      const double nx = p[0] / 127.5 - 1.0, ny = (greenDown ? -1.0 : 1.0) * (p[1] / 127.5 - 1.0);
      sum += glm::dvec2(-dhdu * nx, -dhdv * ny);
    }
  return sum;
}

}  // namespace

// A normal map and the height field of the same material describe one surface: read with the
// material's convention, the map's normals lean against the field's slopes along both axes. The
// lab's own bricks are OpenGL's +Y; LearnOpenGL's bricks2 is DirectX's Y- (its green points down
// the image), which its material says, so green = opengl is right on every scene.
TEST(NormalMaps, TheLabsBricksLeanAgainstTheirOwnHeightField) {
  const BrickTextures bricks = makeBrickTextures(256, 0.04f);
  const glm::dvec2 own = normalsAgainstSlopes(bricks.normal, false, bricks.height, false);
  EXPECT_GT(own.x, 0.0);
  EXPECT_GT(own.y, 0.0);
  EXPECT_LT(normalsAgainstSlopes(bricks.normal, true, bricks.height, false).y, 0.0);
}

TEST(NormalMaps, LearnOpenGLsBricksLeanAgainstTheirOwnHeightFieldReadAsTheirMaterialSays) {
  // LearnOpenGL's bricks2 is listed only where ../shared/data holds it.
  const auto recipes = surfaceScenes();
  const auto recipe =
      std::find_if(recipes.begin(), recipes.end(), [](auto& r) { return r.id == "bricks-learnopengl"; });
  if (recipe == recipes.end()) GTEST_SKIP() << "bricks-learnopengl needs ../shared/data";
  Scene s;
  ASSERT_EQ(recipe->build(s, {}), "");
  const auto bricks2 =
      std::find_if(s.materials.begin(), s.materials.end(), [](auto& m) { return m.name == "bricks2"; });
  ASSERT_NE(bricks2, s.materials.end());
  const Material& m = *bricks2;
  const ImageSource &normal = s.images.at(size_t(m.normalImage)), &height = s.images.at(size_t(m.heightImage));
  const glm::dvec2 learnopengl = normalsAgainstSlopes(normal, m.normalGreenDown, height, m.heightIsDepth);
  EXPECT_GT(learnopengl.x, 0.0);
  EXPECT_GT(learnopengl.y, 0.0);
  EXPECT_LT(normalsAgainstSlopes(normal, !m.normalGreenDown, height, m.heightIsDepth).y, 0.0)
      << "the other convention must disagree, or the test tells nothing";
}
