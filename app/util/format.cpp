#include "app/util/format.h"

#include <cstdio>
#include <cstdlib>

namespace shadelab {

std::string formatNumber(double v) {
  char buf[32];
  for (int precision = 6; precision <= 9; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (float(std::strtod(buf, nullptr)) == float(v)) break;
  }
  return buf;
}

std::string formatFixed(double v, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

bool parseWholeNumber(const std::string& text, long lo, long hi, long& out) {
  char* end = nullptr;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end || n < lo || n > hi) return false;
  out = n;
  return true;
}

}  // namespace shadelab
