// A .zip of files, stored (not compressed): what a student downloads of the shaders they edited
// in the page, laid out like shaders/. Shader files are small; storing keeps this short and
// dependency-free, and every unzip tool reads it.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab {

// CRC-32 (IEEE 802.3, as zip and PNG use it).
uint32_t crc32(std::string_view bytes);

struct ZipEntry {
  std::string name;  // relative, with '/' separators: "shadows/pcf.glsl"
  std::string bytes;
};

// The archive's bytes. Names are written as given (UTF-8); sizes must stay under 4 GB.
std::string storedZip(const std::vector<ZipEntry>& entries);

}  // namespace shadelab
