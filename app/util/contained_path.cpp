#include "app/util/contained_path.h"

#include <string>

namespace fs = std::filesystem;

namespace shadelab {

fs::path containedName(std::string_view name) {
  if (name.empty() || name.find('\0') != std::string_view::npos) return {};
  const fs::path p = fs::path(std::string(name)).lexically_normal();
  if (p.empty() || p.has_root_path() || *p.begin() == "..") return {};
  return p;
}

bool realPathInside(const fs::path& folder, const fs::path& file) {
  std::error_code ec;
  const fs::path realFolder = fs::canonical(folder, ec);
  if (ec) return false;
  const fs::path realFile = fs::canonical(file, ec);
  if (ec) return false;
  const fs::path rel = realFile.lexically_relative(realFolder);
  return !rel.empty() && !rel.is_absolute() && *rel.begin() != "..";
}

}  // namespace shadelab
