// GLSL preprocessing the driver does not do for us: #include, injected #define variants, and
// #line directives so every compiler message points back at the real file and line.
//
// Output layout:   #version ...          (the file's own, kept first as GLSL requires)
//                  #define NAME VALUE    (one per variant define)
//                  #line 2 0             (source-string 0 = the main file, resumes after #version)
//                  ...main file, with each #include replaced by
//                  #line 1 k  <included file k>  #line n+1 parent
//
// Mesa's compiler drops the source-string number from its messages (every error says 0:), so the
// file is carried in the line number too: lines of file k are numbered k * kLinesPerFile + n. A
// driver that reports the source string (NVIDIA, AMD) and one that does not (Mesa) both decode to
// the same file and line (`splitLine`).
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace shadelab {

using Defines = std::vector<std::pair<std::string, std::string>>;

inline constexpr int kLinesPerFile = 100000;
inline int encodeLine(int fileIndex, int line) { return fileIndex * kLinesPerFile + line; }
// A driver's (source string, line) -> (file index, line in that file).
inline std::pair<int, int> splitLine(int sourceString, int line) {
  return line >= kLinesPerFile ? std::pair{line / kLinesPerFile, line % kLinesPerFile} : std::pair{sourceString, line};
}

// Where shader files are looked up, first match wins: the student's folder(s), then shaders/.
//
// The folders are a sandbox: a shader (a student's, graded on a teacher's machine) names files
// only inside them. A name that is absolute, or whose `..` leaves the folder, is refused before
// anything is read; a file that is found is refused too when its real path (symbolic links
// followed, in the file's name or in any folder above it) lies outside the folder that served it.
class ShaderSearchPath {
 public:
  explicit ShaderSearchPath(std::vector<std::filesystem::path> roots = {}) : roots_(std::move(roots)) {}
  void prepend(std::filesystem::path root) { roots_.insert(roots_.begin(), std::move(root)); }
  // A single file that overrides `relPath` wherever it is asked for (a file dropped on the window).
  void overrideFile(std::string relPath, std::filesystem::path file);

  struct Lookup {
    std::filesystem::path file;  // the file that serves the name; empty when none does
    std::string refused;         // why the name may not be read (the sandbox's rule), or ""
  };
  Lookup find(const std::string& relPath) const;
  // The file that serves `relPath`, or empty if none does (or it is refused).
  std::filesystem::path resolve(const std::string& relPath) const { return find(relPath).file; }
  const std::vector<std::filesystem::path>& roots() const { return roots_; }
  const std::vector<std::pair<std::string, std::filesystem::path>>& overrides() const { return overrides_; }

 private:
  std::vector<std::filesystem::path> roots_;
  std::vector<std::pair<std::string, std::filesystem::path>> overrides_;
};

// The built-in shader folder: $SHADELAB_SHADERS, else shaders/ in the source tree.
std::filesystem::path builtinShaderDir();

struct PreprocessedSource {
  std::string text;
  // Source-string number k in #line directives (and so in driver logs) -> the file it names.
  std::vector<std::filesystem::path> files;
  std::vector<std::string> relPaths;  // the same files, as asked for (for the watcher and overrides)
  // When a file or include is missing: where ("file", line, column of the name) and what, and the
  // whole as "file:line:col: error: message".
  std::string error;
  std::string errorFile, errorMessage;
  int errorLine = 0, errorColumn = 0;
  bool ok() const { return error.empty(); }
};

// The one-line rule a refused #include is told.
inline constexpr const char* kSandboxRule = "#include may only name files inside the shader folders";

// Which GLSL the files are compiled as. The files are written in desktop GLSL (#version 330 core
// or 410 core); for OpenGL ES 3.0 / WebGL2 the version line becomes "#version 300 es" with highp
// precision for floats, ints and every sampler type, and SHADELAB_ES is defined (1) for the few
// lines that differ. One dialect per process: the context's.
enum class GlslDialect { Desktop, Es300 };
void setGlslDialect(GlslDialect dialect);
GlslDialect glslDialect();
// The lines that open a shader in `dialect` in place of the file's own #version line.
std::string versionPreamble(const std::string& fileVersionLine, GlslDialect dialect);

// GLSL ES 3.00 has no in/out interface blocks. Each `in|out Block { members } instance;` becomes one
// varying per member named io_member, and `instance.member` becomes io_member: an ES program has a
// vertex and a fragment stage only, whose outputs and inputs then meet by the members' names.
// Heads for the same members under #ifdef/#else are all taken out; lines keep their numbers (the
// heads and the closing line are left empty) and preprocessor lines inside the block stay.
std::string flattenInterfaceBlocks(const std::string& source);

// GLSL allows #extension only before the first declaration; an included file's (outside any #if)
// is moved up to follow the #version line, an empty line left in its place so that every line
// keeps its number.
std::string hoistExtensions(const std::string& source);

PreprocessedSource preprocessShader(const ShaderSearchPath& path, const std::string& relPath, const Defines& defines);

}  // namespace shadelab
