#include "labs/shadows/ray_visibility.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

#include <glm/gtc/constants.hpp>

namespace shadelab {

namespace {

void basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  t = glm::normalize(glm::cross(std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0), n));
  b = glm::cross(n, t);
}

}  // namespace

glm::vec2 stratifiedDiskSample(int i, int j, int n) {
  const float a = 2.0f * (i + 0.5f) / float(n) - 1.0f, b = 2.0f * (j + 0.5f) / float(n) - 1.0f;
  if (a == 0.0f && b == 0.0f) return glm::vec2(0.0f);
  float r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = glm::quarter_pi<float>() * (b / a);
  } else {
    r = b;
    phi = glm::half_pi<float>() - glm::quarter_pi<float>() * (a / b);
  }
  return r * glm::vec2(std::cos(phi), std::sin(phi));
}

ImageF rayTracedVisibility(const RayScene& scene, const LightFrame& light, const ImageF& positions,
                           const ImageF& normals, int samplesPerAxis, float epsilon, JobContext* job) {
  ImageF out;
  out.size = positions.size;
  out.rgba.assign(positions.rgba.size(), 0.0f);
  const int n = light.radiusWorld > 0.0f ? std::max(samplesPerAxis, 1) : 1;
  std::atomic<int> rowsDone{0};
  std::atomic<bool> stop{false};
  const int rows = positions.size.y;
  auto shade = [&](int y0, int y1) {
    for (int y = y0; y < y1 && !stop; ++y) {
      for (int x = 0; x < positions.size.x; ++x) {
        const float* p = positions.at(x, y);
        float* o = out.at(x, y);
        o[3] = p[3] > 0.5f ? 1.0f : 0.0f;
        if (o[3] == 0.0f) continue;
        const glm::vec3 P(p[0], p[1], p[2]), N(normals.at(x, y)[0], normals.at(x, y)[1], normals.at(x, y)[2]);
        const glm::vec3 origin = P + N * epsilon;
        // A ray towards the point `d` (unit disk) of the light's disk; true when it gets through.
        auto reaches = [&](glm::vec2 d) {
          glm::vec3 dir;
          float dist;
          if (light.type == LightType::Directional) {
            glm::vec3 t, b;
            basis(-light.direction, t, b);
            dir = glm::normalize(-light.direction + (t * d.x + b * d.y) * light.radiusWorld);
            dist = std::numeric_limits<float>::infinity();
          } else {
            const glm::vec3 toCentre = light.position - origin;
            glm::vec3 t, b;
            basis(glm::normalize(toCentre), t, b);
            const glm::vec3 target = light.position + (t * d.x + b * d.y) * light.radiusWorld;
            dir = target - origin;
            dist = 1.0f;  // the ray is origin + dir * t, t in [0, 1): stop at the light
          }
          return !scene.occluded(origin, dir, dist);
        };
        const float hard = reaches(glm::vec2(0.0f)) ? 1.0f : 0.0f;
        float area = hard;
        if (n > 1) {
          int lit = 0;
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) lit += reaches(stratifiedDiskSample(i, j, n));
          area = float(lit) / float(n * n);
        }
        o[0] = hard;
        o[1] = o[2] = area;
      }
      const int done = ++rowsDone;
      // One thread reports (JobContext is thread-safe, but one voice is enough).
      if (job && y0 == 0 &&
          !job->progress(float(done) / float(rows),
                         "shadow rays, row " + std::to_string(done) + " of " + std::to_string(rows)))
        stop = true;
      if (job && job->cancelled()) stop = true;
    }
  };
  const int threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(shade, rows * t / threads, rows * (t + 1) / threads);
  for (auto& th : pool) th.join();
  return out;
}

}  // namespace shadelab
