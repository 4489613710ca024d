#include "app/shader/shader_library.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <unordered_set>

#include <glm/gtc/type_ptr.hpp>

#include "app/shader/function_parts.h"

namespace fs = std::filesystem;

namespace shadelab {
namespace {

// The loud fallback: a magenta/black screen-space checker. Kept in C++ on purpose: it must
// work when the shader folder itself is broken or missing. Its version line is the dialect's
// (versionPreamble): in the page it is GLSL ES 3.00 like every other program.
const char* kFallbackVs = R"(
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_viewProj;
void main() { gl_Position = u_viewProj * u_model * vec4(a_position, 1.0); }
)";
const char* kFallbackFs = R"(
out vec4 o_color;
void main() {
  ivec2 cell = ivec2(gl_FragCoord.xy) / 16;
  o_color = ((cell.x + cell.y) & 1) == 0 ? vec4(1.0, 0.0, 1.0, 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
}
)";

std::string infoLog(GLuint object, bool isProgram) {
  GLint len = 0;
  isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &len) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &len);
  std::string log(size_t(std::max(len, 1)), '\0');
  isProgram ? glGetProgramInfoLog(object, len, nullptr, log.data())
            : glGetShaderInfoLog(object, len, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

// Compiles and links; on failure returns an empty name and fills `log`.
gl::ProgramName buildProgram(const std::vector<std::pair<GLenum, std::string>>& sources, std::vector<std::string>& logs,
                             int& failedStage) {
  gl::ProgramName program = gl::ProgramName::make();
  std::vector<gl::ShaderName> shaders;
  failedStage = -1;
  for (size_t i = 0; i < sources.size(); ++i) {
    gl::ShaderName s = gl::ShaderName::make(sources[i].first);
    const char* text = sources[i].second.c_str();
    glShaderSource(s.get(), 1, &text, nullptr);
    glCompileShader(s.get());
    GLint ok = 0;
    glGetShaderiv(s.get(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      logs.push_back(infoLog(s.get(), false));
      failedStage = int(i);
      return {};
    }
    glAttachShader(program.get(), s.get());
    shaders.push_back(std::move(s));
  }
  glLinkProgram(program.get());
  GLint ok = 0;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  for (auto& s : shaders) glDetachShader(program.get(), s.get());
  if (!ok) {
    logs.push_back(infoLog(program.get(), true));
    return {};
  }
  return program;
}

// The hashes of every program linked so far (the GL thread's alone: programs are built there).
std::unordered_set<size_t>& linkedSources() {
  static std::unordered_set<size_t> seen;
  return seen;
}

}  // namespace

size_t distinctProgramsLinked() { return linkedSources().size(); }

const char* stageName(GLenum type) {
  switch (type) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_GEOMETRY_SHADER:
      return "geometry";
    case GL_TESS_CONTROL_SHADER:
      return "tessellation control";
    case GL_TESS_EVALUATION_SHADER:
      return "tessellation evaluation";
    case GL_COMPUTE_SHADER:
      return "compute";
    default:
      return "unknown";
  }
}

GLenum stageFromExtension(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".vert") return GL_VERTEX_SHADER;
  if (ext == ".frag") return GL_FRAGMENT_SHADER;
  if (ext == ".geom") return GL_GEOMETRY_SHADER;
  if (ext == ".tesc") return GL_TESS_CONTROL_SHADER;
  if (ext == ".tese") return GL_TESS_EVALUATION_SHADER;
  if (ext == ".comp") return GL_COMPUTE_SHADER;
  return 0;
}

std::string ProgramSpec::key() const {
  std::string k;
  for (auto& s : stages) k += s.path + "|";
  for (auto& [n, v] : defines) k += n + "=" + v + ";";
  return k;
}

void Program::use() {
  const GLuint id = good_ ? good_.get() : fallback_;
  if (id != bound_) {
    locations_.clear();
    bound_ = id;
  }
  glUseProgram(id);
}

