// The surface-detail lab on OSMesa: only the maps a technique reads are decoded, a filter change
// re-samples without a rebuild, vertex displacement moves every vertex by exactly s (h - base)
// along its normal (transform feedback), the file's own tangents are used when it has them,
// displacement approaches the truth as the mesh is subdivided, self-shadowing is judged against a
// shadowed truth, and a golden image per technique.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "app/host/measurer.h"
#include "app/measure/image.h"
#include "app/scene/loaders.h"
#include "gl_test.h"

using namespace shadelab;

namespace {

std::unique_ptr<LabHost> surfaceHost(const std::vector<std::string>& sets, const char* scene = "bricks") {
  return test::labHost("surface", scene, sets);
}

}  // namespace

TEST(Surface, OnlyTheMapsATechniqueReadsAreDecoded) {
  auto host = surfaceHost({"surface.technique=none"});
  host->renderFrame({64, 48});
  EXPECT_EQ(host->gpuScene().texturesUploaded(), 1) << "colour only";
  host->set("surface.technique=normal-map");
  host->renderFrame({64, 48});
  EXPECT_EQ(host->gpuScene().texturesUploaded(), 2) << "colour + normal map";
  host->set("surface.technique=pom");
  host->renderFrame({64, 48});
  EXPECT_EQ(host->gpuScene().texturesUploaded(), 2) << "colour + height map";
  const int builds = host->sceneBuilds();
  host->set("surface.filter=anisotropic");  // sampling only: the uploaded maps are re-sampled
  host->renderFrame({64, 48});
  host->set("surface.filter=nearest");
  host->renderFrame({64, 48});
  EXPECT_EQ(host->sceneBuilds(), builds);
  EXPECT_EQ(gl::drainErrors(), "");
}

// A mesh with no UVs gets the plain program under every technique, tessellation included: it is
// drawn as triangles (patches sent to a program without tessellation stages were a GL error and
// drew nothing; found by the soak).
TEST(Surface, AMeshWithoutUvsIsDrawnUnderEveryTechnique) {
  const std::string quad = std::string(SHADELAB_SOURCE_DIR) + "/tests/data/quad.off";
  for (const char* technique : {"tessellation", "pom", "displacement", "normal-map"}) {
    auto host = surfaceHost({std::string("surface.technique=") + technique}, quad.c_str());
    gl::drainErrors();
    host->renderFrame({64, 48});
    EXPECT_EQ(gl::drainErrors(), "") << technique;
    const ImageF image = host->readImage();
    int covered = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4)
      covered += image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2] > 0.1f;
    EXPECT_GT(covered, 64 * 48 / 20) << technique << ": the quad is not on screen";
  }
}

