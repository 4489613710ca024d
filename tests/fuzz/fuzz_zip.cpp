// A class's .zip submissions (grade --class): whatever the archive holds, unpacking writes only
// inside its own folder, within its limits, and never crashes.
#include "app/cli/submissions.h"
#include "fuzz_files.h"

namespace fs = std::filesystem;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const fs::path zip = shadelab::fuzz::writeScratch("submission.zip", shadelab::fuzz::asText(data, size));
  const fs::path dest = shadelab::fuzz::scratchDir() / "unpacked";
  shadelab::removeUnpacked(dest);
  shadelab::ZipLimits limits;
  limits.totalBytes = size_t(4) << 20;  // a fuzzer's memory and disk are small
  limits.fileBytes = size_t(1) << 20;
  if (shadelab::unpackZip(zip, dest, limits).empty()) (void)shadelab::shaderRootOf(dest);
  // Nothing outside the scratch folder's own two entries may appear.
  for (auto& e : fs::directory_iterator(shadelab::fuzz::scratchDir()))
    if (e.path() != zip && e.path() != dest) __builtin_trap();
  shadelab::removeUnpacked(dest);
  return 0;
}
