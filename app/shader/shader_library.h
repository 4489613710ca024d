// Programs built from files on the shader search path, cached by (stages, defines), rebuilt
// when any file they read changes on disk. A failed rebuild keeps the last good program; a
// program that never compiled draws the library's loud fallback instead of nothing.
//
// The library keeps the most recently used programs alive after their last user lets go, so
// switching a variant and back is instant and, while a student's file is broken, shows that
// variant's last good program rather than a fallback compiled from the broken file.
#pragma once
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "app/gl/handle.h"
#include "app/shader/compile_log.h"
#include "app/shader/file_watcher.h"
#include "app/shader/preprocessor.h"

namespace shadelab {

struct StageSource {
  GLenum type;       // GL_VERTEX_SHADER, ...
  std::string path;  // relative to the search roots, e.g. "shading/shade.frag"
};

struct ProgramSpec {
  std::string name;  // for messages: "shading/phong"
  std::vector<StageSource> stages;
  Defines defines;
  std::string key() const;
};

class Program {
 public:
  // Binds the last good program, or the fallback if this one never compiled.
  void use();
  bool hasGoodProgram() const { return bool(good_); }
  bool lastBuildFailed() const { return !diagnostics_.empty() && hasErrors_; }
  int generation() const { return generation_; }  // successful builds so far
  const ProgramSpec& spec() const { return spec_; }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  const std::vector<std::filesystem::path>& files() const { return files_; }
  // The same files as the program asks for them ("shading/shade.frag", "common/lighting.glsl").
  const std::vector<std::string>& relPaths() const { return relPaths_; }

  // Whether the program reads the uniform `name` (the compiler drops the ones it does not): a lab
  // binds textures only for the samplers its current variant really samples.
  bool uses(const char* name) { return location(name) >= 0; }
  // Uniforms of the bound program; names it does not use are ignored (as GL does for -1). With
  // uniform checks on (uniformChecks()) and the program built from the built-in files alone, a
  // name that appears nowhere in its preprocessed stages throws UnknownUniform instead: a misspelt
  // name would otherwise leave the uniform at zero without a word. A name the compiler dropped
  // (declared, unused in this variant) is fine, and so is any name once a student's file stands in
  // (a shader of their own need not read everything the lab offers).
  void set(const char* name, int v);
  void set(const char* name, float v);
  void set(const char* name, const glm::vec2& v);
  void set(const char* name, const glm::vec3& v);
  void set(const char* name, const glm::vec4& v);
  void set(const char* name, const glm::mat3& v);
  void set(const char* name, const glm::mat4& v);
  // Uniform arrays in one call; `name` is the array's name ("u_poisson").
  void setArray(const char* name, const glm::vec2* v, int count);
  void setArray(const char* name, const glm::vec3* v, int count);
  void setArray(const char* name, const glm::mat4* v, int count);
  // The uniforms the lab has set on this program (names as set, array elements and struct members
  // by their base name, "u_key"), in order: what a student's shader can read (the Shaders panel).
  const std::vector<std::string>& uniformsSet() const { return uniformsSet_; }

 private:
  friend class ShaderLibrary;
  GLint location(const char* name);

  ProgramSpec spec_;
  gl::ProgramName good_;
  GLuint fallback_ = 0;
  GLuint bound_ = 0;
  std::unordered_map<std::string, GLint> locations_;  // of bound_
  std::string source_;                                // the good build's stages, preprocessed
  bool builtinFiles_ = false;                         // ... read from the built-in folder alone
  std::vector<std::string> uniformsSet_;
  std::vector<std::filesystem::path> files_;
  std::vector<std::string> relPaths_;
  size_t sourceHash_ = 0;
  int generation_ = 0;
  bool hasErrors_ = false;
  std::vector<Diagnostic> diagnostics_;
  bool builtinOnly_ = false;  // built from the built-in folder alone (ShaderLibrary::BuiltinOnly)
};

using ProgramRef = std::shared_ptr<Program>;

// Uniform checks: on in debug builds, and wherever SHADELAB_CHECK_UNIFORMS=1 (the test suite sets
// it); off in a release build's window, where a student's shader that drops a declaration must
// not stop the lab.
bool uniformChecks();
void setUniformChecks(bool on);
struct UnknownUniform : std::logic_error {
  using std::logic_error::logic_error;
};
// Whether `name` ("u_key.viewProj", "u_disk[3]") could name a uniform of `source`: its base name
// and any member appear there as whole words.
bool sourceMentionsUniform(const std::string& source, const std::string& name);

class ShaderLibrary {
 public:
  // Needs a current GL context (it builds the fallback program at once).
  explicit ShaderLibrary(ShaderSearchPath path);
  ~ShaderLibrary();

