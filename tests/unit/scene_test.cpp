// Loaders on good and malformed files, procedural meshes, tangents, camera parsing. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/scene/camera.h"
#include "app/scene/loaders.h"
#include "app/scene/procedural.h"
#include "app/scene/scene_catalog.h"

using namespace shadelab;
namespace fs = std::filesystem;

static const fs::path kData = SHADELAB_TEST_DATA;

static fs::path tempFile(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

TEST(Loaders, OffTriangulatesPolygons) {
  Scene s;
  ASSERT_EQ(loadSceneFile(kData / "quad.off", s), "");
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangleCount(), 3u);  // a triangle and a quad
  EXPECT_EQ(s.meshes[0].normals.size(), 4u);
}

TEST(Loaders, MalformedFilesNameTheFileAndProblem) {
  Scene s;
  EXPECT_EQ(loadSceneFile(kData / "malformed.off", s),
            (kData / "malformed.off").string() + ": face 1 has too few indices");
  const auto badIndex = tempFile("shadelab_badindex.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  EXPECT_EQ(loadSceneFile(badIndex, s), badIndex.string() + ": index 7 out of range (3 vertices)");
  const auto nanVertex = tempFile("shadelab_nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(loadSceneFile(nanVertex, s), nanVertex.string() + ": vertex 1 is missing or malformed");
  const auto notOff = tempFile("shadelab_not.off", "PLY\n");
  EXPECT_EQ(loadSceneFile(notOff, s), notOff.string() + ": not an OFF file (first line must be OFF)");
  EXPECT_EQ(loadSceneFile("/no/such.obj", s), "/no/such.obj: no such file");
  EXPECT_EQ(loadSceneFile("mesh.stl", s),
            "mesh.stl: unknown scene file type '.stl' (valid: .gltf, .glb, .obj, .off, .ply)");
  const auto badGltf = tempFile("shadelab_bad.gltf", "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ { ");
  EXPECT_EQ(loadSceneFile(badGltf, s).rfind(badGltf.string() + ": ", 0), 0u);
  const auto emptyObj = tempFile("shadelab_empty.obj", "# nothing\n");
  EXPECT_EQ(loadSceneFile(emptyObj, s), emptyObj.string() + ": no valid triangle (no faces)");
}

// A binary glTF: the header, a JSON chunk and, if `bin` is given, a BIN chunk whose header claims
// `binClaim` bytes (its true size unless a test lies).
static std::string glb(std::string json, const std::string& bin, size_t binClaim) {
  const auto u32 = [](size_t v) {
    const auto x = uint32_t(v);
    return std::string(reinterpret_cast<const char*>(&x), 4);
  };
  while (json.size() % 4) json += ' ';
  std::string body = u32(json.size()) + "JSON" + json;
  if (!bin.empty()) body += u32(binClaim) + std::string("BIN\0", 4) + bin;
  return "glTF" + u32(2) + u32(12 + body.size()) + body;
}

TEST(Loaders, BinaryGltfChunksMustFitTheFile) {
  // One triangle, its positions in the BIN chunk.
  const std::string json =
      R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})";
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::string positions(reinterpret_cast<const char*>(xyz), sizeof xyz);
  Scene s;
  const auto good = tempFile("shadelab_triangle.glb", glb(json, positions, positions.size()));
  ASSERT_EQ(loadSceneFile(good, s), "");
  EXPECT_EQ(s.meshes.back().triangleCount(), 1u);
  // A BIN chunk claiming 8 bytes more than the file holds (the size of its own header): the
  // library would copy past the end of the file's bytes.
  const auto lying = tempFile("shadelab_lying.glb", glb(json, positions.substr(0, 28), 36));
  EXPECT_EQ(loadSceneFile(lying, s), lying.string() + ": chunk 1 claims 36 bytes, the file has 28 after its header");
  const auto cut = tempFile("shadelab_cut.glb", glb(json, positions, positions.size()).substr(0, 60));
  EXPECT_EQ(loadSceneFile(cut, s).rfind(cut.string() + ": its header gives ", 0), 0u);
}

