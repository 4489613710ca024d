// Where ShadeLab writes what a user asked it to save (screenshots, presets, baked maps): under
// out/ or $SHADELAB_OUT, always under a fresh name, so nothing anyone wrote is overwritten.
#pragma once
#include <filesystem>
#include <string>

namespace shadelab {

// The folder `path` lies in, made if missing (a user's `--out out/shots/a.png` in a fresh clone);
// returns "" or why it could not be made.
std::string makeParentFolder(const std::string& path);
// out/<sub> (or $SHADELAB_OUT/<sub>), created if missing.
std::filesystem::path outputDir(const std::string& sub);
// out/<sub>/<stem>-YYYYmmdd-HHMMSS[-n]<ext>: neither it nor the same name with .json exists.
std::filesystem::path freshName(const std::string& sub, const std::string& stem, const std::string& ext);

}  // namespace shadelab
