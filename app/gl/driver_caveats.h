// What particular drivers do that ShadeLab works around, one entry each: the driver and the
// versions it was seen on, the symptom, the workaround, and when the workaround can go. Each
// workaround runs only where its driver is detected; on any other driver the code path is not
// taken at all. The measurements behind each entry, and how each was found, are in the commit
// history (git log -S with the entry's name); docs/sandbox.md ("Soak") sums them up.
#pragma once
#include <string>
#include <string_view>

namespace gl {

enum class Caveat {
  HeldTextures,    // llvmpipe keeps deleted textures alive through its last references to them
  HeldScenes,      // llvmpipe keeps a busy burst's binned scenes, and what they read, for good
  SlowAnisotropy,  // llvmpipe's anisotropic filtering costs twice as much per finer level read
  Count
};

struct CaveatEntry {
  Caveat caveat;
  std::string_view name;        // for messages, tests and `git log -S`
  std::string_view driver;      // a substring of GL_RENDERER
  std::string_view versions;    // where it was seen
  std::string_view symptom;     // one line
  std::string_view workaround;  // what ShadeLab does about it, and where
  std::string_view removeWhen;  // when the workaround can be deleted
};

inline constexpr CaveatEntry kDriverCaveats[] = {
    {Caveat::HeldTextures, "llvmpipe-held-textures", "llvmpipe", "Mesa 22.3 (Debian 12)",
     "a deleted texture stays allocated while it is the last one cleared through a framebuffer, the last "
     "whose mipmaps were made, or the last sampled on a unit and stage: a left lab's 1 GB shadow map stays resident",
     "on each lab switch, gl::DriverStandIns (stand_ins.h) clears, mipmaps and samples small textures of its own",
     "when the lifecycle tests' memory bounds (tests/gl/lab_lifecycle_test.cpp) hold on llvmpipe without it"},
    {Caveat::HeldScenes, "llvmpipe-held-scenes", "llvmpipe", "Mesa 22.3 (Debian 12)",
     "each binned scene keeps its commands (up to 36 MB) and references to what it read until the driver hands "
     "it out again, and lighter frames after a heavy burst never reach the later ones",
     "on each lab switch, DriverStandIns::handOutEveryScene flushes one long scene and 48 short ones behind it, "
     "so every scene the driver has is handed out once",
     "with llvmpipe-held-textures, or when Mesa frees idle scenes"},
    {Caveat::SlowAnisotropy, "llvmpipe-slow-anisotropy", "llvmpipe", "Mesa 22.3 (Debian 12)",
     "anisotropic filtering takes about twice as long for each level it reads finer than the footprint's "
     "(a negative LOD bias, a manual level): seconds a frame",
     "the filtering lab filters anisotropically in its shader instead in those cases, and says so "
     "(FilteringLab::anisotropyMovedToShader)",
     "when llvmpipe's anisotropic filtering costs what a GPU's does relative to trilinear"},
};
static_assert(std::size(kDriverCaveats) == size_t(Caveat::Count), "one entry per caveat");

const CaveatEntry& entryOf(Caveat c);
// Whether the current context's driver is the one the caveat is about.
bool applies(Caveat c);
// The workaround of `c` ran once more (tests count the runs: none on another driver).
void noteWorkaround(Caveat c);
int workaroundRuns(Caveat c);
// Tests: answer applies() as if GL_RENDERER were `renderer`; "" reads the context's again.
void pretendRenderer(std::string renderer);

}  // namespace gl
