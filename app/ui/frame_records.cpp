#include "app/ui/frame_records.h"

#include <algorithm>
#include <cstdio>

namespace shadelab {

namespace {

template <class Values>
double median(Values v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : double(v[v.size() / 2]);
}

}  // namespace

void ConfigurationCosts::push(const std::string& now, const std::vector<gl::PassTiming>& passes) {
  if (now != signature) {
    signature = now;
    since = std::chrono::steady_clock::now();
    gpu.clear();
    cpu.clear();
  }
  double g = 0, c = 0;
  for (auto& p : passes) {
    g += p.gpuMs;
    c += p.cpuMs;
  }
  gpu.push_back(g);
  cpu.push_back(c);
  if (gpu.size() > 15) {
    gpu.pop_front();
    cpu.pop_front();
  }
}

Metrics ConfigurationCosts::costs() const {
  return gpu.size() < 3 ? Metrics{} : Metrics{{"gpu_ms", median(gpu)}, {"cpu_ms", median(cpu)}};
}

void Responsiveness::report() const {
  std::printf(
      "frames: %zu, %zu while jobs ran; median frame %.1f ms idle, %.1f ms while jobs ran; the lab's passes "
      "%.2f ms\n",
      idleMs.size() + busyMs.size(), busyMs.size(), median(idleMs), median(busyMs), median(labMs));
}

}  // namespace shadelab
