// The denoising lab's CPU side: the published metric, the Laplacian's basic facts, stability and
// divergence, degenerate input, noise, the feature-preserving filter, and the bake.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "app/scene/loaders.h"
#include "app/scene/mesh_topology.h"
#include "app/scene/procedural.h"
#include "app/scene/scene_catalog.h"
#include "labs/denoise/bilateral_normal.h"
#include "labs/denoise/displacement_bake.h"
#include "labs/denoise/laplacian.h"
#include "labs/denoise/mesh_metrics.h"
#include "labs/denoise/mesh_noise.h"
#include "labs/denoise/mesh_pair.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

struct Welded {
  std::vector<glm::dvec3> p;
  std::vector<uint32_t> idx;
  Adjacency adj;
};

Welded weld(const MeshData& m) {
  const WeldedMesh w = weldByPosition(m);
  Welded out{{w.positions.begin(), w.positions.end()}, w.indices, buildAdjacency(w.vertexCount(), w.indices)};
  return out;
}

Welded loadWelded(const std::filesystem::path& file) {
  Scene s;
  EXPECT_EQ(loadObj(file, s), "") << file;
  return weld(s.meshes.at(0));
}

double meanRadius(const std::vector<glm::dvec3>& p) {
  double r = 0;
  for (auto& v : p) r += glm::length(v);
  return r / double(p.size());
}

}  // namespace

TEST(DenoiseMetric, ReproducesThePublishedAnglesOfTheNoisyInputs) {
  const std::filesystem::path data = dataDirectory() / "denoise" / "guided_zhang2015";
  if (!std::filesystem::is_directory(data)) GTEST_SKIP() << data << " is missing";
  // ../shared/data/PROVENANCE.md: the values of Zhang et al.'s code for the noisy inputs.
  const std::pair<const char*, double> published[] = {
      {"Block0.4", 33.719},           {"Fandisk0.3", 28.421}, {"Fandisk0.7", 48.867}, {"SharpSphere0.3", 33.007},
      {"Twelve0.5Impulsive", 28.854}, {"Nicolo0.2", 24.015},  {"Bunny0.2", 21.549}};
  for (auto& [model, angle] : published) {
    const Welded clean = loadWelded(data / model / "Original.obj"), noisy = loadWelded(data / model / "Noisy.obj");
    ASSERT_EQ(clean.idx, noisy.idx) << model << ": the pair must share its faces";
    EXPECT_NEAR(meanFaceNormalAngleDeg(noisy.p, clean.p, clean.idx), angle, 5e-4) << model;
  }
}

TEST(Laplacian, PlanarGridInteriorIsZero) {
  const Welded g = weld(makePlane(2.0f, 8, 1.0f));
  for (auto kind : {LaplacianWeights::Uniform, LaplacianWeights::Cotangent}) {
    const EdgeWeights w = edgeWeights(g.p, g.idx, g.adj, kind, true);
    const auto delta = umbrella(g.p, g.adj, w);
    for (size_t v = 0; v < g.p.size(); ++v)
      if (!g.adj.boundary[v]) EXPECT_LT(glm::length(delta[v]), 1e-12) << "vertex " << v;
  }
}

TEST(Laplacian, ImplicitShrinksASphereMonotonicallyAndStaysFiniteAtHugeLambda) {
  const Welded s = weld(makeUvSphere(1.0f, 32));
  const double limit = stabilityLimit(s.adj, edgeWeights(s.p, s.idx, s.adj, LaplacianWeights::Uniform, true));
  for (double lambda : {0.5, 1000.0 * limit, 1e6}) {
    SmoothingSettings set;
    set.method = SmoothingMethod::Implicit;
    set.lambda = lambda;
    double radius = meanRadius(s.p);
    std::vector<glm::dvec3> p = s.p;
    for (int it = 0; it < 5; ++it) {
      set.iterations = 1;
      const SmoothingResult r = smooth(p, s.idx, s.adj, set);
      ASSERT_EQ(r.error, "");
      for (auto& v : r.positions) ASSERT_TRUE(std::isfinite(v.x + v.y + v.z)) << "lambda " << lambda;
      const double next = meanRadius(r.positions);
      EXPECT_LT(next, radius) << "lambda " << lambda << ", iteration " << it;
      radius = next;
      p = r.positions;
    }
  }
}

