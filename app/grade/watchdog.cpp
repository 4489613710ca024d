#include "app/grade/watchdog.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace shadelab {

namespace {
constexpr rlim_t kMaxChildFileBytes = rlim_t(256) << 20;

#if defined(__SANITIZE_ADDRESS__)
#define SHADELAB_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define SHADELAB_SANITIZED 1
#endif
#endif
}  // namespace

double watchdogTimeScale() {
#ifdef SHADELAB_SANITIZED
  return 4.0;
#else
  return 1.0;
#endif
}

std::string WatchedRun::describe() const {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f s", phaseSeconds);
  switch (end) {
    case End::Exited:
      return "exited with " + std::to_string(status);
    case End::Signalled:
      return "killed by signal " + std::to_string(status) + " (" + strsignal(status) + ")";
    default:
      return "stopped by the watchdog after " + std::string(seconds) +
             (phase.empty() ? "" : " in phase '" + phase + "'");
  }
}

WatchedRun runWatched(const WatchedWork& work, const std::function<double(const std::string&)>& limitFor,
                      const std::string& logPath) {
  using Clock = std::chrono::steady_clock;
  int fds[2];
  if (pipe(fds) != 0) return {WatchedRun::End::Signalled, SIGPIPE, "", 0.0};
  std::fflush(nullptr);  // buffered output would be written twice, once by each process
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    // Nothing a configuration writes (images, numbers, its log) comes near this; a child that
    // tries is stopped by SIGXFSZ and counted as crashed, its submission alone paying for it.
    const rlimit fileSize{kMaxChildFileBytes, kMaxChildFileBytes};
    setrlimit(RLIMIT_FSIZE, &fileSize);
    if (int log = open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644); log >= 0) {
      dup2(log, STDOUT_FILENO);
      dup2(log, STDERR_FILENO);
      close(log);
    }
    const auto enter = [fd = fds[1]](const std::string& phase) {
      const std::string line = phase + "\n";
      [[maybe_unused]] ssize_t n = write(fd, line.data(), line.size());
    };
    const int code = work(enter);
    std::fflush(nullptr);
    _exit(code);
  }
  close(fds[1]);
  WatchedRun run;
  if (pid < 0) {
    close(fds[0]);
    return {WatchedRun::End::Signalled, SIGCHLD, "", 0.0};
  }
  auto phaseStart = Clock::now();
  std::string pending;
  bool open = true;
  while (open) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - phaseStart).count();
    const double left = limitFor(run.phase) * watchdogTimeScale() - elapsed;
    if (left <= 0.0) {
      kill(pid, SIGKILL);
      run.end = WatchedRun::End::TimedOut;
      run.phaseSeconds = elapsed;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, int(std::ceil(std::min(left, 3600.0) * 1000.0)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;  // timed out: the loop kills it
    char buffer[256];
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n <= 0) {
      open = false;  // the child exited (or closed the pipe): collect it below
      run.phaseSeconds = std::chrono::duration<double>(Clock::now() - phaseStart).count();
      break;
    }
    pending.append(buffer, size_t(n));
    for (size_t nl; (nl = pending.find('\n')) != std::string::npos; pending.erase(0, nl + 1)) {
      run.phase = pending.substr(0, nl);
      phaseStart = Clock::now();
    }
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (run.end == WatchedRun::End::TimedOut) return run;
  if (WIFSIGNALED(status)) {
    run.end = WatchedRun::End::Signalled;
    run.status = WTERMSIG(status);
  } else {
    run.status = WEXITSTATUS(status);
  }
  return run;
}

}  // namespace shadelab
