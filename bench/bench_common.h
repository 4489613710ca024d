// What every benchmark of build/bench/shadelab_bench shares: the headless context main() opens
// (SHADELAB_BACKEND=osmesa|egl) and frames timed by their passes' GPU time. The benchmarks live one
// file per lab (shading_bench.cpp, shadows_bench.cpp, ...) and host_bench.cpp for the host's own.
#pragma once
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/host/lab_host.h"

namespace shadelab {

// Each iteration is one frame, timed by the sum of its passes' GPU time (after two warm-up frames).
void timeFrames(benchmark::State& state, LabHost& host, glm::ivec2 size);

// One configuration of `lab` (its `key=value` settings, with `extra` first) timed as above, and
// labelled with the settings.
void timeConfiguration(benchmark::State& state, const char* lab, const std::vector<std::string>& config,
                       const std::vector<std::string>& extra = {});

// A bare program's depth map sampled as the labs sample theirs: nearest texels, and outside the
// map a border of depth 1 (lit). For the texture bound to `target`.
void depthMapSampling(unsigned target);

}  // namespace shadelab
