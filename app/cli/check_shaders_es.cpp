// shadelab check-shaders --dialect es: every program of every lab as the page compiles it (GLSL ES
// 3.00: the preprocessor's #version 300 es, precision statements and flattened interface blocks),
// checked by Khronos' reference compiler, glslangValidator, since the desktop's driver compiles
// only desktop GLSL. Programs with geometry or tessellation stages are never drawn in WebGL2 (the
// labs draw their equivalents there: the six-pass cube, unwelded faces, the CPU's cut), so they are
// counted apart, not compiled.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "app/cli/commands.h"
#include "app/cli/session.h"
#include "app/lab/lab.h"
#include "app/shader/compile_log.h"
#include "app/shader/preprocessor.h"
#include "app/shader/shader_library.h"
#include "app/util/output_files.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

const char* stageExtension(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER:
      return "vert";
    case GL_FRAGMENT_SHADER:
      return "frag";
    default:
      return nullptr;  // no such stage in GLSL ES 3.00
  }
}

// glslangValidator's verdict on one stage's text: "" when it compiles, else its diagnostics at the
// real files' lines (the preprocessor's #line numbers name them).
std::string validate(const fs::path& dir, const PreprocessedSource& src, const char* extension) {
  const fs::path file = dir / (std::string("stage.") + extension);
  if (auto e = writeTextFile(file.string(), src.text); !e.empty()) return e;
  const std::string command = "glslangValidator '" + file.string() + "' 2>&1";
  std::string log;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buffer[4096];
    for (size_t n; (n = fread(buffer, 1, sizeof buffer, p)) > 0;) log.append(buffer, n);
    if (pclose(p) == 0) return {};
  } else {
    return "could not run glslangValidator";
  }
  std::string out;
  std::vector<Diagnostic> diags = parseCompileLog(log, src.files);
  attachSourceLines(diags);
  for (auto& d : diags) {
    // After the first error the validator stops inside whatever #ifdef it was in: what it says
    // then is the aftermath, not the student's.
    if (d.message.find("compilation terminated") != std::string::npos) break;
    if (!out.empty() && d.message.find("missing #endif") != std::string::npos) continue;
    if (d.line == 0 &&
        (d.raw.empty() || d.raw == file.string() || d.raw.find("compilation errors") != std::string::npos))
      continue;  // the validator's own header and summary lines
    out += d.formatWithCaret() + "\n";
  }
  return out.empty() ? log : out;
}

}  // namespace

int runCheckShadersEs(const Options& o) {
  if (std::system("glslangValidator --version >/dev/null 2>&1") != 0)
    return fail(
        "check-shaders --dialect es needs glslangValidator (Debian's glslang-tools: tools/install_deps.sh test)");
  std::string err;
  auto context = createHeadlessContext(o.backend, err);  // the labs ask the context what it has
  if (!context) return fail(err);
  const ShaderSearchPath path = shaderSearchPath(o);
  const fs::path dir = fs::temp_directory_path() / ("shadelab-es-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  setGlslDialect(GlslDialect::Es300);
  std::map<std::string, std::string> verdicts;  // stage text -> diagnostics: variants share stages
  int programs = 0, failed = 0, desktopOnly = 0, stages = 0;
  for (auto& id : labIds()) {
    if (!o.lab.empty() && id != o.lab) continue;
    for (auto& spec : makeLab(id)->allPrograms()) {
      bool esStages = true;
      for (auto& stage : spec.stages) esStages &= stageExtension(stage.type) != nullptr;
      if (!esStages) {
        ++desktopOnly;
        continue;
      }
      ++programs;
      std::string errors;
      for (auto& stage : spec.stages) {
        const PreprocessedSource src = preprocessShader(path, stage.path, spec.defines);
        if (!src.ok()) {
          errors += src.error + "\n";
          continue;
        }
        auto [it, added] = verdicts.emplace(src.text, std::string());
        if (added) {
          ++stages;
          it->second = validate(dir, src, stageExtension(stage.type));
        }
        errors += it->second;
      }
      if (!errors.empty()) {
        ++failed;
        std::string defines;
        for (auto& [n, v] : spec.defines) defines += " " + n + "=" + v;
        std::fprintf(stderr, "%sFAIL %s (GLSL ES 3.00):%s\n", errors.c_str(), spec.name.c_str(), defines.c_str());
      }
    }
  }
  setGlslDialect(GlslDialect::Desktop);
  std::error_code ec;
  fs::remove_all(dir, ec);
  std::printf(
      "check-shaders: %d programs, %d failed (GLSL ES 3.00, glslangValidator: %d distinct stages); %d with "
      "geometry or tessellation stages are desktop-only\n",
      programs, failed, stages, desktopOnly);
  return failed ? 1 : 0;
}

}  // namespace shadelab
