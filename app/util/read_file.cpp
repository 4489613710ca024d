#include "app/util/read_file.h"

#include <fstream>
#include <sstream>

namespace shadelab {

bool readWholeFile(const std::filesystem::path& file, std::string& out) {
  out.clear();
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  out = s.str();
  return true;
}

std::string readWholeFile(const std::filesystem::path& file) {
  std::string text;
  readWholeFile(file, text);
  return text;
}

}  // namespace shadelab
