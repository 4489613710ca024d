#include "app/shader/preprocessor.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <map>
#include <regex>

#include "app/shader/function_parts.h"
#include "app/util/contained_path.h"
#include "app/util/read_file.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace shadelab {

fs::path builtinShaderDir() {
  if (const char* env = std::getenv("SHADELAB_SHADERS"); env && *env) return env;
  return fs::path(SHADELAB_SOURCE_DIR) / "shaders";
}

void ShaderSearchPath::overrideFile(std::string relPath, fs::path file) {
  for (auto& [rel, f] : overrides_)
    if (rel == relPath) {
      f = std::move(file);
      return;
    }
  overrides_.emplace_back(std::move(relPath), std::move(file));
}

ShaderSearchPath::Lookup ShaderSearchPath::find(const std::string& relPath) const {
  for (auto& [rel, file] : overrides_)
    if (rel == relPath) return {file, {}};
  const fs::path name = containedName(relPath);
  if (name.empty()) return {{}, kSandboxRule};
  std::error_code ec;
  for (auto& root : roots_) {
    const fs::path candidate = root / name;
    if (!fs::is_regular_file(candidate, ec)) continue;
    if (!realPathInside(root, candidate))
      return {{}, std::string(kSandboxRule) + " (a link leads out of " + root.string() + ")"};
    return {candidate, {}};
  }
  return {};
}

namespace {

// `#include "name"` -> name; anything else -> empty.
std::string includeTarget(const std::string& line) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line.compare(i, 8, "#include") != 0) return {};
  size_t a = line.find('"', i + 8), b = a == std::string::npos ? a : line.find('"', a + 1);
  return (a != std::string::npos && b != std::string::npos) ? line.substr(a + 1, b - a - 1) : std::string("\x01");
}

bool isVersionLine(const std::string& line) {
  size_t i = line.find_first_not_of(" \t");
  return i != std::string::npos && line.compare(i, 8, "#version") == 0;
}

// The largest shader file read: the lab's largest is 16 KB. A student's folder could hold a file
// of gigabytes; it is refused by its size before a byte of it is read.
constexpr uintmax_t kMaxShaderFileBytes = uintmax_t(1) << 20;

// "" and the file's text, or why it is not read.
std::string readShaderFile(const fs::path& file, std::string& text) {
  std::error_code ec;
  uintmax_t bytes = fs::file_size(file, ec);
  if (!ec && bytes <= kMaxShaderFileBytes && readWholeFile(file, text))
    bytes = text.size();  // it may have grown since
  else if (ec || bytes <= kMaxShaderFileBytes)
    return "cannot be read";
  if (bytes <= kMaxShaderFileBytes) return {};
  text.clear();
  char s[96];
  std::snprintf(s, sizeof s, "is %.1f MB; a shader file may be at most %d MB", double(bytes) / (1 << 20),
                int(kMaxShaderFileBytes >> 20));
  return s;
}

void fail(PreprocessedSource& out, std::string file, int line, int column, std::string message) {
  out.errorFile = std::move(file);
  out.errorLine = line;
  out.errorColumn = column;
  out.errorMessage = std::move(message);
  out.error = out.errorFile + (line > 0 ? ":" + std::to_string(line) : "") +
              (column > 0 ? ":" + std::to_string(column) : "") + ": error: " + out.errorMessage;
}

struct Expander {
  const ShaderSearchPath& path;
  PreprocessedSource& out;
  std::vector<std::string> stack;  // rel paths being expanded, to report cycles

  // Includes resolve next to the including file first ("lighting.glsl" from common/), then
  // from the search roots ("common/lighting.glsl"). A name that leaves the folders from both
  // places stays as written, and find() refuses it.
  struct Resolved {
    std::string rel;                 // the name as the search path knows it
    ShaderSearchPath::Lookup found;  // what serves it, or why it may not be read
  };
  Resolved resolveInclude(const std::string& from, const std::string& name) const {
    if (fs::path(name).is_absolute()) return {name, path.find(name)};
    const std::string sibling = (fs::path(from).parent_path() / name).lexically_normal().string();
    if (ShaderSearchPath::Lookup near = path.find(sibling); !near.file.empty() || !near.refused.empty())
      return {sibling, std::move(near)};
    const fs::path normal = fs::path(name).lexically_normal();
    const std::string rel = normal.empty() ? name : normal.string();
    return {rel, path.find(rel)};
  }