  // Built on first request. Programs live while someone holds the reference.
  ProgramRef program(const ProgramSpec& spec);
  // Ground truths are drawn with the built-in shaders, never with the student's files they
  // judge: while a BuiltinOnly lives, program() builds and serves programs from the built-in
  // folder alone (no student folder, no dropped file), cached apart from the others.
  class BuiltinOnly {
   public:
    explicit BuiltinOnly(ShaderLibrary& library) : library_(library), was_(library.builtinOnly_) {
      library.builtinOnly_ = true;
    }
    ~BuiltinOnly() { library_.builtinOnly_ = was_; }
    BuiltinOnly(const BuiltinOnly&) = delete;
    BuiltinOnly& operator=(const BuiltinOnly&) = delete;

   private:
    ShaderLibrary& library_;
    bool was_;
  };
  // The cache key of `spec` in the current mode (ProgramSlot refetches when it changes).
  std::string keyOf(const ProgramSpec& spec) const { return (builtinOnly_ ? "builtin|" : "") + spec.key(); }
  // Polls the file watcher and rebuilds every live program that reads a changed file.
  // Returns how many programs were rebuilt (successfully or not).
  int reloadChanged();
  // Recompiles now; false when it failed (the last good program stays).
  bool rebuild(Program& p, bool force = false);
  // Serves `file` wherever a shader asks for a file of the same name (a file dropped on the
  // window). Where several programs' files share the name (two labs' lit.frag), the dropped
  // file's own path decides (".../shadows/lit.frag"); if it cannot, nothing changes and
  // `error` says which files it could mean.
  struct OverrideResult {
    std::string replaced;  // the relative path now served by the file, or ""
    std::string error;     // no live program uses that name, or it is ambiguous
  };
  OverrideResult overrideByName(const std::filesystem::path& file);
  // Lets the recently used programs go (a lab switch: the old lab's variants are of no use).
  void forgetRecent() { recent_.clear(); }

  std::vector<ProgramRef> livePrograms() const;
  const ShaderSearchPath& searchPath() const { return path_; }
  // Called for every diagnostic of a failed build; default: one line to stderr.
  std::function<void(const Diagnostic&)> onDiagnostic;

 private:
  void watchFiles(const Program& p);
  // Every diagnostic goes to onDiagnostic once until a file changes: one broken include is one
  // message, not one per variant that includes it.
  void report(const std::vector<Diagnostic>& diagnostics);
  const ShaderSearchPath& pathOf(const Program& p) const { return p.builtinOnly_ ? builtinPath_ : path_; }
  ShaderSearchPath path_;
  ShaderSearchPath builtinPath_;
  bool builtinOnly_ = false;
  FileWatcher watcher_;
  gl::ProgramName fallback_;
  std::map<std::string, std::weak_ptr<Program>> cache_;
  std::deque<ProgramRef> recent_;  // most recently requested first, at most kRecent
  static constexpr size_t kRecent = 16;
  std::set<std::string> reported_;
};

// The program a lab uses for one role (a pass, a variant), re-fetched only when the spec changes:
// `slot.get(library, spec)` each frame costs a key compare, not a library lookup.
class ProgramSlot {
 public:
  Program& get(ShaderLibrary& library, const ProgramSpec& spec);
  const ProgramRef& current() const { return program_; }
  void reset() {
    program_.reset();
    key_.clear();
  }

 private:
  std::string key_;
  ProgramRef program_;
};

// The programs of these slots that hold one: a lab's activePrograms().
std::vector<ProgramRef> heldPrograms(std::span<const ProgramSlot> slots);

GLenum stageFromExtension(const std::string& path);  // .vert .geom .frag .tesc .tese .comp; 0 if unknown
const char* stageName(GLenum type);                  // "vertex", "fragment", ... as drivers' logs say

// Distinct programs (told apart by their preprocessed sources) this process has linked. A driver
// may keep memory for every program it ever compiled: llvmpipe keeps each constant its LLVM
// compiler made until the context goes (about 1 KB a program), so memory that rises with this
// count is the driver meeting new programs, not a leak. The soak records it on every lab entry.
size_t distinctProgramsLinked();

}  // namespace shadelab
