// Noise the way the denoising literature adds it (and the Guided Mesh Normal Filtering data was
// made): each vertex moves along its normal by a Gaussian amount with sigma = level x the mean
// edge length, so one level means the same roughness on any mesh at any scale. Impulsive noise
// moves only a random fraction of the vertices, by the same distribution.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "app/lab/technique.h"

namespace shadelab {

enum class NoiseKind { Gaussian, Impulsive, Count };
inline constexpr Named<NoiseKind> kNoiseKinds[] = {{NoiseKind::Gaussian, "gaussian"},
                                                   {NoiseKind::Impulsive, "impulsive"}};
static_assert(coversEnum<NoiseKind>(kNoiseKinds));

struct NoiseSettings {
  NoiseKind kind = NoiseKind::Gaussian;
  float level = 0.3f;              // sigma in mean edge lengths
  float impulsiveFraction = 0.1f;  // of the vertices, for impulsive noise
  int seed = 1;                    // 0 .. 1e6
  bool operator==(const NoiseSettings&) const = default;
};

// Deterministic for a given seed (the same noise on every machine: std::mt19937 and our own
// Box-Muller, not std::normal_distribution, whose output the standard leaves open).
std::vector<glm::dvec3> addNoise(std::span<const glm::dvec3> positions, std::span<const uint32_t> indices,
                                 const NoiseSettings& settings);

}  // namespace shadelab
