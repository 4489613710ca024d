// Driver compile/link logs -> file:line:col diagnostics. Three dialects:
//   Mesa           0:12(5): error: `foo' undeclared
//   NVIDIA         0(12) : error C1008: undefined variable "foo"
//   AMD / Intel    ERROR: 0:12: 'foo' : undeclared identifier
// The leading number is the #line source-string index the preprocessor assigned to a file.
// Lines that match none of these are kept verbatim (line 0), never dropped.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab {

struct Diagnostic {
  std::string file;  // resolved path, or "" when the log line named none
  int line = 0;      // 1-based; 0 = unknown
  int column = 0;    // 1-based; 0 = unknown
  bool isError = true;
  std::string message;
  std::string raw;         // the driver's line as it was
  std::string sourceLine;  // the offending line of the real file, when known

  // "shaders/shading/shade.frag:12:5: error: message"
  std::string format() const;
  // format(), then the source line and a caret under the column (when they are known).
  std::string formatWithCaret() const;
};

std::vector<Diagnostic> parseCompileLog(std::string_view log, const std::vector<std::filesystem::path>& files);

// Reads the offending source line into each diagnostic (for the panel's caret view).
void attachSourceLines(std::vector<Diagnostic>& diags);

// Link errors carry no line ("fragment shader input `v_normal' has no matching output"). Where one
// names an identifier, find where a stage's files declare it, the stage the message names first,
// and point the diagnostic there.
struct StageFiles {
  std::string stage;  // "vertex", "fragment", "geometry", "tessellation control", ...
  std::vector<std::filesystem::path> files;
};
void locateLinkErrors(std::vector<Diagnostic>& diags, const std::vector<StageFiles>& stages);

}  // namespace shadelab
