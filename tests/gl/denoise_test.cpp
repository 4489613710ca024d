// The denoising lab on OSMesa: welded copies of a position get identical offsets (no seam gap on
// the attribute path) and unwelded ones part; the vertex shader's map path puts every vertex
// where the CPU's read-back of the map says, which is what the lab's metrics assume.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/scene/mesh_topology.h"
#include "app/scene/scene_catalog.h"
#include "gl_test.h"
#include "labs/denoise/denoise_pipeline.h"
#include "labs/denoise/denoise_scenes.h"

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
    const auto gpu =
        test::captureVertexOutput("denoise/mesh.vert", {{"DISPLACE_MAP", "1"}}, "v_world", mesh, [&](GLuint p) {
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
  const auto gpu =
      test::captureVertexOutput("denoise/mesh.vert", {{"DISPLACE_ATTRIBUTE", "1"}}, "v_world", mesh, [](GLuint) {});
  for (size_t v = 0; v < gpu.size(); ++v)
    ASSERT_LT(glm::length(gpu[v] - (r.noisy[v] + r.noisyNormals[v] * r.offsets[v])), 1e-5f) << v;
}

// A user's own pair: the scene is the noisy file, denoise.clean its reference. On the published
// Fandisk pair loaded as two files, the noisy input's error is the paper's 28.421 degrees.
TEST(Denoise, AUsersNoisyMeshIsJudgedAgainstTheCleanFileItNames) {
  const auto folder = dataDirectory() / "denoise" / "guided_zhang2015" / "Fandisk0.3";
  if (!std::filesystem::exists(folder / "Noisy.obj")) GTEST_SKIP() << "no " << folder;
  LabHost host(test::builtinShaders());
  ASSERT_EQ(host.selectLab("denoise"), "");
  ASSERT_EQ(host.selectScene((folder / "Noisy.obj").string()), "");
  host.settle();
  host.renderFrame({160, 120});
  EXPECT_TRUE(test::warns(host.lab(), "is taken as the clean mesh and noise is generated on it"));
  ASSERT_EQ(host.set("denoise.clean=" + (folder / "Original.obj").string()), "");
  host.settle();
  host.renderFrame({160, 120});
  const Metrics m = host.lab().judge()->meshMetrics();
  EXPECT_NEAR(test::metric(m, "noisy_angle_deg"), 28.421, 5e-3);
  EXPECT_LT(test::metric(m, "angle_error_deg"), test::metric(m, "noisy_angle_deg"));
  EXPECT_FALSE(test::warns(host.lab(), "the noise shown is"));
  EXPECT_FALSE(test::warns(host.lab(), "is taken as the clean mesh"));
  // Generated noise on the pair's clean mesh is not the file's own: said so.
  ASSERT_EQ(host.set("denoise.input=generated"), "");
  host.settle();
  host.renderFrame({160, 120});
  EXPECT_TRUE(test::warns(host.lab(), "not the mesh's own: input = published shows the scene file's own noise"));
}

// The built-in cube has no noisy twin: input = published shows generated noise, and says so.
TEST(Denoise, GeneratedNoiseInPlaceOfAMissingTwinIsNamed) {
  LabHost host(test::builtinShaders());
  ASSERT_EQ(host.selectLab("denoise"), "");
  ASSERT_EQ(host.selectScene("denoise-cube"), "");
  host.settle();
  host.renderFrame({160, 120});
  EXPECT_TRUE(test::warns(host.lab(), "this scene has no noisy twin, so the noise shown is generated gaussian noise"));
  // A clean file that is no pair for the scene: one line naming both, and the scene stays the clean mesh.
  auto off = std::filesystem::temp_directory_path() / "shadelab_not_a_pair.off";
  { std::ofstream(off) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"; }
  ASSERT_EQ(host.set("denoise.clean=" + off.string()), "");
  host.settle();
  host.renderFrame({160, 120});
  EXPECT_TRUE(test::warns(host.lab(), "are not a pair")) << "a mesh of 3 vertices cannot be the cube's reference";
  EXPECT_TRUE(host.lab().judge()->meshMetrics().size() > 0);
  std::filesystem::remove(off);
  EXPECT_NE(host.set("denoise.clean=/no/such/mesh.obj"), "");
  EXPECT_NE(host.set("denoise.clean=" + off.replace_extension(".png").string()).find("valid: a .obj, .off, .ply file"),
            std::string::npos);
}
