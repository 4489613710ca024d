#include "app/util/format.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace shadelab {

std::string formatNumber(double v) {
  char buf[32];
  for (int precision = 6; precision <= 9; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (float(std::strtod(buf, nullptr)) == float(v)) break;
  }
  return buf;
}

namespace {

std::string timeNow(const char* format, bool utc) {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  if (utc)
    gmtime_r(&now, &tm);
  else
    localtime_r(&now, &tm);
  char text[64];
  return std::strftime(text, sizeof text, format, &tm) ? text : "";
}

}  // namespace

std::string localTimeNow(const char* format) { return timeNow(format, false); }
std::string utcTimeNow(const char* format) { return timeNow(format, true); }

std::string formatFixed(double v, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string formatSignificant(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

bool parseWholeNumber(const std::string& text, long lo, long hi, long& out) {
  char* end = nullptr;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end || n < lo || n > hi) return false;
  out = n;
  return true;
}

std::string englishList(const std::vector<std::string>& names, const std::string& quote, size_t most) {
  const size_t shown = std::min(names.size(), most);
  const bool more = shown < names.size();
  std::string s;
  for (size_t i = 0; i < shown; ++i)
    s += (i == 0 ? "" : i + 1 == shown && !more ? " and " : ", ") + quote + names[i] + quote;
  if (more) s += " and " + std::to_string(names.size() - shown) + " more";
  return s;
}

}  // namespace shadelab