  // The part file of `rel` (function_parts.h), where a folder holds one: its functions matched
  // with `text`'s and its file recorded. False (and `out` failed) when it cannot be used.
  struct Parts {
    int index = -1;  // source-string number of the part file; -1: none
    std::string text;
    std::vector<FunctionSpan> base, part;
  };
  bool findParts(const std::string& rel, const std::string& text, Parts& parts) {
    const std::string partRel = rel + std::string(kPartSuffix);
    const ShaderSearchPath::Lookup found = path.find(partRel);
    if (!found.refused.empty()) {
      fail(out, partRel, 0, 0, found.refused);
      return false;
    }
    if (found.file.empty()) return true;
    if (auto why = readShaderFile(found.file, parts.text); !why.empty()) {
      fail(out, found.file.string(), 0, 0, why);
      return false;
    }
    if (auto e = matchParts(text, parts.text, parts.base, parts.part); !e.empty()) {
      const size_t colon = e.find(':');
      fail(out, found.file.string(), std::atoi(e.c_str()), 1, e.substr(colon + 2));
      return false;
    }
    parts.index = int(out.files.size());
    out.files.push_back(found.file);
    out.relPaths.push_back(partRel);
    return true;
  }

  bool expand(const std::string& rel, const std::string& text, int fileIndex, bool isMain) {
    Parts parts;
    if (!findParts(rel, text, parts)) return false;
    std::istringstream in(text);
    std::string line;
    int lineNo = 0, skipThrough = 0;
    bool sawVersion = false;
    while (std::getline(in, line)) {
      ++lineNo;
      if (lineNo <= skipThrough) continue;  // a function the part file replaced
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (auto at = std::find_if(parts.base.begin(), parts.base.end(),
                                 [&](const FunctionSpan& s) { return s.firstLine == lineNo; });
          at != parts.base.end()) {
        const FunctionSpan& replacement = parts.part[size_t(at - parts.base.begin())];
        out.text += "#line " + std::to_string(encodeLine(parts.index, replacement.firstLine)) + " " +
                    std::to_string(parts.index) + "\n";
        out.text += linesOf(parts.text, replacement);
        out.text +=
            "#line " + std::to_string(encodeLine(fileIndex, at->lastLine + 1)) + " " + std::to_string(fileIndex) + "\n";
        skipThrough = at->lastLine;
        continue;
      }
      if (isMain && !sawVersion && isVersionLine(line)) {
        sawVersion = true;
        out.text += '\n';  // already emitted ahead of the defines; an empty line keeps numbering
        continue;
      }
      const std::string target = includeTarget(line);
      if (target.empty()) {
        out.text += line;
        out.text += '\n';
        continue;
      }
      const std::string file = out.files[fileIndex].string();
      const size_t quote = line.find('"');
      const int nameColumn = quote == std::string::npos ? 1 : int(quote) + 2;  // the name, 1-based
      if (target == "\x01") {
        fail(out, file, lineNo, int(line.find('#')) + 1, "#include expects \"file\"");
        return false;
      }
      const auto [incRel, found] = resolveInclude(rel, target);
      for (auto& s : stack)
        if (s == incRel) {
          fail(out, file, lineNo, nameColumn, "#include \"" + target + "\" is circular");
          return false;
        }
      bool already = false;
      for (auto& r : out.relPaths) already |= r == incRel;
      if (!already) {  // every file is included once per program, like #pragma once
        if (!found.refused.empty()) {
          fail(out, file, lineNo, nameColumn, found.refused + ": \"" + target + "\"");
          return false;
        }
        const fs::path file = found.file;
        std::string incText;
        if (file.empty()) {
          fail(out, out.files[fileIndex].string(), lineNo, nameColumn, "cannot find include \"" + target + "\"");
          return false;
        }
        if (auto why = readShaderFile(file, incText); !why.empty()) {
          fail(out, out.files[fileIndex].string(), lineNo, nameColumn,
               "#include \"" + target + "\": " + file.string() + " " + why);
          return false;
        }
        const int k = int(out.files.size());
        out.files.push_back(file);
        out.relPaths.push_back(incRel);
        out.text += "#line " + std::to_string(encodeLine(k, 1)) + " " + std::to_string(k) + "\n";
        stack.push_back(incRel);
        if (!expand(incRel, incText, k, false)) return false;
        stack.pop_back();
      }
      out.text += "#line " + std::to_string(encodeLine(fileIndex, lineNo + 1)) + " " + std::to_string(fileIndex) + "\n";
    }
    return true;
  }
};

}  // namespace