namespace {

std::optional<bool>& uniformChecksSetting() {
  static std::optional<bool> on;
  return on;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool mentionsWord(const std::string& text, std::string_view word) {
  if (word.empty()) return false;
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool before = at == 0 || !isIdentifierChar(text[at - 1]);
    const bool after = at + word.size() >= text.size() || !isIdentifierChar(text[at + word.size()]);
    if (before && after) return true;
  }
  return false;
}

std::string_view baseName(std::string_view name) { return name.substr(0, name.find_first_of("[.")); }

}  // namespace

bool uniformChecks() {
  auto& on = uniformChecksSetting();
  if (!on) {
#ifndef NDEBUG
    on = true;
#else
    const char* env = std::getenv("SHADELAB_CHECK_UNIFORMS");
    on = env && std::string_view(env) == "1";
#endif
  }
  return *on;
}

void setUniformChecks(bool on) { uniformChecksSetting() = on; }

bool sourceMentionsUniform(const std::string& source, const std::string& name) {
  const std::string_view n(name);
  if (!mentionsWord(source, baseName(n))) return false;
  // Struct members, as in "u_key.viewProj" or "u_cascade[2].layer": each must appear too.
  for (size_t dot = n.find('.'); dot != std::string_view::npos; dot = n.find('.', dot + 1))
    if (!mentionsWord(source, baseName(n.substr(dot + 1)))) return false;
  return true;
}

GLint Program::location(const char* name) {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint at = glGetUniformLocation(bound_, name);
  const std::string base(baseName(name));
  if (std::find(uniformsSet_.begin(), uniformsSet_.end(), base) == uniformsSet_.end()) uniformsSet_.push_back(base);
  if (at < 0 && good_ && bound_ == good_.get() && builtinFiles_ && uniformChecks() &&
      !sourceMentionsUniform(source_, name))
    throw UnknownUniform(spec_.name + ": the lab sets the uniform '" + name +
                         "', which no stage of the program declares (a misspelt name, or one a shader no longer has)");
  return locations_.emplace(name, at).first->second;
}

void Program::set(const char* n, int v) { glUniform1i(location(n), v); }
void Program::set(const char* n, float v) { glUniform1f(location(n), v); }
void Program::set(const char* n, const glm::vec2& v) { glUniform2fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec3& v) { glUniform3fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec4& v) { glUniform4fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::mat3& v) {
  glUniformMatrix3fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) {
  glUniformMatrix4fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}

void Program::setArray(const char* n, const glm::vec2* v, int count) {
  glUniform2fv(location(n), count, glm::value_ptr(v[0]));
}
void Program::setArray(const char* n, const glm::vec3* v, int count) {
  glUniform3fv(location(n), count, glm::value_ptr(v[0]));
}
void Program::setArray(const char* n, const glm::mat4* v, int count) {
  glUniformMatrix4fv(location(n), count, GL_FALSE, glm::value_ptr(v[0]));
}

std::vector<ProgramRef> heldPrograms(std::span<const ProgramSlot> slots) {
  std::vector<ProgramRef> out;
  for (const ProgramSlot& slot : slots)
    if (slot.current()) out.push_back(slot.current());
  return out;
}

ShaderLibrary::ShaderLibrary(ShaderSearchPath path)
    : path_(std::move(path)), builtinPath_(std::vector<fs::path>{builtinShaderDir()}) {
  onDiagnostic = [](const Diagnostic& d) { std::fprintf(stderr, "%s\n", d.format().c_str()); };
  std::vector<std::string> logs;
  int failed = -1;
  const std::string version = versionPreamble("#version 330 core", glslDialect());
  fallback_ = buildProgram({{GL_VERTEX_SHADER, version + kFallbackVs}, {GL_FRAGMENT_SHADER, version + kFallbackFs}},
                           logs, failed);
  if (!fallback_)
    for (auto& l : logs) std::fprintf(stderr, "shadelab: the fallback program did not build: %s\n", l.c_str());
}

