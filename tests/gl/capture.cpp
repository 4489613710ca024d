// Test helpers of gl_test.h: golden images, transform-feedback capture of a vertex stage's output.
#include <gtest/gtest.h>

#include <cstdlib>

#include "app/scene/gpu_mesh.h"
#include "app/shader/preprocessor.h"
#include "gl_test.h"

namespace shadelab::test {

void expectGolden(const std::string& name, const ImageF& actual) {
  ASSERT_EQ(countNonFinite(actual), 0u) << name;
  const std::string golden = std::string(SHADELAB_GOLDEN_DIR) + "/" + name + ".png";
  if (std::getenv("SHADELAB_UPDATE_GOLDEN")) {
    ASSERT_EQ(writePng(golden, actual), "");
    GTEST_SKIP() << "updated " << golden;
  }
  ImageF expected;
  ASSERT_EQ(readImage(golden, expected), "") << "run with SHADELAB_UPDATE_GOLDEN=1 to create " << golden;
  const ImageError e = compareImages(actual, expected, 0.2);
  if (e.meanError > 0.004 || e.badPixelPct > 0.5) {
    writePng(testOutput(name + "_actual.png"), actual);
    writePng(testOutput(name + "_diff.png"), diffImage(actual, expected));
  }
  EXPECT_LE(e.meanError, 0.004) << name;
  EXPECT_LE(e.badPixelPct, 0.5) << name;
}

std::vector<glm::vec3> captureVertexOutput(const std::string& relPath, const Defines& defines, const char* varying,
                                           const GpuMesh& mesh, const std::function<void(GLuint)>& uniforms) {
  const PreprocessedSource src = preprocessShader(builtinShaders(), relPath, defines);
  EXPECT_TRUE(src.ok()) << src.error;
  gl::ShaderName vs = gl::ShaderName::make(GL_VERTEX_SHADER);
  const char* text = src.text.c_str();
  glShaderSource(vs.get(), 1, &text, nullptr);
  glCompileShader(vs.get());
  GLint ok = 0;
  glGetShaderiv(vs.get(), GL_COMPILE_STATUS, &ok);
  EXPECT_TRUE(ok) << relPath << " did not compile";
  gl::ProgramName program = gl::ProgramName::make();
  glAttachShader(program.get(), vs.get());
  glTransformFeedbackVaryings(program.get(), 1, &varying, GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(program.get());
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  EXPECT_TRUE(ok) << relPath << " did not link for capture";
  glDetachShader(program.get(), vs.get());

  std::vector<glm::vec3> out(mesh.vertexCount());
  gl::Buffer captured = gl::Buffer::make();
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, captured.get());
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(out.size() * sizeof(glm::vec3)), nullptr, GL_STATIC_READ);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captured.get());
  glUseProgram(program.get());
  uniforms(program.get());
  glEnable(GL_RASTERIZER_DISCARD);
  glBeginTransformFeedback(GL_POINTS);
  mesh.draw(Primitive::Points);
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(out.size() * sizeof(glm::vec3)), out.data());
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  glUseProgram(0);
  glBindVertexArray(0);
  return out;
}

}  // namespace shadelab::test