TEST(Laplacian, ExplicitDivergenceIsDetectedBeyondTheStabilityLimit) {
  const Welded s = weld(makeUvSphere(1.0f, 24));
  const std::vector<glm::dvec3> noisy = addNoise(s.p, s.idx, {NoiseKind::Gaussian, 0.2, 0.1, 7});
  for (auto kind : {LaplacianWeights::Uniform, LaplacianWeights::Cotangent}) {
    const double limit = stabilityLimit(s.adj, edgeWeights(noisy, s.idx, s.adj, kind, true));
    EXPECT_GT(limit, 0.9) << "uniform weights are stable to about lambda = 1 and somewhat beyond";
    EXPECT_LT(limit, 2.0);
    SmoothingSettings set;
    set.weights = kind;
    set.alongNormal = false;
    set.iterations = 30;
    set.lambda = 0.5 * limit;
    const SmoothingResult calm = smooth(noisy, s.idx, s.adj, set);
    EXPECT_EQ(calm.grewAt, 0) << "below the limit the energy never grows";
    set.lambda = 1.5 * limit;
    const SmoothingResult wild = smooth(noisy, s.idx, s.adj, set);
    EXPECT_GT(wild.grewAt, 0) << "beyond the limit the energy must be seen growing";
    for (auto& v : wild.positions) ASSERT_TRUE(std::isfinite(v.x + v.y + v.z));
    set.lambda = 1e6;  // far beyond: stopped, never NaN
    const SmoothingResult exploded = smooth(noisy, s.idx, s.adj, set);
    EXPECT_GT(exploded.stoppedAt, 0);
    for (auto& v : exploded.positions) ASSERT_TRUE(std::isfinite(v.x + v.y + v.z));
  }
}

TEST(Laplacian, DegenerateInputStaysFinite) {
  // A sliver (negative cotangent weights), a zero-area face, a non-manifold edge, an isolated
  // vertex and a boundary, all in one mesh.
  const std::vector<glm::dvec3> p = {{0, 0, 0},    {1, 0, 0},   {0.5, 1e-7, 0}, {0.5, 1, 0},
                                     {0.5, -1, 0}, {0.5, 0, 1}, {2, 2, 2},      {0, 0, 0.0}};
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3, 1, 3, 2, 0, 4, 1, 0, 1, 5, 0, 1, 7, 2, 2, 3};
  const Adjacency a = buildAdjacency(p.size(), idx);
  EXPECT_EQ(a.isolatedVertices, 1u);
  EXPECT_GT(a.nonManifoldEdges, 0u);
  for (auto method : {SmoothingMethod::Explicit, SmoothingMethod::Taubin, SmoothingMethod::Implicit})
    for (auto kind : {LaplacianWeights::Uniform, LaplacianWeights::Cotangent})
      for (bool clamp : {true, false}) {
        SmoothingSettings set{method, kind, 0.5, 10, true, clamp, 0.1};
        const SmoothingResult r = smooth(p, idx, a, set);
        for (auto& v : r.positions) EXPECT_TRUE(std::isfinite(v.x + v.y + v.z)) << int(method) << int(kind) << clamp;
        for (double e : r.energy) EXPECT_FALSE(std::isnan(e));
      }
  const BilateralResult b = bilateralNormalFilter(p, idx, {});
  for (auto& v : b.positions) EXPECT_TRUE(std::isfinite(v.x + v.y + v.z));
}

TEST(Noise, IsSeededAndHasTheAskedSigma) {
  const Welded s = weld(makeUvSphere(1.0f, 64));
  const NoiseSettings set{NoiseKind::Gaussian, 0.3, 0.1, 42};
  const auto a = addNoise(s.p, s.idx, set), b = addNoise(s.p, s.idx, set);
  EXPECT_EQ(a, b);
  const auto normals = vertexNormals(s.p, s.idx, NormalWeighting::Area);
  double sq = 0, tangential = 0;
  for (size_t v = 0; v < a.size(); ++v) {
    const double along = glm::dot(a[v] - s.p[v], normals[v]);
    sq += along * along;
    tangential += glm::length(a[v] - s.p[v] - along * normals[v]);
  }
  const double sigma = std::sqrt(sq / double(a.size())), expected = 0.3 * meanEdgeLength(s.p, s.idx);
  EXPECT_NEAR(sigma, expected, 0.1 * expected);
  EXPECT_LT(tangential, 1e-9) << "noise moves along the normal only";
  size_t moved = 0;
  for (size_t v = 0; v < a.size(); ++v)
    moved += addNoise(s.p, s.idx, {NoiseKind::Impulsive, 0.3, 0.1, 42})[v] != s.p[v];
  EXPECT_NEAR(double(moved) / double(a.size()), 0.1, 0.03);
}