namespace {
std::atomic<GlslDialect> g_dialect{GlslDialect::Desktop};
}  // namespace

void setGlslDialect(GlslDialect dialect) { g_dialect = dialect; }
GlslDialect glslDialect() { return g_dialect; }

std::string versionPreamble(const std::string& fileVersionLine, GlslDialect dialect) {
  if (dialect == GlslDialect::Desktop) return fileVersionLine + "\n";
  std::string out = "#version 300 es\n";
  for (const char* type : {"float", "int", "sampler2D", "sampler3D", "samplerCube", "sampler2DArray", "sampler2DShadow",
                           "samplerCubeShadow", "sampler2DArrayShadow", "isampler2D", "usampler2D"})
    out += std::string("precision highp ") + type + ";\n";
  return out + "#define SHADELAB_ES 1\n";
}

std::string flattenInterfaceBlocks(const std::string& source) {
  static const std::regex open(R"(^\s*(in|out)\s+([A-Za-z_]\w*)\s*\{\s*(//.*)?$)");
  static const std::regex close(R"(^\s*\}\s*([A-Za-z_]\w*)\s*(\[\s*\d*\s*\])?\s*;.*$)");
  static const std::regex member(
      R"(^(\s*)((?:[A-Za-z_]\w*\s+)*?)([A-Za-z_]\w*)\s+([A-Za-z_]\w*)\s*(\[[^\]]*\])?\s*;(.*)$)");
  std::vector<std::string> lines;
  {
    std::istringstream in(source);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  // The patterns are tried only on lines short enough to be a block's head, member or close:
  // std::regex recurses per character, and a student's 100,000-character line overflowed the stack.
  constexpr size_t kLongestBlockLine = 400;
  auto matches = [](const std::string& line, std::smatch& m, const std::regex& re) {
    return line.size() <= kLongestBlockLine && std::regex_match(line, m, re);
  };
  std::vector<std::pair<std::string, std::string>> renames;  // "instance." -> "io_"
  for (size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (!matches(lines[i], m, open)) continue;
    const std::string storage = m[1];
    size_t j = i + 1;
    std::smatch c;
    while (j < lines.size() && !matches(lines[j], c, close)) ++j;
    if (j == lines.size()) break;  // not closed: leave it for the compiler to report
    renames.push_back({std::string(c[1]) + ".", "io_"});
    lines[i] = "";
    lines[j] = "";
    for (size_t k = i + 1; k < j; ++k) {
      std::smatch v;
      const std::string& line = lines[k];
      const size_t first = line.find_first_not_of(" \t");
      if (first == std::string::npos || line[first] == '#' || line.compare(first, 2, "//") == 0) continue;
      if (matches(line, v, open))
        lines[k] = "";  // another head for the same members (#ifdef ... #else)
      else if (matches(line, v, member))
        lines[k] = std::string(v[1]) + std::string(v[2]) + storage + " " + std::string(v[3]) + " io_" +
                   std::string(v[4]) + std::string(v[5]) + ";" + std::string(v[6]);
    }
    i = j;
  }
  std::string out;
  for (auto& line : lines) {
    std::string l = line;
    for (auto& [from, to] : renames) {
      for (size_t at = 0; (at = l.find(from, at)) != std::string::npos;) {
        const bool wordStart = at == 0 || !(std::isalnum(static_cast<unsigned char>(l[at - 1])) || l[at - 1] == '_');
        if (wordStart) {
          l.replace(at, from.size(), to);
          at += to.size();
        } else {
          at += from.size();
        }
      }
    }
    out += l + "\n";
  }
  return out;
}

std::string hoistExtensions(const std::string& source) {
  if (source.find("#extension") == std::string::npos) return source;  // every program is preprocessed: most have none
  std::vector<std::string> lines;
  {
    std::istringstream in(source);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  std::string hoisted;
  // #if depth per source string (`#line N K`: the lines that follow are file K's): an extension
  // under its own file's #if stays with its condition; the #if an include sits in is the
  // including file's, and the extension is the included file's whenever it is included.
  std::map<int, int> depth;
  int file = 0;
  for (size_t i = 1; i < lines.size(); ++i) {
    const size_t first = lines[i].find_first_not_of(" \t");
    if (first == std::string::npos || lines[i][first] != '#') continue;
    const std::string_view directive = std::string_view(lines[i]).substr(first);
    if (directive.starts_with("#line ")) {  // "#line N K": the second number, when there is one
      const size_t space = directive.find(' ', 6);
      int k = 0;
      if (space != std::string_view::npos &&
          std::from_chars(directive.data() + space + 1, directive.data() + directive.size(), k).ec == std::errc())
        file = k;
    }
    if (directive.starts_with("#if")) ++depth[file];
    if (directive.starts_with("#endif")) --depth[file];
    if (depth[file] != 0 || !directive.starts_with("#extension")) continue;
    hoisted += std::string(directive) + "\n";
    lines[i].clear();  // an empty line in its place: the lines after it keep their numbers
  }
  if (hoisted.empty()) return source;
  std::string out = lines.front() + "\n" + hoisted;
  for (size_t i = 1; i < lines.size(); ++i) out += lines[i] + "\n";
  return out;
}

PreprocessedSource preprocessShader(const ShaderSearchPath& path, const std::string& relPath, const Defines& defines) {
  PreprocessedSource out;
  const ShaderSearchPath::Lookup found = path.find(relPath);
  const fs::path file = found.file;
  std::string text;
  if (!found.refused.empty()) {
    fail(out, relPath, 0, 0, found.refused);
    return out;
  }
  if (file.empty()) {
    fail(out, relPath, 0, 0, "shader file not found in the search path");
    return out;
  }
  if (auto why = readShaderFile(file, text); !why.empty()) {
    fail(out, file.string(), 0, 0, why);
    return out;
  }
  out.files.push_back(file);
  out.relPaths.push_back(relPath);

  // #version must come first; find the file's own, or default to the project's 330 core.
  std::istringstream in(text);
  std::string line, version = "#version 330 core";
  while (std::getline(in, line))
    if (isVersionLine(line)) {
      version = line;
      break;
    }
  out.text = versionPreamble(version, glslDialect());
  for (auto& [name, value] : defines) out.text += "#define " + name + " " + value + "\n";
  // A file included by several stages can tell the fragment stage (gl_FragCoord, derivatives) apart.
  if (relPath.ends_with(".frag")) out.text += "#define SHADELAB_FRAGMENT_STAGE 1\n";
  out.text += "#line 1 0\n";
  Expander ex{path, out, {relPath}};
  if (!ex.expand(relPath, text, 0, true)) {
    out.text.clear();
    return out;
  }
  out.text = hoistExtensions(out.text);
  if (glslDialect() == GlslDialect::Es300) out.text = flattenInterfaceBlocks(out.text);
  return out;
}

}  // namespace shadelab
