// The process's memory, for the soak's records: what the system holds for it and what the
// allocator has handed out. Linux reads /proc and glibc; the page, its WebAssembly heap.
#pragma once

namespace shadelab {

double residentMb();      // resident set (the page: the WebAssembly memory's size)
// The resident set in two parts: anonymous pages (the heap, mappings the process made: memory it
// holds) and pages of mapped files (the code of the libraries it runs, which grows as more of a
// library is run for the first time and which the system may drop and read again at will).
struct ResidentParts {
  double anonymousMb = 0.0;
  double fileMb = 0.0;
};
ResidentParts residentParts();
double heapInUseMb();     // allocated and in use: tells memory kept from pages kept
void returnFreePages();   // the allocator gives its free pages back (before a residentMb worth comparing)

}  // namespace shadelab
