#include "app/util/thread_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace shadelab {

ThreadPriority::ThreadPriority() : self_(syscall(SYS_gettid)), normal_(getpriority(PRIO_PROCESS, id_t(self_))) {}

void ThreadPriority::lower(bool low) const { setpriority(PRIO_PROCESS, id_t(self_), low ? normal_ + 10 : normal_); }

}  // namespace shadelab
