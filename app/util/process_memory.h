// The process's memory, for the soak's records: what the system holds for it and what the
// allocator has handed out; and image-sized buffers that are cheap to fill. Linux reads /proc and
// glibc; the page, its WebAssembly heap.
#pragma once

#include <cstddef>
#include <vector>

namespace shadelab {

double residentMb();  // resident set (the page: the WebAssembly memory's size)
// The resident set in two parts: anonymous pages (the heap, mappings the process made: memory it
// holds) and pages of mapped files (the code of the libraries it runs, which grows as more of a
// library is run for the first time and which the system may drop and read again at will).
struct ResidentParts {
  double anonymousMb = 0.0;
  double fileMb = 0.0;
};
ResidentParts residentParts();
double heapInUseMb();    // allocated and in use: tells memory kept from pages kept
void returnFreePages();  // the allocator gives its free pages back (before a residentMb worth comparing)
// Called once at start: blocks of 1 MiB and more are mapped on their own and given back when
// freed. glibc otherwise raises that threshold to the largest block freed (up to 32 MiB), and a
// frame's transient images are then carved from the heap among small long-lived blocks, whose
// pages cannot be returned (docs/sandbox.md has the soak's figures).
void keepLargeBlocksApart();

// Asks the kernel to back [data, data + bytes) with huge pages where it offers them on request
// (transparent huge pages in "madvise" mode, as on Debian); nothing for a block under 2 MiB, or on
// the page.
void adviseHugePages(void* data, size_t bytes);
// `count` zeroed values for an image-sized buffer filled at once (a read-back, a truth). Such a
// block is mapped afresh each time (keepLargeBlocksApart), and each small page faults on first
// touch; huge pages make that a few faults (BM_ImageBuffer measures both).
template <typename T>
std::vector<T> largeBuffer(size_t count) {
  std::vector<T> values;
  values.reserve(count);
  adviseHugePages(values.data(), count * sizeof(T));
  values.resize(count);
  return values;
}

}  // namespace shadelab
