// The pixel trace's storage buffer, where the desktop's GL has one (grade/pixel_trace.h).
#include <cstring>

#include "app/gl/gl.h"
#include "app/gl/handle.h"
#include "app/grade/pixel_trace.h"

namespace shadelab {

bool pixelTraceSupported(std::string& why) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  bool storage = false;
  for (GLint i = 0; i < count && !storage; ++i)
    storage = std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))),
                          "GL_ARB_shader_storage_buffer_object") == 0;
  if (!storage || !glMemoryBarrier) {
    why = "this driver has no shader storage buffers (GL 4.3 or GL_ARB_shader_storage_buffer_object)";
    return false;
  }
  return true;
}

std::string drawIntoStorageBuffer(unsigned binding, std::vector<float>& data, const std::function<void()>& draw) {
  if (std::string why; !pixelTraceSupported(why)) return why;
  const GLsizeiptr bytes = GLsizeiptr(data.size() * sizeof(float));
  const gl::Buffer buffer = gl::Buffer::make();
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.get());
  glBufferData(GL_SHADER_STORAGE_BUFFER, bytes, data.data(), GL_STREAM_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer.get());
  draw();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the shaders' writes seen by the read below
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.get());
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, bytes, data.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  return {};
}

}  // namespace shadelab
