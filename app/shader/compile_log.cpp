#include "shader/compile_log.h"

#include <fstream>
#include <regex>
#include <sstream>

namespace shadelab {

std::string Diagnostic::format() const {
  std::string s = file.empty() ? std::string("<shader>") : file;
  if (line > 0) s += ":" + std::to_string(line);
  if (column > 0) s += ":" + std::to_string(column);
  s += isError ? ": error: " : ": warning: ";
  s += message;
  return s;
}

namespace {

std::string trim(std::string s) {
  const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

bool isErrorWord(std::string w) {
  for (auto& c : w) c = char(std::tolower(static_cast<unsigned char>(c)));
  return w != "warning";
}

}  // namespace

std::vector<Diagnostic> parseCompileLog(std::string_view log, const std::vector<std::filesystem::path>& files) {
  static const std::regex mesa(R"(^\s*(\d+):(\d+)\((\d+)\):\s*(error|warning)\s*:?\s*(.*)$)");
  static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(error|warning)\s*(\w*)\s*:?\s*(.*)$)");
  static const std::regex amd(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");
  std::vector<Diagnostic> out;
  std::istringstream in{std::string(log)};
  std::string line;
  auto fileName = [&](const std::string& idx) {
    const size_t k = std::stoul(idx);
    return k < files.size() ? files[k].string() : "source-string " + idx;
  };
  while (std::getline(in, line)) {
    if (trim(line).empty()) continue;
    Diagnostic d;
    d.raw = line;
    std::smatch m;
    if (std::regex_match(line, m, mesa)) {
      d.file = fileName(m[1]);
      d.line = std::stoi(m[2]);
      d.column = std::stoi(m[3]);
      d.isError = isErrorWord(m[4]);
      d.message = trim(m[5]);
    } else if (std::regex_match(line, m, nvidia)) {
      d.file = fileName(m[1]);
      d.line = std::stoi(m[2]);
      d.isError = isErrorWord(m[3]);
      d.message = trim(m[4].str().empty() ? m[5].str() : m[4].str() + ": " + m[5].str());
    } else if (std::regex_match(line, m, amd)) {
      d.file = fileName(m[2]);
      d.line = std::stoi(m[3]);
      d.isError = isErrorWord(m[1]);
      d.message = trim(m[4]);
    } else {
      d.message = trim(line);  // unparsed: shown raw
    }
    out.push_back(std::move(d));
  }
  return out;
}

void attachSourceLines(std::vector<Diagnostic>& diags) {
  for (auto& d : diags) {
    if (d.file.empty() || d.line <= 0) continue;
    std::ifstream in(d.file);
    std::string text;
    for (int n = 1; std::getline(in, text); ++n)
      if (n == d.line) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        d.sourceLine = text;
        break;
      }
  }
}

}  // namespace shadelab
