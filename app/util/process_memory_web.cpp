#include "app/util/process_memory.h"

#include <emscripten/heap.h>
#include <malloc.h>

namespace shadelab {

double residentMb() { return double(emscripten_get_heap_size()) / (1024.0 * 1024.0); }

ResidentParts residentParts() { return {residentMb(), 0.0}; }

double heapInUseMb() {
  const struct mallinfo heap = ::mallinfo();
  return double(heap.uordblks + heap.hblkhd) / (1024.0 * 1024.0);
}

void keepLargeBlocksApart() {}          // one linear memory: nothing to map apart
void returnFreePages() {}               // WebAssembly memory only grows
void adviseHugePages(void*, size_t) {}  // no pages to choose

}  // namespace shadelab
