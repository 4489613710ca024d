// The calling thread's scheduling priority, for job workers that must not take the window's frames.
// Linux: nice is per thread and inherited by the threads it starts. The browser's workers have no
// priority to set: there lowering is a no-op.
#pragma once

namespace shadelab {

class ThreadPriority {
 public:
  ThreadPriority();            // remembers the calling thread's priority as its normal one
  void lower(bool low) const;  // normal + 10 when `low`, normal otherwise; the calling thread

 private:
  long self_ = 0;
  int normal_ = 0;
};

}  // namespace shadelab