ShaderLibrary::~ShaderLibrary() = default;

ProgramRef ShaderLibrary::program(const ProgramSpec& spec) {
  const std::string key = keyOf(spec);
  ProgramRef p;
  if (auto it = cache_.find(key); it != cache_.end()) p = it->second.lock();
  if (!p) {
    p = std::make_shared<Program>();
    p->spec_ = spec;
    p->builtinOnly_ = builtinOnly_;
    p->fallback_ = fallback_.get();
    rebuild(*p, true);
    // Programs nobody holds any more leave their entries behind: sweep them before adding one, so
    // the map stays the size of the live set over any number of variants.
    std::erase_if(cache_, [](const auto& entry) { return entry.second.expired(); });
    cache_[key] = p;
  }
  std::erase(recent_, p);
  recent_.push_front(p);
  if (recent_.size() > kRecent) recent_.pop_back();
  return p;
}

void ShaderLibrary::report(const std::vector<Diagnostic>& diagnostics) {
  for (auto& d : diagnostics)
    if (reported_.insert(d.format()).second) onDiagnostic(d);
}

bool ShaderLibrary::rebuild(Program& p, bool force) {
  std::vector<std::pair<GLenum, std::string>> sources;
  std::vector<PreprocessedSource> pre;
  p.diagnostics_.clear();
  p.hasErrors_ = false;
  p.files_.clear();
  p.relPaths_.clear();
  size_t hash = 0;
  for (auto& stage : p.spec_.stages) {
    pre.push_back(preprocessShader(pathOf(p), stage.path, p.spec_.defines));
    auto& src = pre.back();
    for (size_t i = 0; i < src.files.size(); ++i) {
      p.files_.push_back(src.files[i]);
      p.relPaths_.push_back(src.relPaths[i]);
    }
    if (!src.ok()) {
      Diagnostic d;
      d.file = src.errorFile;
      d.line = src.errorLine;
      d.column = src.errorColumn;
      d.message = src.errorMessage;
      d.raw = src.error;
      p.diagnostics_.push_back(d);
      continue;
    }
    hash = hash * 1099511628211ull ^ std::hash<std::string>{}(src.text);
    sources.emplace_back(stage.type, src.text);
  }
  watchFiles(p);
  if (!p.diagnostics_.empty()) {
    p.hasErrors_ = true;
    attachSourceLines(p.diagnostics_);  // the caret under a missing include's name
    report(p.diagnostics_);
    return false;
  }
  if (!force && p.good_ && hash == p.sourceHash_) return true;  // saved, but nothing changed

  std::vector<std::string> logs;
  int failedStage = -1;
  gl::ProgramName built = buildProgram(sources, logs, failedStage);
  const auto& files = failedStage >= 0 ? pre[size_t(failedStage)].files : pre.front().files;
  for (auto& log : logs)
    for (auto& d : parseCompileLog(log, files)) p.diagnostics_.push_back(std::move(d));
  if (!built && failedStage < 0) {
    // A link error: its log's source-string numbers are not any one stage's. Drop them, and point
    // each message at the declaration of the identifier it names, in the stage it names.
    for (auto& d : p.diagnostics_)
      if (d.line > 0 && d.file.find("source-string") == std::string::npos)
        d = {"", 0, 0, d.isError, d.message, d.raw, ""};
    std::vector<StageFiles> stages;
    for (size_t i = 0; i < p.spec_.stages.size() && i < pre.size(); ++i)
      stages.push_back({stageName(p.spec_.stages[i].type), pre[i].files});
    locateLinkErrors(p.diagnostics_, stages);
  }
  attachSourceLines(p.diagnostics_);
  if (!built) {
    p.hasErrors_ = true;
    if (p.diagnostics_.empty()) p.diagnostics_.push_back({"", 0, 0, true, p.spec_.name + ": link failed", "", ""});
    report(p.diagnostics_);
    return false;
  }
  p.good_ = std::move(built);
  p.source_.clear();
  for (auto& [type, text] : sources) p.source_ += text;
  const fs::path builtin = fs::weakly_canonical(builtinShaderDir());
  p.builtinFiles_ = std::all_of(p.files_.begin(), p.files_.end(), [&](const fs::path& f) {
    const fs::path rel = fs::weakly_canonical(f).lexically_relative(builtin);
    return !rel.empty() && *rel.begin() != "..";
  });
  p.sourceHash_ = hash;
  linkedSources().insert(hash);
  p.bound_ = 0;
  p.locations_.clear();
  ++p.generation_;
  return true;
}