TEST(Loaders, GltfWithNodeTransformsAndMaterial) {
  Scene s;
  ASSERT_EQ(loadSceneFile(kData / "triangle.gltf", s), "");
  ASSERT_EQ(s.instances.size(), 2u);                  // one mesh, two nodes
  EXPECT_FLOAT_EQ(s.instances[1].model[3][0], 2.0f);  // translation of the second node
  EXPECT_EQ(s.meshes[0].triangleCount(), 1u);
  EXPECT_EQ(s.meshes[0].uvs.size(), 3u);
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[0].y, 0.0f);  // glTF v=1 (bottom of the image) -> our v=0
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[2].y, 1.0f);
  const Material& m = s.materials[size_t(s.meshes[0].material)];
  EXPECT_FLOAT_EQ(m.baseColor.r, 1.0f);
  EXPECT_FLOAT_EQ(m.baseColor.g, 0.5f);
}

TEST(Loaders, GltfTexturesSamplersAndTrsStayEncodedUntilAsked) {
  Scene s;
  ASSERT_EQ(loadSceneFile(kData / "textured_quad.gltf", s), "");
  // One image, two samplers: two image sources, each with its texture's sampler.
  ASSERT_EQ(s.images.size(), 2u);
  for (auto& img : s.images) {
    EXPECT_TRUE(img.rgba.empty());  // kept encoded at load
    EXPECT_FALSE(img.bytes.empty());
  }
  const Material& m = s.materials[size_t(s.meshes[0].material)];
  EXPECT_EQ(m.name, "tiles");
  EXPECT_FLOAT_EQ(m.metallic, 0.25f);
  EXPECT_FLOAT_EQ(m.roughness, 0.75f);
  ASSERT_GE(m.baseColorImage, 0);
  ASSERT_GE(m.normalImage, 0);
  EXPECT_EQ(m.normalImage, m.metallicRoughnessImage);  // same image, same (default) sampler
  EXPECT_NE(m.baseColorImage, m.normalImage);
  const gl::SamplerState& base = s.images[size_t(m.baseColorImage)].sampler;
  EXPECT_EQ(base.wrapS, GLenum(GL_CLAMP_TO_EDGE));
  EXPECT_EQ(base.wrapT, GLenum(GL_MIRRORED_REPEAT));
  EXPECT_EQ(base.magFilter, GLenum(GL_NEAREST));
  EXPECT_EQ(s.images[size_t(m.normalImage)].sampler.wrapS, GLenum(GL_REPEAT));  // glTF's default
  // TRS: 90 degrees about +Y, scale 2: local +X lands on world -Z, twice as long.
  const glm::vec4 x = s.instances[0].model * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(x.x, 0.0f, 1e-5f);
  EXPECT_NEAR(x.z, -2.0f, 1e-5f);
  std::vector<unsigned char> rgba;
  glm::ivec2 size;
  ASSERT_EQ(decodeImage(s.images[size_t(m.baseColorImage)], rgba, size), "");
  EXPECT_EQ(size, glm::ivec2(2, 2));
  EXPECT_EQ(rgba[0], 255);  // top-left texel is red
  EXPECT_EQ(rgba[5], 255);  // then green
}

TEST(Loaders, SharedObjWithTexturesIsNotDecodedAtLoad) {
  const fs::path data = dataDirectory();
  if (data.empty()) GTEST_SKIP() << "shared data folder not found";
  Scene s;
  SceneNeeds needs;
  needs.uvs = true;
  ASSERT_EQ(buildScene("spot", needs, s), "");
  EXPECT_EQ(s.meshes[0].positions.size(), 3225u);  // UV seams split the 2,930 positions
  EXPECT_EQ(s.meshes[0].triangleCount(), 5856u);
  ASSERT_EQ(s.images.size(), 1u);
  EXPECT_TRUE(s.images[0].rgba.empty());  // recorded, not decoded
  std::vector<unsigned char> rgba;
  glm::ivec2 size;
  EXPECT_EQ(decodeImage(s.images[0], rgba, size), "");
  EXPECT_EQ(size, glm::ivec2(1024, 1024));
}

TEST(Scenes, LeaveOutUvsAndTangentsUnlessNeeded) {
  Scene s;
  SceneNeeds needs;
  ASSERT_EQ(buildScene("shading", needs, s), "");
  for (auto& m : s.meshes) {
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_TRUE(m.tangents.empty());
  }
  needs.uvs = needs.tangents = true;
  ASSERT_EQ(buildScene("shading", needs, s), "");
  for (auto& m : s.meshes) EXPECT_EQ(m.tangents.size(), m.positions.size());
  EXPECT_NE(buildScene("nowhere", needs, s).find("unknown scene 'nowhere' (valid: shading, sphere"), std::string::npos);
}

