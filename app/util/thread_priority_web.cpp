#include "app/util/thread_priority.h"

namespace shadelab {

ThreadPriority::ThreadPriority() = default;

void ThreadPriority::lower(bool) const {}

}  // namespace shadelab
