// What the grading tests share: files read whole, names made safe for folders and test names, and
// a fresh scratch folder under the build's test output.
#pragma once
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace shadelab::test {

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// "shadows/pcf" -> "shadows_pcf"
inline std::string slug(std::string s) {
  for (auto& ch : s) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return s;
}

// SHADELAB_TEST_OUT/<group>/<name>, emptied and made.
inline std::filesystem::path freshFolder(const std::string& group, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(SHADELAB_TEST_OUT) / group / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace shadelab::test
