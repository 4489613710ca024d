// A page's link (index.html#lab=...&scene=...&LAB.KEY=...): anyone can write one and send it to a
// class. Reading it back never crashes, whatever the bytes.
#include "app/host/share_link.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const shadelab::OpenedLink link = shadelab::openLink(std::string(shadelab::fuzz::asText(data, size)));
  (void)shadelab::percentEncode(link.camera + link.scene);
  return 0;
}
