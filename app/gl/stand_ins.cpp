// The driver's references to deleted textures moved onto stand-ins the host keeps (stand_ins.h).
#include "app/gl/stand_ins.h"

#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "app/gl/driver_caveats.h"

namespace gl {

namespace {

// Makes `previous` current again, unless it went when it stopped being current: a program deleted
// while in use lives only as long as it stays so, and naming it afterwards is GL_INVALID_VALUE.
void restoreProgram(GLint previous) { glUseProgram(glIsProgram(GLuint(previous)) ? GLuint(previous) : 0); }

constexpr int kUnits = 16;  // the texture units every stage is sure to have

// The program of these stages, its samplers u_unit0-15 (if it has them) on units 0-15; empty if it
// does not link.
ProgramName linkedProgram(const std::vector<std::pair<GLenum, std::string>>& stages) {
  ProgramName program = ProgramName::make();
  for (const auto& [type, source] : stages) {
    const GLuint shader = glCreateShader(type);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    glAttachShader(program.get(), shader);
    glDeleteShader(shader);
  }
  glLinkProgram(program.get());
  GLint linked = 0, previous = 0;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &linked);
  if (!linked) return {};
  glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
  glUseProgram(program.get());
  for (int u = 0; u < kUnits; ++u)
    glUniform1i(glGetUniformLocation(program.get(), ("u_unit" + std::to_string(u)).c_str()), u);
  restoreProgram(previous);
  return program;
}

// GLSL declaring the sixteen units' samplers, and an expression summing a lookup of each (an
// explicit level: vertex and tessellation stages have no derivatives).
std::string unitSamplers() {
  std::string out;
  for (int u = 0; u < kUnits; ++u) out += "uniform sampler2D u_unit" + std::to_string(u) + ";\n";
  return out;
}
std::string sumOfUnits() {
  std::string out = "vec4(0.0)";
  for (int u = 0; u < kUnits; ++u) out += " + textureLod(u_unit" + std::to_string(u) + ", vec2(0.5), 0.0)";
  return out;
}

// A triangle covering the viewport, from gl_VertexID.
constexpr const char* kCorner = "vec4(vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0, 0.0, 1.0)";

// The stand-ins' sampling programs: one whose fragment stage samples every unit; where the
// context has tessellation, a second one whose evaluation stage does (its sum goes to the colour
// written, so no compiler drops a lookup).
std::vector<std::vector<std::pair<GLenum, std::string>>> samplingPrograms() {
  const std::string vertex = std::string("#version 330 core\nvoid main() { gl_Position = ") + kCorner + "; }\n";
  const std::string fragment =
      "#version 330 core\n" + unitSamplers() + "out vec4 o_color;\nvoid main() { o_color = " + sumOfUnits() + "; }\n";
  std::vector<std::vector<std::pair<GLenum, std::string>>> programs = {
      {{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}};
  if (hasTessellation()) {
    programs.push_back(
        {{GL_VERTEX_SHADER, std::string("#version 400 core\nvoid main() { gl_Position = ") + kCorner + "; }\n"},
         {GL_TESS_CONTROL_SHADER,
          "#version 400 core\nlayout(vertices = 3) out;\nvoid main() {\n"
          "  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;\n"
          "  gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelInner[0] = 1.0;\n}\n"},
         {GL_TESS_EVALUATION_SHADER,
          "#version 400 core\nlayout(triangles) in;\n" + unitSamplers() +
              "out vec4 v_sum;\nvoid main() {\n  v_sum = " + sumOfUnits() +
              ";\n  gl_Position = gl_TessCoord.x * gl_in[0].gl_Position + gl_TessCoord.y * gl_in[1].gl_Position + "
              "gl_TessCoord.z * gl_in[2].gl_Position;\n}\n"},
         {GL_FRAGMENT_SHADER,
          "#version 400 core\nin vec4 v_sum;\nout vec4 o_color;\nvoid main() { o_color = v_sum; }\n"}});
  }
  return programs;
}

// A loop of `u_work` dependent steps per pixel: a scene that keeps the rasteriser busy.
constexpr const char* kLongSceneFragment = R"(#version 330 core
uniform int u_work;
out vec4 o_color;
void main() {
  float s = gl_FragCoord.x;
  for (int i = 0; i < u_work; ++i) s = sin(s) * 1.01 + 0.5;
  o_color = vec4(s);
}
)";

// What a lab may leave set that would keep the stand-ins' draws and clears from reaching a pixel
// (the front-face culling of a shadow pass, a scissor, a colour mask): off while this lives, and
// as it was after, with the program and vertex array bound.
class PlainRaster {
 public:
  PlainRaster() {
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
    for (size_t i = 0; i < std::size(kCaps); ++i) {
      enabled_[i] = glIsEnabled(kCaps[i]);
      glDisable(kCaps[i]);
    }
    glGetBooleanv(GL_COLOR_WRITEMASK, mask_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  ~PlainRaster() {
    for (size_t i = 0; i < std::size(kCaps); ++i)
      if (enabled_[i]) glEnable(kCaps[i]);
    glColorMask(mask_[0], mask_[1], mask_[2], mask_[3]);
    glBindVertexArray(GLuint(vao_));
    restoreProgram(program_);
  }
  PlainRaster(const PlainRaster&) = delete;
  PlainRaster& operator=(const PlainRaster&) = delete;

 private:
  static constexpr GLenum kCaps[] = {GL_SCISSOR_TEST, GL_DEPTH_TEST, GL_STENCIL_TEST,
                                     GL_BLEND,        GL_CULL_FACE,  GL_RASTERIZER_DISCARD};
  GLboolean enabled_[std::size(kCaps)] = {};
  GLboolean mask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
  GLint program_ = 0, vao_ = 0;
};

}  // namespace

// Big enough that the rasteriser threads get tiles of them (llvmpipe's threads hold their own);
// one byte a texel (3 MB).
constexpr int kSide = 512, kLayers = 8, kLevels = 3;  // as many layers as a lab's arrays have (cascades: 4)

DriverStandIns::DriverStandIns()
    : plain_(TextureName::make()),
      array_(TextureName::make()),
      texel_(TextureName::make()),
      framebuffer_(FramebufferName::make()),
      vao_(VertexArray::make()) {
  if (!esContext())  // OpenGL ES and WebGL do not keep the last draw's textures
    for (const auto& stages : samplingPrograms())
      if (ProgramName program = linkedProgram(stages)) programs_.push_back({std::move(program), stages.size() > 2});
  if (applies(Caveat::HeldScenes)) {
    sceneTarget_ = TextureName::make();
    sceneFramebuffer_ = FramebufferName::make();
    longScene_ = linkedProgram(
        {{GL_VERTEX_SHADER, std::string("#version 330 core\nvoid main() { gl_Position = ") + kCorner + "; }\n"},
         {GL_FRAGMENT_SHADER, kLongSceneFragment}});
  }
  GLint texture2d = 0, textureArray = 0, framebuffer = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture2d);
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &textureArray);
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
  const uint8_t zero = 0;
  glBindTexture(GL_TEXTURE_2D, texel_.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, 1, 1, 0, GL_RED, GL_UNSIGNED_BYTE, &zero);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, plain_.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, kSide, kSide, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D_ARRAY, array_.get());
  for (int level = 0; level < kLevels; ++level)
    glTexImage3D(GL_TEXTURE_2D_ARRAY, level, GL_R8, kSide >> level, kSide >> level, kLayers, 0, GL_RED,
                 GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, kLevels - 1);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, plain_.get(), 0);
  if (sceneTarget_) {
    glBindTexture(GL_TEXTURE_2D, sceneTarget_.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, 1, 1, 0, GL_RED, GL_UNSIGNED_BYTE, &zero);
    glBindFramebuffer(GL_FRAMEBUFFER, sceneFramebuffer_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, sceneTarget_.get(), 0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer));
  glBindTexture(GL_TEXTURE_2D_ARRAY, GLuint(textureArray));
  glBindTexture(GL_TEXTURE_2D, GLuint(texture2d));
}

