#include "app/util/output_files.h"

#include <cstdlib>

#include "app/util/format.h"

namespace fs = std::filesystem;

namespace shadelab {

std::string makeParentFolder(const std::string& path) {
  const fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) return {};
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec || !fs::is_directory(folder))
    return path + ": cannot make the folder " + folder.string() + (ec ? ": " + ec.message() : "");
  return {};
}

fs::path outputDir(const std::string& sub) {
  const char* env = std::getenv("SHADELAB_OUT");
  fs::path dir = fs::path(env && *env ? env : "out") / sub;
  std::error_code ec;
  fs::create_directories(dir, ec);
  return dir;
}

fs::path freshName(const std::string& sub, const std::string& stem, const std::string& ext) {
  const std::string stamp = localTimeNow("%Y%m%d-%H%M%S");
  const fs::path dir = outputDir(sub);
  fs::path p = dir / (stem + "-" + stamp + ext);
  for (int n = 2; fs::exists(p) || fs::exists(fs::path(p).replace_extension(".json")); ++n)
    p = dir / (stem + "-" + stamp + "-" + std::to_string(n) + ext);
  return p;
}

}  // namespace shadelab
