#include "app/util/process_memory.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#if defined(__SANITIZE_ADDRESS__)
#define SHADELAB_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SHADELAB_ASAN 1
#endif
#endif
#ifdef SHADELAB_ASAN
// The sanitizers' public interface (compiler-rt's sanitizer/allocator_interface.h, which GCC does
// not install).
extern "C" size_t __sanitizer_get_current_allocated_bytes();
#endif

namespace shadelab {

double residentMb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return double(resident) * double(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

ResidentParts residentParts() {
  // /proc/self/status: "RssAnon:  123456 kB", "RssFile: ...", "RssShmem: ..." (shared memory
  // counts as the process's own: a window's shared images are).
  std::ifstream status("/proc/self/status");
  ResidentParts parts;
  for (std::string key; status >> key;) {
    double kb = 0;
    if (key == "RssAnon:" || key == "RssShmem:") {
      status >> kb;
      parts.anonymousMb += kb / 1024.0;
    } else if (key == "RssFile:") {
      status >> kb;
      parts.fileMb += kb / 1024.0;
    }
    status.ignore(1 << 20, '\n');
  }
  return parts;
}

double heapInUseMb() {
#ifdef SHADELAB_ASAN
  // AddressSanitizer's allocator serves malloc; glibc's mallinfo2 then counts nothing.
  return double(__sanitizer_get_current_allocated_bytes()) / (1024.0 * 1024.0);
#else
  const struct mallinfo2 heap = ::mallinfo2();
  return double(heap.uordblks + heap.hblkhd) / (1024.0 * 1024.0);
#endif
}

void returnFreePages() { ::malloc_trim(0); }

void keepLargeBlocksApart() { ::mallopt(M_MMAP_THRESHOLD, 1 << 20); }  // a fixed threshold is never raised

void adviseHugePages(void* data, size_t bytes) {
  constexpr uintptr_t kHugePage = uintptr_t(2) << 20, kPage = 4096;
  if (!data || bytes < kHugePage) return;
  const uintptr_t begin = (uintptr_t(data) + kPage - 1) & ~(kPage - 1), end = (uintptr_t(data) + bytes) & ~(kPage - 1);
  if (end > begin)
    ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice: a refusal costs nothing
}

}  // namespace shadelab
