#include "labs/denoise/mesh_noise.h"

#include <cmath>
#include <random>

#include <glm/gtc/constants.hpp>

namespace shadelab {

std::vector<glm::dvec3> vertexNormalsOf(std::span<const glm::dvec3> p, std::span<const uint32_t> idx) {
  std::vector<glm::dvec3> n(p.size(), glm::dvec3(0.0));
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    const glm::dvec3 c = glm::cross(p[idx[t + 1]] - p[idx[t]], p[idx[t + 2]] - p[idx[t]]);
    if (!std::isfinite(c.x + c.y + c.z)) continue;
    for (int k = 0; k < 3; ++k) n[idx[t + size_t(k)]] += c;
  }
  for (auto& v : n) {
    const double len = glm::length(v);
    v = len > 1e-300 && std::isfinite(len) ? v / len : glm::dvec3(0, 0, 1);
  }
  return n;
}

double meanEdgeLengthOf(std::span<const glm::dvec3> p, std::span<const uint32_t> idx) {
  double sum = 0.0;
  for (size_t t = 0; t + 2 < idx.size(); t += 3)
    for (int e = 0; e < 3; ++e) sum += glm::length(p[idx[t + size_t(e)]] - p[idx[t + size_t((e + 1) % 3)]]);
  return idx.size() >= 3 ? sum / double(idx.size()) : 0.0;
}

std::vector<glm::dvec3> addNoise(std::span<const glm::dvec3> p, std::span<const uint32_t> idx, const NoiseSettings& s) {
  const std::vector<glm::dvec3> n = vertexNormalsOf(p, idx);
  const double sigma = s.level * meanEdgeLengthOf(p, idx);
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