TEST(Bilateral, KeepsTheEdgesOfACubeThatLaplacianRoundsOff) {
  MeshData cube = makeBox(glm::vec3(1.0f));
  // Subdivide the box's faces: a grid per face, welded along the edges.
  MeshData fine;
  for (int face = 0; face < 6; ++face) {
    const uint32_t base = uint32_t(fine.positions.size());
    const glm::vec3 o = cube.positions[size_t(4 * face)], du = cube.positions[size_t(4 * face + 1)] - o,
                    dv = cube.positions[size_t(4 * face + 2)] - o;
    const int n = 12;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) fine.positions.push_back(o + du * (float(i) / n) + dv * (float(j) / n));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const uint32_t a = base + uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
        fine.indices.insert(fine.indices.end(), {a, b, c, b, d, c});
      }
  }
  const Welded clean = weld(fine);
  const auto noisy = addNoise(clean.p, clean.idx, {NoiseKind::Gaussian, 0.2, 0.1, 3});
  SmoothingSettings lap;
  lap.iterations = 20;
  const double laplacian =
      meanFaceNormalAngleDeg(smooth(noisy, clean.idx, clean.adj, lap).positions, clean.p, clean.idx);
  const double bilateral =
      meanFaceNormalAngleDeg(bilateralNormalFilter(noisy, clean.idx, {}).positions, clean.p, clean.idx);
  const double before = meanFaceNormalAngleDeg(noisy, clean.p, clean.idx);
  EXPECT_LT(bilateral, laplacian) << "noisy " << before << ", Laplacian " << laplacian << ", bilateral " << bilateral;
  EXPECT_LT(bilateral, 0.5 * before);
}

TEST(Bake, RasterisedMapReconstructsOffsetsWithinTolerance) {
  // A smooth offset field over a UV sphere, baked at 1024^2 into 16 bits and read back bilinearly
  // at every vertex: the stated bound is 0.2 % of the offsets' range.
  const MeshData sphere = makeUvSphere(1.0f, 48);
  std::vector<float> offsets;
  for (auto& uv : sphere.uvs) offsets.push_back(std::sin(6.0f * uv.x) * std::cos(3.0f * uv.y));
  const BakeResult r =
      bakeDisplacement(sphere.uvs, sphere.indices, offsets, {BakeMethod::Raster, 1024, 32, 4, MapFormat::Unorm16});
  ASSERT_EQ(r.error, "");
  float worst = 0;
  for (size_t v = 0; v < offsets.size(); ++v)
    worst = std::max(worst, std::abs(sampleDisplacement(r.map, sphere.uvs[v], true) - offsets[v]));
  EXPECT_LT(worst, 0.002f * 2.0f) << "range 2: bound 0.004";
  // 8 bits quantise to range / 255: the same bake in Unorm8 is worse, but still within one step.
  const BakeResult r8 =
      bakeDisplacement(sphere.uvs, sphere.indices, offsets, {BakeMethod::Raster, 1024, 32, 4, MapFormat::Unorm8});
  float worst8 = 0;
  for (size_t v = 0; v < offsets.size(); ++v)
    worst8 = std::max(worst8, std::abs(sampleDisplacement(r8.map, sphere.uvs[v], true) - offsets[v]));
  EXPECT_GT(worst8, worst);
  EXPECT_LT(worst8, 2.0f / 255.0f + 0.004f);
}