TEST(Scenes, OpaquePassesDrawTheNearestInstanceFirst) {
  // LearnOpenGL's layout: a 50 x 50 floor listed first, then a cube on it, seen from above and behind.
  Scene s;
  s.meshes = {makePlane(50.0f, 1, 1.0f), makeBox(glm::vec3(0.5f))};
  s.instances = {{0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.5f, 0.0f))},
                 {1, glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, 0.0f, 1.0f))},
                 {1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.5f, -8.0f))}};
  const glm::vec3 eye(0.0f, 2.96f, 6.84f);
  EXPECT_EQ(s.nearestFirst(eye), (std::vector<size_t>{1, 0, 2}));  // the cube hides floor; the far cube last
  for (size_t i = 0; i < s.instances.size(); ++i) s.instanceBounds.push_back(s.boundsOfInstance(i));
  EXPECT_EQ(s.nearestFirst(eye), (std::vector<size_t>{1, 0, 2}));
  EXPECT_EQ(s.nearestFirst(glm::vec3(0.0f, 1.5f, -12.0f)), (std::vector<size_t>{2, 0, 1}));
  EXPECT_TRUE(Scene().nearestFirst(eye).empty());
}

TEST(Mesh, SphereNormalsPointOutAndTessellationScales) {
  const MeshData coarse = makeUvSphere(1.0f, 8), fine = makeUvSphere(1.0f, 64);
  EXPECT_EQ(coarse.triangleCount(), 8u * 4 * 2);
  EXPECT_EQ(fine.triangleCount(), 64u * 32 * 2);
  for (size_t i = 0; i < fine.positions.size(); ++i)
    EXPECT_NEAR(glm::dot(fine.positions[i], fine.normals[i]), 1.0f, 1e-5f);
  // Winding: counter-clockwise seen from outside, so the geometric normal agrees with the vertex normals.
  MeshData recomputed = fine;
  computeNormals(recomputed);
  for (size_t i = 0; i < fine.normals.size(); ++i)
    if (std::abs(fine.normals[i].y) < 0.99f) EXPECT_GT(glm::dot(recomputed.normals[i], fine.normals[i]), 0.99f);
}

TEST(Mesh, DegenerateGeometryNeverYieldsNaN) {
  MeshData m;
  m.positions = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  m.uvs = {{0, 0}, {0, 0}, {0, 0}};  // zero-area in UV space too
  m.indices = {0, 1, 2};
  computeNormals(m);
  EXPECT_EQ(computeTangents(m).fallbacks, 3);
  for (auto& t : m.tangents) {
    EXPECT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
    EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
  }
}

TEST(Mesh, MirroredUvsFlipHandedness) {
  MeshData m = makePlane(2.0f, 1, 1.0f);
  computeTangents(m);
  const float handedness = m.tangents[0].w;
  EXPECT_EQ(std::abs(handedness), 1.0f);
  for (auto& uv : m.uvs) uv.x = -uv.x;
  computeTangents(m);
  EXPECT_EQ(m.tangents[0].w, -handedness);
}

TEST(Camera, ParseAndErrors) {
  OrbitCamera c;
  EXPECT_EQ(c.parse("yaw=10,pitch=-5,distance=3,target=1;2;3,fov=60"), "");
  EXPECT_FLOAT_EQ(c.yawDeg, 10.0f);
  EXPECT_FLOAT_EQ(c.target.z, 3.0f);
  OrbitCamera again;
  EXPECT_EQ(again.parse(c.toString()), "");
  EXPECT_NEAR(glm::length(again.eye() - c.eye()), 0.0f, 1e-5f);
  EXPECT_EQ(c.parse("tilt=3"),
            "--camera: unknown key 'tilt' (valid keys: yaw, pitch, distance, target=x;y;z, fov, near, far)");
  EXPECT_EQ(c.parse("pitch=95"), "--camera: bad value for pitch: '95'");
  EXPECT_EQ(c.parse("target=1;2"), "--camera: bad value for target: '1;2'");
  EXPECT_EQ(c.parse("near=10,far=1"), "--camera: near must be smaller than far");
  EXPECT_FLOAT_EQ(c.yawDeg, 10.0f);  // a failed parse changes nothing
}

TEST(Camera, ProjectionFinite) {
  OrbitCamera c;
  c.nearPlane = 1e-6f;
  c.farPlane = 1e6f;
  for (float aspect : {0.1f, 1.0f, 10.0f}) {
    const glm::mat4 p = c.projection(aspect) * c.view();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(p[i][j]));
  }
}

