#include "app/shader/function_parts.h"

#include <algorithm>
#include <cctype>

namespace shadelab {
namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// `source` split into lines (without their '\n').
std::vector<std::string_view> splitLines(std::string_view source) {
  std::vector<std::string_view> lines;
  size_t at = 0;
  while (at <= source.size()) {
    const size_t end = std::min(source.find('\n', at), source.size());
    lines.push_back(source.substr(at, end - at));
    if (end == source.size()) break;
    at = end + 1;
  }
  return lines;
}

}  // namespace

std::vector<FunctionSpan> findFunctions(std::string_view source) {
  std::vector<FunctionSpan> out;
  int depth = 0, line = 1;
  int declarationLine = 0;  // where the current top-level declaration began (its first token)
  std::string name;         // the identifier before its first '(': a function's name
  FunctionSpan open;        // the body being read; no name: a struct's or a block's, not recorded
  bool block = false, lineComment = false, lineStart = true, directive = false;
  for (size_t i = 0; i < source.size(); ++i) {
    const char c = source[i];
    const char next = i + 1 < source.size() ? source[i + 1] : '\0';
    if (c == '\n') {
      ++line;
      lineComment = directive = false;
      lineStart = true;
      continue;
    }
    if (block) {
      if (c == '*' && next == '/') block = false, ++i;
      continue;
    }
    if (lineComment || directive) continue;
    if (c == '/' && (next == '*' || next == '/')) {
      (next == '*' ? block : lineComment) = true, ++i;
      continue;
    }
    if (lineStart && c == '#') {
      directive = true;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    lineStart = false;
    if (depth > 0) {  // inside a body: only its end matters
      if (c == '{') ++depth;
      if (c == '}' && --depth == 0) {
        open.lastLine = line;
        if (!open.name.empty()) out.push_back(open);
        declarationLine = 0, name.clear();
      }
      continue;
    }
    if (declarationLine == 0) declarationLine = line;
    if (c == ';' || c == '}') {
      declarationLine = 0, name.clear();
    } else if (c == '(' && name.empty()) {
      size_t e = i;
      while (e > 0 && std::isspace(static_cast<unsigned char>(source[e - 1]))) --e;
      size_t b = e;
      while (b > 0 && identifierChar(source[b - 1])) --b;
      name = std::string(source.substr(b, e - b));
      if (name == "layout") name.clear();  // layout(...) qualifies a block or a variable, not a function
    } else if (c == '{') {
      depth = 1;
      open = {name, declarationLine, 0};
    }
  }
  return out;
}

std::string linesOf(std::string_view source, const FunctionSpan& span) {
  const auto lines = splitLines(source);
  std::string text;
  for (int l = span.firstLine; l <= span.lastLine && l <= int(lines.size()); ++l) {
    text += lines[size_t(l - 1)];
    text += '\n';
  }
  return text;
}

std::string matchParts(std::string_view base, std::string_view part, std::vector<FunctionSpan>& baseSpans,
                       std::vector<FunctionSpan>& partSpans) {
  const auto lines = splitLines(part);
  for (size_t l = 0; l < lines.size(); ++l) {
    const size_t first = lines[l].find_first_not_of(" \t");
    if (first != std::string_view::npos && lines[l].substr(first, 8) == "#include")
      return std::to_string(l + 1) + ": a part file holds functions only: no #include";
  }
  const std::vector<FunctionSpan> inBase = findFunctions(base), inPart = findFunctions(part);
  if (inPart.empty())
    return "1: a part file holds one or more functions of the file it belongs to; this one holds none";
  baseSpans.clear();
  partSpans.clear();
  for (const FunctionSpan& p : inPart) {
    // Overloads share a name: the first definition in the base not yet replaced.
    auto it = std::find_if(inBase.begin(), inBase.end(), [&](const FunctionSpan& b) {
      return b.name == p.name && std::none_of(baseSpans.begin(), baseSpans.end(), [&](const FunctionSpan& taken) {
               return taken.firstLine == b.firstLine;
             });
    });
    if (it == inBase.end())
      return std::to_string(p.firstLine) + ": '" + p.name + "' is not a function of the file this part belongs to";
    baseSpans.push_back(*it);
    partSpans.push_back(p);
  }
  return {};
}

std::string extractPart(std::string_view base, const std::vector<std::string>& names) {
  const std::vector<FunctionSpan> spans = findFunctions(base);
  std::string text;
  for (const std::string& name : names) {
    auto it = std::find_if(spans.begin(), spans.end(), [&](const FunctionSpan& s) { return s.name == name; });
    if (it == spans.end()) return {};
    text += (text.empty() ? "" : "\n") + linesOf(base, *it);
  }
  return text;
}

}  // namespace shadelab