TEST(Bake, NearestVertexByFlannMatchesBruteForce) {
  const MeshData sphere = makeUvSphere(1.0f, 16);
  std::vector<float> offsets(sphere.uvs.size());
  for (size_t v = 0; v < offsets.size(); ++v) offsets[v] = float(v);  // the map then names the vertex
  const BakeResult r =
      bakeDisplacement(sphere.uvs, sphere.indices, offsets, {BakeMethod::NearestExact, 64, 32, 0, MapFormat::Float32});
  ASSERT_EQ(r.error, "");
  for (int y = 0; y < 64; y += 7)
    for (int x = 0; x < 64; x += 5) {
      const glm::vec2 uv((x + 0.5f) / 64, (y + 0.5f) / 64);
      float best = INFINITY;
      for (auto& v : sphere.uvs) best = std::min(best, glm::distance(v, uv));
      const size_t got = size_t(r.map.stored[size_t(y * 64 + x)]);
      EXPECT_NEAR(glm::distance(sphere.uvs[got], uv), best, 1e-6f);
    }
  const BakeResult approx =
      bakeDisplacement(sphere.uvs, sphere.indices, offsets, {BakeMethod::NearestApprox, 64, 1, 0, MapFormat::Float32});
  const BakeResult many = bakeDisplacement(sphere.uvs, sphere.indices, offsets,
                                           {BakeMethod::NearestApprox, 64, 512, 0, MapFormat::Float32});
  EXPECT_LE(many.wrongNeighbours, approx.wrongNeighbours) << "more checks, fewer wrong neighbours";
}

TEST(Bake, AMeshWithoutUvsIsRefusedWithAReason) {
  const std::vector<glm::vec2> none;
  const std::vector<float> offsets(3, 0.0f);
  const BakeResult r = bakeDisplacement(none, std::vector<uint32_t>{0, 1, 2}, offsets, {});
  EXPECT_NE(r.error.find("no UVs"), std::string::npos);
}

TEST(Bake, OverlappingUvLayoutsAreDetected) {
  // Two quads in different places with the same UVs (a mirrored model's layout): one map cannot
  // hold both; the raster bake counts the texels claimed twice.
  const std::vector<glm::vec2> uvs = {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.1f, 0.9f},
                                      {0.1f, 0.1f}, {0.9f, 0.1f}, {0.1f, 0.9f}};
  const std::vector<uint32_t> idx = {0, 1, 2, 3, 4, 5};
  const std::vector<float> offsets = {0, 0, 0, 1, 1, 1};
  const BakeResult r = bakeDisplacement(uvs, idx, offsets, {BakeMethod::Raster, 64, 32, 0, MapFormat::Float32});
  EXPECT_GT(r.overlapping, 64u * 64u / 4);
  const std::vector<glm::vec2> apart = {{0.1f, 0.1f}, {0.4f, 0.1f}, {0.1f, 0.4f},
                                        {0.6f, 0.6f}, {0.9f, 0.6f}, {0.6f, 0.9f}};
  EXPECT_EQ(bakeDisplacement(apart, idx, offsets, {BakeMethod::Raster, 64, 32, 0, MapFormat::Float32}).overlapping, 0u);
}

TEST(Bake, UvsOutsideTheUnitSquareWrapLikeTheTexture) {
  // A triangle from u = -0.2 to 0.2: with a repeating map its left part lands at u = 0.8 .. 1.
  const std::vector<glm::vec2> uvs = {{-0.2f, 0.2f}, {0.2f, 0.2f}, {0.0f, 0.6f}};
  const std::vector<uint32_t> idx = {0, 1, 2};
  const std::vector<float> offsets = {1.0f, 1.0f, 1.0f};
  EXPECT_TRUE(uvsLeaveUnitSquare(uvs));
  EXPECT_FALSE(uvsLeaveUnitSquare(std::vector<glm::vec2>{{0, 0}, {1, 1}}));
  for (auto method : {BakeMethod::Raster, BakeMethod::NearestExact}) {
    const BakeResult r = bakeDisplacement(uvs, idx, offsets, {method, 64, 32, 4, MapFormat::Float32, true});
    for (auto& uv : uvs) EXPECT_NEAR(sampleDisplacement(r.map, uv, true), 1.0f, 1e-5f) << int(method);
    EXPECT_NEAR(sampleDisplacement(r.map, {0.9f, 0.25f}, false), 1.0f, 1e-5f) << "the wrapped part was not drawn";
  }
}