TEST(Loaders, PlyAsciiAndBinaryReadTheSameMesh) {
  const std::string header =
      "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "property float s\nproperty float t\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const auto ascii = tempFile("shadelab_quad.ply", "ply\nformat ascii 1.0\ncomment a quad\n" + header +
                                                       "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n4 0 1 2 3\n");
  std::string binary = "ply\nformat binary_big_endian 1.0\n" + header;
  auto put = [&](const void* p, size_t n) {  // big-endian on this little-endian machine: reverse
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = n; i-- > 0;) binary += char(b[i]);
  };
  const float v[4][5] = {{0, 0, 0, 0, 0}, {1, 0, 0, 1, 0}, {1, 1, 0, 1, 1}, {0, 1, 0, 0, 1}};
  for (auto& row : v)
    for (float f : row) put(&f, 4);
  binary += char(4);
  for (int32_t i : {0, 1, 2, 3}) put(&i, 4);
  const auto bin = tempFile("shadelab_quad_be.ply", binary);
  for (auto& file : {ascii, bin}) {
    Scene s;
    ASSERT_EQ(loadSceneFile(file, s), "") << file;
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].triangleCount(), 2u);
    EXPECT_EQ(s.meshes[0].uvs.size(), 4u);
    EXPECT_EQ(s.meshes[0].positions[2], glm::vec3(1, 1, 0));
    EXPECT_EQ(s.meshes[0].uvs[3], glm::vec2(0, 1));
  }
}