TEST(Surface, VertexDisplacementMovesExactlySTimesHAlongTheNormal) {
  // A 4 x 4 height map read at its texel centres (nearest): the value is known exactly there.
  const uint8_t heights[16] = {0, 16, 32, 48, 64, 80, 96, 112, 128, 144, 160, 176, 192, 208, 224, 255};
  gl::SamplerState nearest;
  nearest.minFilter = nearest.magFilter = GL_NEAREST;
  const gl::Texture2D map = gl::Texture2D::fromData({4, 4}, GL_R8, GL_RED, GL_UNSIGNED_BYTE, heights, nearest);
  MeshData grid;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      grid.positions.emplace_back(float(i), float(j), 0.0f);
      grid.normals.push_back(glm::normalize(glm::vec3(0.3f * float(i - 1), 0.2f, 1.0f)));  // not all alike
      grid.uvs.emplace_back((float(i) + 0.5f) / 4.0f, (float(j) + 0.5f) / 4.0f);
    }
  for (uint32_t j = 0; j < 3; ++j)
    for (uint32_t i = 0; i < 3; ++i) grid.indices.insert(grid.indices.end(), {j * 4 + i, j * 4 + i + 1, j * 4 + i + 4});
  grid.tangents.assign(16, glm::vec4(1, 0, 0, 1));
  const GpuMesh mesh = GpuMesh::upload(grid);
  for (float base : {1.0f, 0.0f})
    for (float s : {0.25f, -0.7f}) {
      const auto out = test::captureVertexOutput(
          "surface/surface.vert", {{"DISPLACE_VERTEX", "1"}}, "Surface.world", mesh, [&](GLuint p) {
            const glm::mat4 id(1.0f);
            const glm::mat3 id3(1.0f);
            glUniformMatrix4fv(glGetUniformLocation(p, "u_model"), 1, GL_FALSE, &id[0][0]);
            glUniformMatrix3fv(glGetUniformLocation(p, "u_normalMatrix"), 1, GL_FALSE, &id3[0][0]);
            map.bind(0);
            glUniform1i(glGetUniformLocation(p, "u_heightMap"), 0);
            glUniform1f(glGetUniformLocation(p, "u_heightScale"), s);
            glUniform1f(glGetUniformLocation(p, "u_heightBase"), base);
          });
      for (size_t v = 0; v < 16; ++v) {
        const glm::vec3 expected = grid.positions[v] + grid.normals[v] * s * (float(heights[v]) / 255.0f - base);
        EXPECT_LT(glm::length(out[v] - expected), 1e-5f) << "vertex " << v << " base " << base << " s " << s;
      }
    }
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST(Surface, TheFilesOwnTangentsAreUsedWhenItHasThem) {
  // tangent_quad.gltf's TANGENT points along +z while its u runs along +x: 90 degrees apart, which
  // the tangent-angle view at a 90-degree scale shows in full yellow.
  const std::string quad = std::string(SHADELAB_SOURCE_DIR) + "/tests/data/tangent_quad.gltf";
  auto host = surfaceHost({"surface.technique=normal-map", "surface.view=tangent-angle", "surface.angle_scale=90",
                           "surface.tangents=mesh", "surface.compare_with=generated"},
                          quad.c_str());
  host->set("surface.technique=normal-map");
  host->camera().parse("yaw=0,pitch=89");
  host->renderFrame({64, 64});
  auto px = host->target()->readPixel(32, 32);
  // Yellow (the full angle) has far more green than blue; slate (none) has less. The light dims both alike.
  EXPECT_GT(px[1], px[2] + 0.2f) << "the file's tangents, not generated ones";
  host->set("surface.tangents=generated");
  host->renderFrame({64, 64});
  px = host->target()->readPixel(32, 32);
  EXPECT_LT(px[1], px[2]) << "generated against generated: no angle";
  // A file without tangents: generated ones stand in, and the lab says so.
  auto plain = surfaceHost({"surface.technique=normal-map", "surface.tangents=mesh"},
                           (std::string(SHADELAB_SOURCE_DIR) + "/tests/data/textured_quad.gltf").c_str());
  plain->renderFrame({32, 32});
  bool said = false;
  for (auto& w : plain->warnings()) said |= w.find("has no tangents of its own") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(Surface, DisplacementApproachesTheTruthAsTheMeshIsSubdivided) {
  auto host = surfaceHost({"surface.technique=displacement", "surface.light_elevation=25"});
  Measurer measurer(*host);
  double angle[3], silhouette[3];
  const int levels[3] = {3, 5, 7};
  for (int i = 0; i < 3; ++i) {
    host->set("surface.subdivision=" + std::to_string(levels[i]));
    auto m = measurer.measureNow({160, 120}, 0.0f, {{"gpu_ms", 1.0}});
    ASSERT_TRUE(m);
    angle[i] = test::metric(m->values, "normal_angle_deg");
    silhouette[i] = test::metric(m->values, "silhouette_pct");
  }
  EXPECT_GT(angle[0], angle[1]);
  EXPECT_GT(angle[1], angle[2]);
  EXPECT_GE(silhouette[0], silhouette[2]);
  host->set("surface.technique=truth");  // the truth against itself, through the same path
  auto self = measurer.measureNow({160, 120}, 0.0f, {{"gpu_ms", 1.0}});
  ASSERT_TRUE(self);
  EXPECT_LT(test::metric(self->values, "normal_angle_deg"), angle[2]);
  EXPECT_LT(test::metric(self->values, "silhouette_pct"), 0.5);
}

TEST(Surface, SelfShadowingIsJudgedAgainstAShadowedTruth) {
  // With self_shadow on, the truth is shadowed (the height field marched half a texel at a time)...
  auto host = surfaceHost({"surface.technique=truth"});
  host->renderFrame({192, 108});
  const ImageF plain = host->readImage();
  host->set("surface.self_shadow=on");
  host->renderFrame({192, 108});
  EXPECT_GT(compareImages(host->readImage(), plain).rmse, 0.03) << "the truth casts no shadow";
  // ... and POM's own shadow march comes far closer to it than a normal map, which cannot shadow.
  host->set("surface.technique=pom");
  host->set("surface.layers=32");
  Measurer measurer(*host);
  auto rmse = [&] {
    auto m = measurer.measureNow({192, 108}, 0.0f, {{"gpu_ms", 1.0}});
    EXPECT_TRUE(m);
    return m ? test::metric(m->values, "rmse") : NAN;
  };
  const double pom = rmse();
  host->set("surface.technique=normal-map");
  EXPECT_LT(pom, 0.6 * rmse());
}

struct SurfaceGolden {
  const char* name;
  std::vector<std::string> sets;
};

class SurfaceGoldens : public ::testing::TestWithParam<SurfaceGolden> {};

TEST_P(SurfaceGoldens, MatchWithinTolerance) {
  auto host = surfaceHost(GetParam().sets);
  host->renderFrame({256, 144});
  test::expectGolden(GetParam().name, host->readImage());
}

INSTANTIATE_TEST_SUITE_P(
    Surface, SurfaceGoldens,
    ::testing::Values(SurfaceGolden{"surface_none", {"surface.technique=none"}},
                      SurfaceGolden{"surface_normal_map", {"surface.technique=normal-map"}},
                      SurfaceGolden{"surface_bump", {"surface.technique=bump"}},
                      SurfaceGolden{"surface_displacement",
                                    {"surface.technique=displacement", "surface.subdivision=5"}},
                      SurfaceGolden{"surface_tessellation", {"surface.technique=tessellation"}},
                      SurfaceGolden{"surface_parallax", {"surface.technique=parallax"}},
                      SurfaceGolden{"surface_steep_parallax", {"surface.technique=steep-parallax"}},
                      SurfaceGolden{"surface_pom_shadowed", {"surface.technique=pom", "surface.self_shadow=on"}}),
    [](const auto& info) { return std::string(info.param.name); });

// A user's own material: an MTL's height map (disp, or bump when it is grey) is read; a material
// without one gets no truth and a warning instead of a flat frame judged against a "true surface";
// a height image given to the host brings the relief and the truth back; depth maps read inverted.
namespace {

struct UsersQuad {
  std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("shadelab_users_quad_" + std::to_string(::getpid()));
  explicit UsersQuad(const std::string& mtl) {
    std::filesystem::create_directories(folder);
    ImageF bumps{{64, 64}, {}}, normals{{8, 8}, {}};
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const float h = 0.5f + 0.5f * std::sin(x * 0.4f) * std::sin(y * 0.4f);
        bumps.rgba.insert(bumps.rgba.end(), {h, h, h, 1.0f});
      }
    for (int i = 0; i < 64; ++i) normals.rgba.insert(normals.rgba.end(), {0.5f, 0.5f, 1.0f, 1.0f});
    EXPECT_EQ(writePng((folder / "bumps.png").string(), bumps), "");
    EXPECT_EQ(writePng((folder / "normals.png").string(), normals), "");
    std::ofstream(folder / "quad.mtl") << "newmtl wall\nKd 0.8 0.7 0.6\n" << mtl;
    std::ofstream(folder / "quad.obj")
        << "mtllib quad.mtl\nusemtl wall\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
  }
  ~UsersQuad() { std::filesystem::remove_all(folder); }
  std::string obj() const { return (folder / "quad.obj").string(); }
};

}  // namespace

