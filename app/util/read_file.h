// Reading a whole file into memory, the one way the project does it.
#pragma once
#include <filesystem>
#include <string>

namespace shadelab {

// The file's bytes into `out`; false (and `out` empty) when it cannot be opened.
bool readWholeFile(const std::filesystem::path& file, std::string& out);
// The file's bytes, or "" when it cannot be opened.
std::string readWholeFile(const std::filesystem::path& file);

}  // namespace shadelab
