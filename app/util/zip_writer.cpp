#include "app/util/zip_writer.h"

#include <array>

namespace shadelab {

namespace {

const std::array<uint32_t, 256>& crcTable() {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  return table;
}

void put16(std::string& out, uint32_t v) {
  out += char(v & 0xFF);
  out += char((v >> 8) & 0xFF);
}

void put32(std::string& out, uint32_t v) {
  put16(out, v & 0xFFFF);
  put16(out, v >> 16);
}

}  // namespace

uint32_t crc32(std::string_view bytes) {
  uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) c = crcTable()[(c ^ b) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::string storedZip(const std::vector<ZipEntry>& entries) {
  // Each file: a local header and its bytes; then the central directory, one record a file; then
  // its end record. Version 2.0, method 0 (stored), bit 11: names are UTF-8. No date (1980-01-01).
  std::string out, central;
  constexpr uint32_t kDosDate = (0 << 9) | (1 << 5) | 1;
  for (const ZipEntry& e : entries) {
    const uint32_t offset = uint32_t(out.size()), crc = crc32(e.bytes), size = uint32_t(e.bytes.size());
    const auto common = [&](std::string& s) {
      put16(s, 20);        // version needed: 2.0
      put16(s, 1u << 11);  // UTF-8 names
      put16(s, 0);         // stored
      put16(s, 0);         // time
      put16(s, kDosDate);
      put32(s, crc);
      put32(s, size);  // compressed
      put32(s, size);  // uncompressed
      put16(s, uint32_t(e.name.size()));
      put16(s, 0);  // extra field
    };
    put32(out, 0x04034b50);
    common(out);
    out += e.name;
    out += e.bytes;
    put32(central, 0x02014b50);
    put16(central, (3u << 8) | 20);  // made by: Unix, 2.0
    common(central);
    put16(central, 0);               // comment
    put16(central, 0);               // disk
    put16(central, 0);               // internal attributes
    put32(central, 0100644u << 16);  // external: a regular file, rw-r--r--
    put32(central, offset);
    central += e.name;
  }
  const uint32_t centralOffset = uint32_t(out.size());
  out += central;
  put32(out, 0x06054b50);
  put16(out, 0);
  put16(out, 0);
  put16(out, uint32_t(entries.size()));
  put16(out, uint32_t(entries.size()));
  put32(out, uint32_t(central.size()));
  put32(out, centralOffset);
  put16(out, 0);  // comment
  return out;
}

}  // namespace shadelab
