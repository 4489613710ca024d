// Runs work in a child process under a watchdog. A student's shader can loop forever; a GPU (or
// llvmpipe) drawing it never returns from glFinish, and nothing inside the process can stop it.
// A process can be stopped from outside: the grader forks one per configuration, the child
// announces the phases it enters ("solution", "student") and each phase has its own time limit.
// Past it the child is killed and the parent carries on with the next configuration.
//
// The parent must hold no GL context and run no threads that the child would need: fork copies
// only the calling thread. The grader's parent never touches GL; each child makes its own context.
#pragma once
#include <functional>
#include <string>

namespace shadelab {

struct WatchedRun {
  enum class End { Exited, Signalled, TimedOut };
  End end = End::Exited;
  int status = 0;                // exit code, or the signal that ended it
  std::string phase;             // the last phase the child entered ("" if none)
  double phaseSeconds = 0.0;     // how long it had been in that phase when it ended
  std::string describe() const;  // "exited with 0", "killed by signal 11 (Segmentation fault)", ...
};

// The child calls `enter(name)` when a phase starts; returns its exit code.
using WatchedWork = std::function<int(const std::function<void(const std::string&)>& enter)>;

// Forks; the child runs `work` with stdout and stderr going to `logPath` and exits with its
// result. `limitFor(phase)` gives each phase's limit in seconds ("" = before the first phase),
// times watchdogTimeScale().
// How much longer than its limit a phase may run in this build: 4 in a sanitized build (./test.sh
// --sanitize), whose own code in the child runs several times slower than a release build's, so
// that a limit means the same work in both; else 1.
double watchdogTimeScale();

WatchedRun runWatched(const WatchedWork& work, const std::function<double(const std::string&)>& limitFor,
                      const std::string& logPath);

}  // namespace shadelab
