// The process's memory, for the soak's records: what the system holds for it and what the
// allocator has handed out. Linux reads /proc and glibc; the page, its WebAssembly heap.
#pragma once

namespace shadelab {

double residentMb();      // resident set (the page: the WebAssembly memory's size)
double heapInUseMb();     // allocated and in use: tells memory kept from pages kept
void returnFreePages();   // the allocator gives its free pages back (before a residentMb worth comparing)

}  // namespace shadelab