TEST(Loaders, MalformedPlyNamesTheFileAndTheProblem) {
  Scene s;
  const auto truncated = tempFile("shadelab_cut.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 1\n"
                                  "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n");
  EXPECT_EQ(loadSceneFile(truncated, s), truncated.string() + ": vertex 2 is missing or malformed");
  const auto badIndex = tempFile("shadelab_idx.ply",
                                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                 "property float y\nproperty float z\nelement face 1\n"
                                 "property list uchar int vertex_indices\nend_header\n"
                                 "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  EXPECT_EQ(loadSceneFile(badIndex, s), badIndex.string() + ": index 7 out of range (3 vertices)");
  const auto nan = tempFile("shadelab_nan.ply",
                            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 1\n"
                            "property list uchar int vertex_indices\nend_header\n"
                            "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(loadSceneFile(nan, s), nan.string() + ": a vertex position is NaN or Inf");
  EXPECT_EQ(loadSceneFile(tempFile("shadelab_fmt.ply", "ply\nformat weird 1.0\nend_header\n"), s)
                    .find("unknown format 'weird'") != std::string::npos,
            true);
}

TEST(Tangents, GeneratedMatchAnalyticOnASphereAndAPlane) {
  // Sphere: p = (sin t sin f, cos t, sin t cos f), f = 2 pi u, t = pi v: dp/du points along
  // (cos f, 0, -sin f), dp/dv along (cos t sin f, -sin t, cos t cos f).
  MeshData sphere = makeUvSphere(1.0f, 64);
  ASSERT_EQ(computeTangents(sphere).mirrorSplits, 0);
  float worstInterior = 0.0f, worstSeam = 0.0f;
  for (size_t v = 0; v < sphere.positions.size(); ++v) {
    const glm::vec2 uv = sphere.uvs[v];
    if (uv.y < 0.1f || uv.y > 0.9f) continue;  // the poles: every direction is a tangent
    const float f = uv.x * 2.0f * glm::pi<float>(), t = uv.y * glm::pi<float>();
    const glm::vec3 T(std::cos(f), 0.0f, -std::sin(f)),
        B(std::cos(t) * std::sin(f), -std::sin(t), std::cos(t) * std::cos(f));
    const float off = glm::degrees(std::acos(std::clamp(glm::dot(glm::vec3(sphere.tangents[v]), T), -1.0f, 1.0f)));
    (uv.x == 0.0f || uv.x == 1.0f ? worstSeam : worstInterior) =
        std::max(uv.x == 0.0f || uv.x == 1.0f ? worstSeam : worstInterior, off);
    const glm::vec3 bitangent = glm::cross(sphere.normals[v], glm::vec3(sphere.tangents[v])) * sphere.tangents[v].w;
    EXPECT_GT(glm::dot(bitangent, B), 0.99f) << "handedness at vertex " << v;
  }
  // Inside, the triangles on either side of a vertex cancel each other's chord error; a vertex on
  // the UV seam (split, as MikkTSpace splits it) has one side only: half a segment, 360/64/2 deg.
  EXPECT_LT(worstInterior, 0.5f) << "degrees off the analytic tangent";
  EXPECT_LT(worstSeam, 360.0f / 64.0f / 2.0f + 0.1f);
  EXPECT_GT(worstSeam, worstInterior);
  MeshData plane = makePlane(2.0f, 4, 1.0f);  // u along +x, v along +z, normal +y
  computeTangents(plane);
  for (size_t v = 0; v < plane.positions.size(); ++v) {
    EXPECT_NEAR(glm::length(glm::vec3(plane.tangents[v]) - glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
    const glm::vec3 bitangent = glm::cross(plane.normals[v], glm::vec3(plane.tangents[v])) * plane.tangents[v].w;
    EXPECT_NEAR(glm::length(bitangent - glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
  }
}

TEST(Tangents, MirroredHalvesAreSplitAndKeepTheirHandedness) {
  // A strip of two quads sharing the middle column, whose right quad's u runs backwards: the UV
  // layout mirrors at the shared edge (as a symmetric character's two halves share one texture).
  MeshData m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}, {1, 0, 1}, {2, 0, 1}};
  m.uvs = {{0, 0}, {1, 0}, {0, 0}, {0, 1}, {1, 1}, {0, 1}};
  m.normals.assign(6, glm::vec3(0, 1, 0));
  m.indices = {0, 3, 1, 1, 3, 4, 1, 4, 2, 2, 4, 5};
  const TangentReport r = computeTangents(m);
  EXPECT_EQ(r.mirrorSplits, 2) << "the two vertices of the mirror line are split";
  EXPECT_EQ(m.positions.size(), 8u);
  for (size_t t = 0; t < 4; ++t) {
    const uint32_t v = m.indices[3 * t];
    const glm::vec3 expected = t < 2 ? glm::vec3(1, 0, 0) : glm::vec3(-1, 0, 0);
    for (int k = 0; k < 3; ++k) {
      const glm::vec4 tangent = m.tangents[m.indices[3 * t + size_t(k)]];
      EXPECT_NEAR(glm::length(glm::vec3(tangent) - expected), 0.0f, 1e-5f) << "triangle " << t << " vertex " << v;
      const glm::vec3 bitangent = glm::cross(glm::vec3(0, 1, 0), glm::vec3(tangent)) * tangent.w;
      EXPECT_NEAR(glm::length(bitangent - glm::vec3(0, 0, 1)), 0.0f, 1e-5f) << "v runs along +z on both halves";
    }
  }
}

TEST(Tangents, DegenerateUvsGiveFiniteOrthonormalFrames) {
  MeshData m = makePlane(2.0f, 2, 1.0f);
  for (size_t v = 0; v < 4; ++v) m.uvs[v] = glm::vec2(0.5f);  // one row collapsed to a point in UV
  m.uvs[7] = glm::vec2(NAN);
  const TangentReport r = computeTangents(m);
  EXPECT_GT(r.degenerateUvTriangles, 0);
  for (size_t v = 0; v < m.tangents.size(); ++v) {
    const glm::vec3 t(m.tangents[v]);
    ASSERT_TRUE(std::isfinite(t.x + t.y + t.z)) << v;
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(t, m.normals[v]), 0.0f, 1e-5f);
    EXPECT_EQ(std::abs(m.tangents[v].w), 1.0f);
  }
}

TEST(Tangents, AGltfTangentAttributeIsKeptAsTheFilesOwn) {
  Scene s;
  ASSERT_EQ(loadSceneFile(kData / "tangent_quad.gltf", s), "");
  MeshData& m = s.meshes.at(0);
  ASSERT_EQ(m.sourceTangents.size(), 4u);
  // The file says +Z (deliberately not the UVs' u direction), w = +1, which is -1 once v is flipped.
  EXPECT_EQ(glm::vec3(m.sourceTangents[0]), glm::vec3(0, 0, 1));
  EXPECT_EQ(m.sourceTangents[0].w, -1.0f);
  computeTangents(m);
  EXPECT_GT(glm::length(glm::vec3(m.tangents[0]) - glm::vec3(m.sourceTangents[0])), 0.5f)
      << "generated tangents follow the UVs, the file's do not: the two must stay apart";
  Scene plain;
  ASSERT_EQ(loadSceneFile(kData / "triangle.gltf", plain), "");
  EXPECT_TRUE(plain.meshes.at(0).sourceTangents.empty());
}
