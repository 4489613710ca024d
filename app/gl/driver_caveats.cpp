#include "app/gl/driver_caveats.h"

#include <array>

#include "app/gl/gl.h"

namespace gl {
namespace {

std::string& pretended() {
  static std::string renderer;
  return renderer;
}

std::array<int, size_t(Caveat::Count)>& runs() {
  static std::array<int, size_t(Caveat::Count)> counts{};
  return counts;
}

}  // namespace

const CaveatEntry& entryOf(Caveat c) { return kDriverCaveats[size_t(c)]; }

bool applies(Caveat c) {
  const std::string driver(entryOf(c).driver);
  if (!pretended().empty()) return pretended().find(driver) != std::string::npos;
  return rendererIs(driver.c_str());
}

void noteWorkaround(Caveat c) { ++runs()[size_t(c)]; }
int workaroundRuns(Caveat c) { return runs()[size_t(c)]; }
void pretendRenderer(std::string renderer) { pretended() = std::move(renderer); }

}  // namespace gl
