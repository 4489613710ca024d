// The denoising lab on OSMesa: welded copies of a position get identical offsets (no seam gap on
// the attribute path) and unwelded ones part; the vertex shader's map path puts every vertex
// where the CPU's read-back of the map says, which is what the lab's metrics assume.
#include <gtest/gtest.h>

#include <cmath>

#include "gl_test.h"
#include "labs/denoise/denoise_pipeline.h"
#include "labs/denoise/denoise_scenes.h"
#include "scene/mesh_topology.h"

using namespace shadelab;

namespace {

std::shared_ptr<const DenoiseModel> cubeModel() {
  Scene s;
  for (auto& r : denoiseScenes())
    if (r.id == "denoise-cube") EXPECT_EQ(r.build(s, {}), "");
  std::string error;
  auto model = buildDenoiseModel(s.meshes.at(0), nullptr, error);
  EXPECT_TRUE(model) << error;
  return model;
}

}  // namespace

// The lab that teaches crack-free seams must not crack on its own cube: welded, the 24 x 24 cube is
// closed, with the (n+1)^3 - (n-1)^3 positions of its surface grid.
TEST(Denoise, TheBuiltInCubeWeldsClosed) {
  Scene s;
  for (auto& r : denoiseScenes())
    if (r.id == "denoise-cube") ASSERT_EQ(r.build(s, {}), "");
  const MeshData& cube = s.meshes.at(0);
  const WeldedMesh welded = weldByPosition(cube);
  const MeshStatistics stats = meshStatistics(cube, welded, buildAdjacency(welded.positions.size(), welded.indices));
  EXPECT_EQ(stats.boundaryEdges, 0u);
  EXPECT_EQ(stats.nonManifoldEdges, 0u);
  EXPECT_EQ(stats.logicalVertices, 25u * 25u * 25u - 23u * 23u * 23u);
}

TEST(Denoise, WeldedCopiesGetIdenticalOffsetsAndUnweldedOnesCrack) {
  LabHost host(test::builtinShaders());
  ASSERT_EQ(host.selectLab("denoise"), "");
  ASSERT_EQ(host.selectScene("denoise-cube"), "");
  ASSERT_EQ(host.set("denoise.input=generated"), "");
  host.settle();
  host.renderFrame({160, 120});
  Metrics m = host.lab().judge()->meshMetrics();
  EXPECT_EQ(test::metric(m, "attribute_gap_max"), 0.0) << "copies of a position must move together";
  EXPECT_GT(test::metric(m, "seam_gap_max"), 0.0) << "the bilinear map path reads different texels across a seam";
  EXPECT_LT(test::metric(m, "angle_error_deg"), test::metric(m, "noisy_angle_deg"));
  ASSERT_EQ(host.set("denoise.weld=off"), "");
  host.settle();
  host.renderFrame({160, 120});
  m = host.lab().judge()->meshMetrics();
  EXPECT_GT(test::metric(m, "attribute_gap_max"), 0.05) << "unwelded, seam copies are smoothed apart";
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST(Denoise, VertexShaderDisplacesWhereTheCpuSaysItDoes) {
  const auto model = cubeModel();
  for (bool bilinear : {false, true}) {
    DenoiseConfig c;
    c.noise.level = 0.4;
    c.bilinear = bilinear;
    c.bake.resolution = 256;
    c.bake.format = MapFormat::Unorm16;
    const DenoiseResult r = runDenoise(*model, c);
    ASSERT_TRUE(r.map);
    MeshData base = model->render;
    base.positions = r.noisy;
    base.normals = r.noisyNormals;
    const GpuMesh mesh = GpuMesh::upload(base);
    gl::SamplerState s;
    s.minFilter = s.magFilter = bilinear ? GL_LINEAR : GL_NEAREST;
    s.wrapS = s.wrapT = r.map->repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;  // as the bake and the read-back
    const std::vector<uint8_t> texels = encodeMap(*r.map, false);
    const gl::Texture2D map = gl::Texture2D::fromData(r.map->size, GL_R16, GL_RED, GL_UNSIGNED_SHORT, texels.data(), s);
    const auto gpu = test::captureVertexOutput("denoise/mesh.vert", {{"DISPLACE_MAP", "1"}}, "v_world", mesh, [&](GLuint p) {
      map.bind(0);
      glUniform1i(glGetUniformLocation(p, "u_displacement"), 0);
      glUniform1f(glGetUniformLocation(p, "u_bias"), r.map->bias);
      glUniform1f(glGetUniformLocation(p, "u_scale"), r.map->scale);
    });
    // Nearest: the same texel, so the same number. Bilinear: GPUs quantise the weights (8 bits of
    // sub-texel position is common), so 0.1% of the offsets' range (llvmpipe agrees to 1e-7).
    const float tolerance = bilinear ? 1e-3f * r.map->scale : 1e-5f * r.map->scale + 1e-6f;
    float worst = 0.0f;
    for (size_t v = 0; v < gpu.size(); ++v) {
      const glm::vec3 cpu = r.noisy[v] + r.noisyNormals[v] * r.readBack[v];
      worst = std::max(worst, glm::length(gpu[v] - cpu));
    }
    EXPECT_LT(worst, tolerance) << (bilinear ? "bilinear" : "nearest");
  }
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST(Denoise, AttributePathIsTheOffsetAlongTheNormal) {
  const auto model = cubeModel();
  const DenoiseResult r = runDenoise(*model, DenoiseConfig{});
  MeshData base = model->render;
  base.positions = r.noisy;
  base.normals = r.noisyNormals;
  GpuMesh mesh = GpuMesh::upload(base);
  ASSERT_TRUE(mesh.setScalars(kScalar0, r.offsets));
  const auto gpu = test::captureVertexOutput("denoise/mesh.vert", {{"DISPLACE_ATTRIBUTE", "1"}}, "v_world", mesh,
                                             [](GLuint) {});
  for (size_t v = 0; v < gpu.size(); ++v)
    ASSERT_LT(glm::length(gpu[v] - (r.noisy[v] + r.noisyNormals[v] * r.offsets[v])), 1e-5f) << v;
}
