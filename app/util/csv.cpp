#include "app/util/csv.h"

#include <cstdlib>

namespace shadelab {

static bool isNumber(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  // strtod also reads "inf", "nan" and hex; those are fine cells too, but only whole-text numbers count.
  return end == s.c_str() + s.size();
}

std::string csvField(const std::string& text) {
  std::string s = text;
  const bool formula =
      !s.empty() && (s[0] == '=' || s[0] == '+' || s[0] == '-' || s[0] == '@' || s[0] == '\t' || s[0] == '\r');
  if (formula && !isNumber(s)) s = "'" + s;
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace shadelab
