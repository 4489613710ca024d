// Lab-owned geometry: arrays replaced in place take effect and allocate nothing; extra scalar
// attributes get one buffer; patches draw through a tessellation stage.
#include <gtest/gtest.h>

#include "app/gl/texture.h"
#include "app/scene/gpu_mesh.h"
#include "gl_test.h"

using namespace shadelab;

namespace {

ShaderSearchPath testShaders() {
  return ShaderSearchPath({std::filesystem::path(SHADELAB_SOURCE_DIR) / "tests" / "data" / "shaders"});
}

// A triangle covering the left half of clip space, at x in [-1, x1].
MeshData triangle(float x1) {
  MeshData m;
  m.positions = {{-1, -1, 0}, {x1, -1, 0}, {-1, 1, 0}};
  m.indices = {0, 1, 2};
  return m;
}

size_t coveredPixels(const gl::RenderTarget& rt) {
  size_t n = 0;
  const auto rgba = rt.readRgba();
  for (size_t i = 0; i < rgba.size(); i += 4) n += rgba[i + 1] > 0.5f || rgba[i + 2] > 0.5f;
  return n;
}

}  // namespace

TEST(LabGeometry, ReplacedArraysTakeEffectAndAllocateNothing) {
  gl::drainErrors();
  const int before = gl::liveObjectsTotal();
  {
    ShaderLibrary lib(testShaders());
    auto prog = lib.program(
        {"test/plain", {{GL_VERTEX_SHADER, "test/plain.vert"}, {GL_FRAGMENT_SHADER, "test/plain.frag"}}, {}});
    ASSERT_TRUE(prog->hasGoodProgram());
    gl::RenderTarget rt = gl::RenderTarget::create({64, 64});
    MeshData m = triangle(-1.0f + 2.0f / 64.0f);  // a sliver
    GpuMesh mesh = GpuMesh::upload(m);
    const int uploaded = gl::liveObjectsTotal();
    auto draw = [&] {
      rt.bind();
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glDisable(GL_DEPTH_TEST);
      prog->use();
      mesh.draw();
    };
    draw();
    const size_t sliver = coveredPixels(rt);
    for (int i = 0; i < 50; ++i) {  // a dragged lambda slider: 50 results, one mesh
      m.positions[1].x = -1.0f + 2.0f * float(i + 1) / 50.0f;
      ASSERT_TRUE(mesh.updatePositions(m.positions));
    }
    draw();
    EXPECT_GT(coveredPixels(rt), sliver * 10) << "the new positions were not drawn";
    EXPECT_EQ(gl::liveObjectsTotal(), uploaded) << "updating positions allocated GL objects";
    const std::vector<float> ones(3, 1.0f);
    EXPECT_TRUE(mesh.setScalars(kScalar0, ones));
    EXPECT_TRUE(mesh.setScalars(kScalar0, ones));
    EXPECT_EQ(gl::liveObjectsTotal(), uploaded + 1) << "one buffer per scalar attribute, made once";
    draw();
    EXPECT_GT(rt.readPixel(4, 60)[0], 0.5f) << "the scalar attribute did not reach the shader";
    EXPECT_FALSE(mesh.updatePositions(std::vector<glm::vec3>(5))) << "a wrong length must be refused";
    EXPECT_FALSE(mesh.updateNormals(std::vector<glm::vec3>(3))) << "no normals were uploaded";
    EXPECT_EQ(gl::drainErrors(), "");
  }
  EXPECT_EQ(gl::liveObjectsTotal(), before);
}

TEST(LabGeometry, PatchesDrawThroughTessellation) {
  ShaderLibrary lib(testShaders());
  const ProgramSpec spec{"test/patch",
                         {{GL_VERTEX_SHADER, "test/patch.vert"},
                          {GL_TESS_CONTROL_SHADER, "test/patch.tesc"},
                          {GL_TESS_EVALUATION_SHADER, "test/patch.tese"},
                          {GL_FRAGMENT_SHADER, "test/patch.frag"}},
                         {{"LEVEL", "4"}}};
  auto prog = lib.program(spec);
  ASSERT_TRUE(prog->hasGoodProgram());
  gl::RenderTarget rt = gl::RenderTarget::create({64, 64});
  GpuMesh mesh = GpuMesh::upload(triangle(1.0f));
  rt.bind();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  gl::Query query = gl::Query::make();
  glBeginQuery(GL_PRIMITIVES_GENERATED, query.get());
  prog->use();
  mesh.draw(Primitive::Patches);
  glEndQuery(GL_PRIMITIVES_GENERATED);
  GLuint primitives = 0;
  glGetQueryObjectuiv(query.get(), GL_QUERY_RESULT, &primitives);
  // Level 4 makes two concentric rings: 3 (4 + 2) + 3 (2 + 0) = 24 triangles.
  EXPECT_EQ(primitives, 24u);
  const size_t covered = coveredPixels(rt);
  EXPECT_NEAR(double(covered), 64.0 * 64.0 / 2.0, 64.0 * 2) << "the patch covers half the target";
  EXPECT_EQ(gl::drainErrors(), "");
}