void ShaderLibrary::watchFiles(const Program& p) {
  // Every root's candidate for every file, and for its part file (function_parts.h), so a
  // student's new copy that starts overriding a built-in file or function is picked up too.
  for (auto& rel : p.relPaths_)
    for (auto& root : pathOf(p).roots()) {
      watcher_.watch(root / rel);
      watcher_.watch(root / (rel + std::string(kPartSuffix)));
    }
  for (auto& f : p.files_) watcher_.watch(f);
}

int ShaderLibrary::reloadChanged() {
  const auto changed = watcher_.poll();
  if (changed.empty()) return 0;
  reported_.clear();  // the student saved: every message is news again
  int rebuilt = 0;
  for (auto& p : livePrograms()) {
    bool affected = false;
    for (auto& c : changed) {
      for (auto& rel : p->relPaths_) {
        const std::string name = fs::path(rel).filename().string();
        affected |= c.filename() == name || c.filename() == name + std::string(kPartSuffix);
      }
    }
    if (affected) {
      rebuild(*p);
      ++rebuilt;
    }
  }
  return rebuilt;
}

ShaderLibrary::OverrideResult ShaderLibrary::overrideByName(const fs::path& file) {
  std::set<std::string> candidates;
  for (auto& p : livePrograms())
    for (auto& rel : p->relPaths_)
      if (fs::path(rel).filename() == file.filename()) candidates.insert(rel);
  if (candidates.empty()) return {"", file.filename().string() + ": no shader of the current lab is named so"};
  std::string replaced;
  if (candidates.size() == 1) {
    replaced = *candidates.begin();
  } else {
    // Two files of one name (shading/lit.frag, shadows/lit.frag): the one the dropped file's own
    // path ends with, if exactly one does.
    const std::string dropped = fs::absolute(file).lexically_normal().generic_string();
    std::string list;
    int matches = 0;
    for (auto& rel : candidates) {
      list += (list.empty() ? "" : ", ") + rel;
      if (dropped.size() > rel.size() && dropped.compare(dropped.size() - rel.size(), rel.size(), rel) == 0 &&
          dropped[dropped.size() - rel.size() - 1] == '/') {
        replaced = rel;
        ++matches;
      }
    }
    if (matches != 1)
      return {"", file.filename().string() + " is ambiguous: it could replace " + list +
                      "; drop it from a folder named like the one it replaces (e.g. .../" + *candidates.begin() +
                      "), or use --shaders DIR"};
  }
  path_.overrideFile(replaced, fs::absolute(file));
  reported_.clear();
  for (auto& p : livePrograms()) rebuild(*p, true);
  return {replaced, ""};
}

Program& ProgramSlot::get(ShaderLibrary& library, const ProgramSpec& spec) {
  std::string key = library.keyOf(spec);
  if (!program_ || key != key_) {
    program_ = library.program(spec);
    key_ = std::move(key);
  }
  return *program_;
}

std::vector<ProgramRef> ShaderLibrary::livePrograms() const {
  std::vector<ProgramRef> out;
  for (auto& [key, weak] : cache_)
    if (auto p = weak.lock()) out.push_back(std::move(p));
  return out;
}

}  // namespace shadelab