TEST(Surface, AnMtlHeightMapIsReadFromDispOrAGreyBump) {
  for (const char* line : {"disp bumps.png\n", "bump bumps.png\n", "map_Bump bumps.png\nnorm normals.png\n"}) {
    UsersQuad quad(line);
    Scene s;
    ASSERT_EQ(loadSceneFile(quad.obj(), s), "");
    const Material& m = s.materials.back();
    ASSERT_GE(m.heightImage, 0) << line;
    EXPECT_EQ(s.images[size_t(m.heightImage)].name, "bumps.png") << line;
  }
  UsersQuad normalInBump("bump normals.png\n");  // the exporters' habit: a normal map in bump
  Scene s;
  ASSERT_EQ(loadSceneFile(normalInBump.obj(), s), "");
  EXPECT_LT(s.materials.back().heightImage, 0);
  EXPECT_GE(s.materials.back().normalImage, 0);
}

TEST(Surface, AMaterialWithoutAHeightMapHasNoTruthUntilOneIsGiven) {
  UsersQuad quad("");
  auto host = surfaceHost({"surface.technique=pom"}, quad.obj().c_str());
  host->renderFrame({64, 48});
  EXPECT_EQ(referenceOf(host->lab()).kind, TruthKind::None);
  EXPECT_TRUE(test::warns(host->lab(), "material 'wall' has no height map: pom has nothing to read"));
  ASSERT_EQ(host->setHeightMap((quad.folder / "bumps.png").string()), "");
  host->renderFrame({64, 48});
  EXPECT_EQ(referenceOf(host->lab()).kind, TruthKind::Image);
  EXPECT_FALSE(test::warns(host->lab(), "has no height map"));
  EXPECT_NE(host->setHeightMap((quad.folder / "quad.mtl").string()), "") << "not an image";
  // A screenshot's preset reproduces the frame: it carries the height map.
  const nlohmann::json state = host->stateJson();
  auto again = surfaceHost({});
  ASSERT_EQ(again->applyStateJson(state), "");
  EXPECT_EQ(again->heightMap(), (quad.folder / "bumps.png").string());
  // The height view shows h; read as a depth map it shows 1 - h (no parallax: the same texel).
  ASSERT_EQ(host->set("surface.technique=none"), "");
  ASSERT_EQ(host->set("surface.view=height"), "");
  host->renderFrame({64, 48});
  const float asHeight = host->readImage().at(32, 24)[0];
  ASSERT_EQ(host->set("surface.height_map=depth"), "");
  host->renderFrame({64, 48});
  const float asDepth = host->readImage().at(32, 24)[0];
  EXPECT_NEAR(asHeight + asDepth, 1.0f, 2.0f / 255.0f);
  EXPECT_GT(std::abs(asHeight - asDepth), 0.05f) << "the test needs a pixel away from mid-grey";
  EXPECT_EQ(gl::drainErrors(), "");
}

