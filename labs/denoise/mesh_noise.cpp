#include "labs/denoise/mesh_noise.h"

#include <cmath>
#include <random>

#include <glm/gtc/constants.hpp>

#include "app/scene/mesh_topology.h"

namespace shadelab {

std::vector<glm::dvec3> addNoise(std::span<const glm::dvec3> p, std::span<const uint32_t> idx, const NoiseSettings& s) {
  const std::vector<glm::dvec3> n = vertexNormals(p, idx, NormalWeighting::Area);
  const double sigma = s.level * meanEdgeLength(p, idx);
  std::mt19937 rng(s.seed);
  auto uniform = [&] { return (double(rng()) + 0.5) / 4294967296.0; };  // (0, 1), never 0
  auto gaussian = [&] { return std::sqrt(-2.0 * std::log(uniform())) * std::cos(glm::two_pi<double>() * uniform()); };
  std::vector<glm::dvec3> out(p.begin(), p.end());
  for (size_t v = 0; v < out.size(); ++v) {
    const bool hit = s.kind == NoiseKind::Gaussian || uniform() < s.impulsiveFraction;
    const double amount = gaussian();  // drawn for every vertex, so the fraction changes only which move
    if (hit) out[v] += n[v] * (sigma * amount);
  }
  return out;
}

}  // namespace shadelab
