// Welding, adjacency and vertex normals: the surface behind split render vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "app/scene/mesh_topology.h"
#include "app/scene/procedural.h"

using namespace shadelab;

TEST(Topology, WeldingJoinsCopiesOfAPositionAcrossAUvSeam) {
  // Two triangles of a quad whose shared edge is a UV seam: the edge's vertices exist twice.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<uint32_t> idx = {0, 1, 2, 3, 4, 5};
  const WeldedMesh w = weldByPosition(p, idx);
  EXPECT_EQ(w.vertexCount(), 4u);
  EXPECT_EQ(w.logicalOf, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(w.indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  const Adjacency a = buildAdjacency(w.vertexCount(), w.indices);
  EXPECT_EQ(a.boundaryEdges, 4u) << "welded, the seam edge is interior";
  const Adjacency split = buildAdjacency(p.size(), idx);
  EXPECT_EQ(split.boundaryEdges, 6u) << "unwelded, the seam is two boundaries";
}

TEST(Topology, MinusZeroAndPlusZeroAreOnePosition) {
  const std::vector<glm::vec3> p = {{0.0f, 1, 2}, {-0.0f, 1, 2}};
  EXPECT_EQ(weldByPosition(p, std::vector<uint32_t>{}).vertexCount(), 1u);
}

TEST(Topology, GridInteriorHasSixNeighboursAndBoundaryIsMarked) {
  const MeshData plane = makePlane(2.0f, 4, 1.0f);  // 5 x 5 vertices, each quad split once
  const WeldedMesh w = weldByPosition(plane);
  const Adjacency a = buildAdjacency(w.vertexCount(), w.indices);
  const uint32_t centre = 12;  // (2, 2)
  EXPECT_EQ(a.degree(centre), 6u);
  EXPECT_FALSE(a.boundary[centre]);
  EXPECT_TRUE(a.boundary[0]);
  EXPECT_EQ(a.boundaryEdges, 16u);
  EXPECT_EQ(a.nonManifoldEdges, 0u);
  for (uint32_t n : a.neighbours(centre))
    EXPECT_LE(glm::length(w.positions[n] - w.positions[centre]), 0.5f * std::sqrt(2.0f) + 1e-6f);
}

TEST(Topology, NonManifoldEdgesAndIsolatedVerticesAreCounted) {
  // Three triangles on the edge (0, 1), and vertex 5 in none.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {9, 9, 9}};
  const std::vector<uint32_t> idx = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  const Adjacency a = buildAdjacency(p.size(), idx);
  EXPECT_EQ(a.nonManifoldEdges, 1u);
  EXPECT_EQ(a.isolatedVertices, 1u);
  EXPECT_EQ(a.degree(5), 0u);
}

TEST(Topology, AngleWeightedNormalsIgnoreHowAFaceIsTriangulated) {
  // The corner (0,0,0) of a cube with three faces. The z = 0 face is one triangle, or the whole
  // square cut along its diagonal from the corner: angle weighting must not care, area weighting does.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  const std::vector<uint32_t> oneTri = {0, 2, 1, 0, 1, 3, 0, 3, 2};
  const std::vector<uint32_t> twoTris = {0, 2, 4, 0, 4, 1, 0, 1, 3, 0, 3, 2};
  const glm::vec3 expected = -glm::normalize(glm::vec3(1, 1, 1));
  for (const auto* idx : {&oneTri, &twoTris}) {
    const auto n = vertexNormals(p, *idx, NormalWeighting::Angle);
    EXPECT_NEAR(glm::length(n[0] - expected), 0.0f, 1e-5f);
  }
  const auto a1 = vertexNormals(p, oneTri, NormalWeighting::Area),
             a2 = vertexNormals(p, twoTris, NormalWeighting::Area);
  EXPECT_GT(glm::length(a1[0] - a2[0]), 0.05f);
}

TEST(Topology, DegenerateFacesGiveZeroFaceNormalsAndFiniteVertexNormals) {
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 0}};
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 3, 1};  // collinear, then two coincident corners
  for (auto& n : faceNormals(p, idx)) EXPECT_EQ(n, glm::vec3(0.0f));
  for (auto w : {NormalWeighting::Area, NormalWeighting::Angle})
    for (auto& n : vertexNormals(p, idx, w)) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(Topology, StatisticsOfASeamedMesh) {
  MeshData sphere = makeUvSphere(1.0f, 8);  // a UV seam meridian and two poles of copies
  const WeldedMesh w = weldByPosition(sphere);
  const Adjacency a = buildAdjacency(w.vertexCount(), w.indices);
  const MeshStatistics s = meshStatistics(sphere, w, a);
  EXPECT_EQ(s.renderVertices, 9u * 5u);
  EXPECT_EQ(s.logicalVertices, 8u * 3u + 2u);
  EXPECT_EQ(s.seamVertices, 3u + 2u);
  EXPECT_EQ(s.boundaryEdges, 0u) << "welded, the sphere is closed";
  EXPECT_GT(s.zeroAreaFaces, 0u) << "the pole rows are triangles with two coincident corners";
  EXPECT_NEAR(meanEdgeLength(std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, std::vector<uint32_t>{0, 1, 2}),
              (2.0 + std::sqrt(2.0)) / 3.0, 1e-6);
}