// The truth's two million triangles are drawn in eight parts, one per window frame: the parts,
// composed by the depth test, are the frame one call draws, to the last bit.
TEST(Surface, ATruthDrawnInPartsIsTheFrameDrawnAtOnce) {
  auto host = surfaceHost({"surface.technique=truth", "surface.self_shadow=on"});
  ASSERT_GT(referenceOf(host->lab()).slices, 1);
  const gl::RenderTarget target = gl::RenderTarget::create({96, 72});
  host->renderFrame({96, 72});
  host->drawInto(target, host->camera(), 0.0f, {0.25f, -0.25f});
  const ImageF whole{target.size(), target.readRgba()};
  host->drawInto(target, host->camera(), 0.0f, {0.25f, -0.25f}, 0, 8);
  const ImageF first{target.size(), target.readRgba()};
  for (int slice = 1; slice < 8; ++slice) host->drawInto(target, host->camera(), 0.0f, {0.25f, -0.25f}, slice, 8);
  const ImageF parts{target.size(), target.readRgba()};
  size_t firstCovered = 0, wholeCovered = 0;
  for (size_t i = 3; i < whole.rgba.size(); i += 4) {
    firstCovered += first.rgba[i] > 0.5f;
    wholeCovered += whole.rgba[i] > 0.5f;
  }
  EXPECT_LT(firstCovered, wholeCovered * 3 / 4) << "the first part draws only its share of the triangles";
  ASSERT_EQ(whole.rgba.size(), parts.rgba.size());
  size_t differ = 0;
  for (size_t i = 0; i < whole.rgba.size(); ++i) differ += whole.rgba[i] != parts.rgba[i];
  EXPECT_EQ(differ, 0u);
  double covered = 0;
  for (size_t i = 3; i < parts.rgba.size(); i += 4) covered += parts.rgba[i];
  EXPECT_GT(covered, 0.5 * double(parts.rgba.size() / 4)) << "the test needs the wall to fill the frame";
  EXPECT_EQ(gl::drainErrors(), "");
}
