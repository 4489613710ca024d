// Driver compile and link logs (Mesa, NVIDIA, AMD/Intel and lines none of them match) mapped back
// to files and lines, with the source line and caret attached and link errors located.
#include "app/shader/compile_log.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::vector<std::filesystem::path> files = {
      shadelab::fuzz::writeScratch("shade.frag",
                                   "#version 330 core\nin vec3 v_normal;\nout vec4 o_color;\n"
                                   "void main() {\n\to_color = vec4(v_normal, 1.0);\n}\n"),
      shadelab::fuzz::writeScratch("lighting.glsl", "float lit(vec3 n) { return n.z; }\n"),
      shadelab::fuzz::writeScratch("empty.glsl", ""),
  };
  auto diags = shadelab::parseCompileLog(shadelab::fuzz::asText(data, size), files);
  shadelab::attachSourceLines(diags);
  shadelab::locateLinkErrors(diags, {{"vertex", {files[1]}}, {"fragment", {files[0], files[2]}}});
  for (auto& d : diags) (void)d.formatWithCaret();
  return 0;
}