// A user's noisy mesh and its clean reference come as two files: paired by the order of their
// vertices (OFF, PLY, OBJ with the faces listed differently) or by the order of their faces
// (vertices renumbered); anything else is refused, naming both meshes' counts.
namespace {

fs::path writeMeshFile(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("shadelab_pair_" + std::to_string(::getpid())) / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
  return p;
}

MeshData loadOne(const fs::path& file) {
  Scene s;
  EXPECT_EQ(loadSceneFile(file, s), "");
  return s.meshes.at(0);
}

}  // namespace

TEST(MeshPair, ObjFilesWithTheSameVerticesPairByVertexNumberWhateverTheFaceOrder) {
  // Two triangles over four vertices; the noisy file lists the faces in the other order and with
  // rotated corners, so the loader meets its vertices in another order than the clean file's.
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  const MeshData clean = loadOne(writeMeshFile("clean.obj", v + "f 1 2 3\nf 1 3 4\n"));
  const MeshData noisy =
      loadOne(writeMeshFile("noisy.obj", "v 0 0 0.1\nv 1 0 -0.1\nv 1 1 0.2\nv 0 1 -0.2\nf 4 1 3\nf 3 1 2\n"));
  ASSERT_NE(noisy.positions[0], glm::vec3(0, 0, 0.1f)) << "the test needs the loader to reorder the noisy vertices";
  MeshPair pair;
  ASSERT_EQ(pairWithClean(noisy, clean, "noisy.obj", "clean.obj", pair), "");
  EXPECT_EQ(pair.how, "vertices in the same order");
  EXPECT_EQ(pair.twin.indices, clean.indices) << "the twin has the clean mesh's faces";
  for (size_t i = 0; i < clean.positions.size(); ++i) {
    const glm::vec3 c = clean.positions[i], n = pair.twin.positions[i];
    EXPECT_EQ(glm::vec2(c), glm::vec2(n)) << "vertex " << i << " paired with another vertex";
    EXPECT_NE(c.z, n.z);
  }
}

TEST(MeshPair, RenumberedVerticesPairByFaceOrder) {
  MeshData clean;
  clean.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
  clean.indices = {0, 1, 2, 0, 2, 3};  // vertex 4 is in no face
  MeshData noisy;                      // the same four vertices, numbered backwards, with noise in z; one fewer vertex
  noisy.positions = {{0, 1, 0.4f}, {1, 1, 0.3f}, {1, 0, 0.2f}, {0, 0, 0.1f}};
  noisy.indices = {3, 2, 1, 3, 1, 0};
  MeshPair pair;
  ASSERT_EQ(pairWithClean(noisy, clean, "noisy", "clean", pair), "");
  EXPECT_EQ(pair.how, "faces in the same order");
  EXPECT_EQ(pair.twin.positions[0], glm::vec3(0, 0, 0.1f));
  EXPECT_EQ(pair.twin.positions[3], glm::vec3(0, 1, 0.4f));
  EXPECT_EQ(pair.twin.positions[4], clean.positions[4]) << "a vertex in no face keeps its place";
  EXPECT_NEAR(pair.meanMoveEdges, (0.1 + 0.2 + 0.3 + 0.4) / 5.0 / ((4 + 2 * std::sqrt(2.0)) / 6.0), 1e-6);
}

TEST(MeshPair, MeshesThatAreNoPairAreRefusedWithTheirCounts) {
  MeshData clean = makeUvSphere(1.0f, 8), other = makeUvSphere(1.0f, 12);
  MeshPair pair;
  const std::string err = pairWithClean(other, clean, "scan.ply", "truth.off", pair);
  EXPECT_NE(err.find("scan.ply ("), std::string::npos) << err;
  EXPECT_NE(err.find("are not a pair"), std::string::npos) << err;
  // The same face count, but the faces of another mesh: corners disagree.
  MeshData shuffled = clean;
  std::swap(shuffled.indices[0], shuffled.indices[5]);
  shuffled.positions.push_back({9, 9, 9});  // one more vertex: pairing by vertices is out
  EXPECT_NE(pairWithClean(shuffled, clean, "a", "b", pair).find("not in the same order"), std::string::npos);
}
