#include "util/process_memory.h"

#include <malloc.h>
#include <unistd.h>

#include <fstream>

namespace shadelab {

double residentMb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return double(resident) * double(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

double heapInUseMb() {
  const struct mallinfo2 heap = ::mallinfo2();
  return double(heap.uordblks + heap.hblkhd) / (1024.0 * 1024.0);
}

void returnFreePages() { ::malloc_trim(0); }

}  // namespace shadelab