void DriverStandIns::takeDriverReferences() {
  noteWorkaround(Caveat::HeldTextures);
  const PlainRaster plain;
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, kSide, kSide);
  glBindTexture(GL_TEXTURE_2D_ARRAY, array_.get());
  handOutEveryScene();
  // The references per unit move with one draw. Those per rasteriser thread move only for a thread
  // that takes tiles of the clear and of the mipmaps, which is up to the threads: so the clear and
  // the mipmaps are made in rounds, each finished before the next, each another chance for every
  // thread.
  drawSamplingEveryUnit();
  constexpr int kRounds = 3;
  for (int round = 0; round < kRounds; ++round) {
    glClear(GL_COLOR_BUFFER_BIT);
    glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
    glFinish();
  }
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

void DriverStandIns::handOutEveryScene() {
  if (!longScene_) return;
  noteWorkaround(Caveat::HeldScenes);
  // Mesa 22.3 makes at most 64 scenes, and once it has 64 it waits for the first and reuses only
  // that one: the rest are never reached again and every flush waits for the one before. So this
  // never asks for more than 48 behind the long one, and a pool it grows stays below 64.
  constexpr int kScenes = 48;
  glUseProgram(longScene_.get());
  glBindVertexArray(vao_.get());
  const GLint work = glGetUniformLocation(longScene_.get(), "u_work");
  // 32 steps on 512^2 pixels outlast the 48 flushes on two cores (the whole walk: 12-22 ms a lab
  // switch); a machine that draws it sooner gets one more round, four times as long.
  for (int steps = 32; steps <= 128; steps *= 4) {
    glUniform1i(work, steps);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const GLsync longScene = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);  // flushes it
    // Cleared scenes of a target of their own: clearing the long scene's would wait for it.
    glBindFramebuffer(GL_FRAMEBUFFER, sceneFramebuffer_.get());
    int handedOut = 0;
    for (; handedOut < kScenes; ++handedOut) {
      glClear(GL_COLOR_BUFFER_BIT);
      glFlush();
      if (glClientWaitSync(longScene, 0, 0) != GL_TIMEOUT_EXPIRED) break;  // drawn: the next would reuse it
    }
    glDeleteSync(longScene);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    if (handedOut == kScenes) break;
  }
  glFinish();
}

void DriverStandIns::drawSamplingEveryUnit() {
  GLint previousUnit = 0, previousPatch = 3;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &previousUnit);
  if (hasTessellation()) glGetIntegerv(GL_PATCH_VERTICES, &previousPatch);
  for (int u = 0; u < kUnits; ++u) {
    glActiveTexture(GLenum(GL_TEXTURE0 + u));
    glBindTexture(GL_TEXTURE_2D, texel_.get());
    glBindSampler(GLuint(u), 0);
  }
  glBindVertexArray(vao_.get());
  glViewport(0, 0, 1, 1);
  for (const SamplingProgram& p : programs_) {
    glUseProgram(p.program.get());
    if (p.patches) {
      glPatchParameteri(GL_PATCH_VERTICES, 3);
      glDrawArrays(GL_PATCHES, 0, 3);
    } else {
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
  }
  for (int u = 0; u < kUnits; ++u) {
    glActiveTexture(GLenum(GL_TEXTURE0 + u));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glActiveTexture(GLenum(previousUnit));
  if (hasTessellation()) glPatchParameteri(GL_PATCH_VERTICES, previousPatch);
}

}  // namespace gl
