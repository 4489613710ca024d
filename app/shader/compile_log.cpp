#include "app/shader/compile_log.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "app/shader/preprocessor.h"

namespace shadelab {

std::string Diagnostic::format() const {
  std::string s = file.empty() ? std::string("<shader>") : file;
  if (line > 0) s += ":" + std::to_string(line);
  if (column > 0) s += ":" + std::to_string(column);
  // Unparsed driver lines keep their own "error: " (a linker's); do not say it twice.
  const bool worded = message.rfind("error: ", 0) == 0 || message.rfind("warning: ", 0) == 0;
  s += worded ? ": " : isError ? ": error: " : ": warning: ";
  s += message;
  return s;
}

std::string Diagnostic::formatWithCaret() const {
  std::string s = format();
  if (sourceLine.empty()) return s;
  s += "\n    ";
  s += sourceLine;
  if (column <= 0 || size_t(column) > sourceLine.size() + 1) return s;  // no caret past the line's end
  std::string pad(size_t(column - 1), ' ');
  for (size_t i = 0; i < pad.size() && i < sourceLine.size(); ++i)
    if (sourceLine[i] == '\t') pad[i] = '\t';  // the caret lines up whatever the tab width
  s += "\n    ";
  s += pad;
  s += '^';
  return s;
}

namespace {

std::string trim(std::string s) {
  const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// A number from a driver's log; anything past int's range (a corrupt log) reads as 0: unknown.
int logNumber(const std::string& digits) {
  long long v = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return 0;
    v = v * 10 + (c - '0');
    if (v > 2147483647LL) return 0;
  }
  return int(v);
}

// std::regex matches recursively, so a line long enough exhausts the stack: no driver writes
// a diagnostic this long, and such a line is shown as it is.
constexpr size_t kLongestParsedLine = 2000;

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
  // The file and line a (source string, line) pair names, with the file index decoded from the
  // line where the driver reported source string 0 (see preprocessor.h).
  auto locate = [&](Diagnostic& d, const std::string& source, const std::string& line) {
    const auto [k, n] = splitLine(logNumber(source), logNumber(line));
    d.file = size_t(k) < files.size() ? files[size_t(k)].string() : "source-string " + std::to_string(k);
    d.line = n;
  };
  while (std::getline(in, line)) {
    if (trim(line).empty()) continue;
    Diagnostic d;
    d.raw = line;
    std::smatch m;
    if (line.size() > kLongestParsedLine) {
      d.message = trim(line.substr(0, kLongestParsedLine)) + "...";
    } else if (std::regex_match(line, m, mesa)) {
      locate(d, m[1], m[2]);
      d.column = logNumber(m[3]);
      d.isError = isErrorWord(m[4]);
      d.message = trim(m[5]);
    } else if (std::regex_match(line, m, nvidia)) {
      locate(d, m[1], m[2]);
      d.isError = isErrorWord(m[3]);
      d.message = trim(m[4].str().empty() ? m[5].str() : m[4].str() + ": " + m[5].str());
    } else if (std::regex_match(line, m, amd)) {
      locate(d, m[2], m[3]);
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

void locateLinkErrors(std::vector<Diagnostic>& diags, const std::vector<StageFiles>& stages) {
  static const std::regex quoted(R"([`'"]([A-Za-z_][A-Za-z0-9_]*)['"])");
  static const std::regex declaration(R"(\b(in|out|uniform|varying|attribute|buffer)\b)");
  for (auto& d : diags) {
    if (d.line > 0) continue;
    std::smatch m;
    if (!std::regex_search(d.message, m, quoted)) continue;
    const std::string name = m[1];
    const std::regex word("\\b" + name + "\\b");
    std::string lower = d.message;
    for (auto& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    // The stage the message names first, then the others.
    std::vector<const StageFiles*> order;
    for (auto& st : stages)
      if (lower.find(st.stage + " shader") != std::string::npos) order.push_back(&st);
    for (auto& st : stages)
      if (std::find(order.begin(), order.end(), &st) == order.end()) order.push_back(&st);
    bool found = false;
    for (const StageFiles* st : order) {
      for (auto& file : st->files) {
        std::ifstream in(file);
        std::string line;
        int n = 0, firstUse = 0, firstUseColumn = 0;
        while (std::getline(in, line)) {
          ++n;
          std::smatch w;
          if (!std::regex_search(line, w, word)) continue;
          if (std::regex_search(line, declaration)) {
            d.file = file.string();
            d.line = n;
            d.column = int(w.position(0)) + 1;
            found = true;
            break;
          }
          if (!firstUse) {
            firstUse = n;
            firstUseColumn = int(w.position(0)) + 1;
          }
        }
        if (!found && firstUse) {
          d.file = file.string();
          d.line = firstUse;
          d.column = firstUseColumn;
          found = true;
        }
        if (found) break;
      }
      if (found) break;
    }
  }
}

}  // namespace shadelab
