#include "labs/shadows/light_rig.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>

#include "labs/params.h"

namespace shadelab {

float LightFrame::texelWorld(float depth, int resolution) const {
  const float res = float(std::max(resolution, 1));
  switch (type) {
    case LightType::Directional: return 2.0f * orthoHalfExtent / res;
    case LightType::Spot: return 2.0f * std::max(depth, nearPlane) * tanHalfFov / res;
    case LightType::Point: return 2.0f * std::max(depth, nearPlane) / res;
  }
  return 0.0f;
}

static glm::vec3 upFor(const glm::vec3& dir) {
  return std::abs(dir.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
}

LightFrame buildLight(const LightSetup& s, const Bounds& bounds, std::vector<std::string>& warnings) {
  LightFrame L;
  L.type = s.type;
  const glm::vec3 c = bounds.center();
  const float R = std::max(bounds.radius(), 1e-30f);
  const float el = glm::radians(s.elevationDeg), az = glm::radians(s.azimuthDeg);
  const glm::vec3 toLight(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
  L.direction = -toLight;

  if (s.type == LightType::Directional) {
    // The box is centred on the scene; the eye sits two radii out along the light.
    L.position = c + toLight * (2.0f * R);
    L.orthoHalfExtent = (s.autoFit ? 1.0f : s.orthoExtent) * R;
    L.nearPlane = (s.autoFit ? 1.0f : s.nearPlane) * R;
    L.farPlane = (s.autoFit ? 3.0f : s.farPlane) * R;
    L.view = glm::lookAt(L.position, c, upFor(L.direction));
    const float e = L.orthoHalfExtent;
    L.proj = glm::ortho(-e, e, -e, e, L.nearPlane, L.farPlane);
    // Angular radius: a light of `radius` scene radii seen from three radii away.
    L.radiusWorld = s.radius / 3.0f;
  } else {
    L.position = c + toLight * (s.distance * R);
    const float d = s.distance * R;
    L.nearPlane = s.autoFit ? std::max(d - R, 0.01f * R) : s.nearPlane * R;
    L.farPlane = s.autoFit ? d + R : s.farPlane * R;
    L.radiusWorld = s.radius * R;
    if (s.type == LightType::Spot) {
      L.tanHalfFov = std::tan(glm::radians(std::clamp(s.spotAngleDeg, 1.0f, 170.0f)) * 0.5f);
      L.view = glm::lookAt(L.position, c, upFor(L.direction));
      L.proj = glm::perspective(glm::radians(std::clamp(s.spotAngleDeg, 1.0f, 170.0f)), 1.0f, L.nearPlane, L.farPlane);
    } else {
      L.tanHalfFov = 1.0f;
      if (s.autoFit) L.nearPlane = 0.01f * R;  // a point light sees all around: the scene may be anywhere
      L.view = glm::mat4(1.0f);
      L.proj = glm::perspective(glm::radians(90.0f), 1.0f, L.nearPlane, L.farPlane);
      static const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
      for (int f = 0; f < 6; ++f) L.faceViewProj[f] = L.proj * glm::lookAt(L.position, L.position + dirs[f], ups[f]);
    }
  }
  L.viewProj = L.proj * L.view;

  // Warnings a student should see.
  const float ratio = L.farPlane / std::max(L.nearPlane, 1e-30f);
  if (s.type != LightType::Directional && ratio > 1e4f)
    warnings.push_back("light far/near ratio " + formatNumber(ratio) +
                       ": perspective depth keeps almost no precision far from the light (acne and leaks)");
  if (!s.autoFit && L.nearPlane >= L.farPlane) warnings.push_back("light near plane is beyond its far plane: no shadows");
  if (s.type != LightType::Point && glm::length(L.position - c) < R && s.type == LightType::Spot)
    warnings.push_back("the spot light is inside the scene bounds: geometry behind it casts no shadow");
  if (s.type == LightType::Directional && !s.autoFit && s.orthoExtent < 0.5f)
    warnings.push_back("ortho extent " + formatNumber(s.orthoExtent) + " radii: most of the scene is outside the map");
  return L;
}

std::vector<glm::vec2> poissonDisk(int count) {
  std::vector<glm::vec2> pts;
  uint32_t state = 0x9E3779B9u;
  auto rnd = [&] {  // xorshift32: the same disk on every machine
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return float(state) / 4294967296.0f;
  };
  // Minimum distance for `count` well-spread points in the unit disk, relaxed whenever a point
  // cannot be placed after many tries.
  float minDist = 1.6f / std::sqrt(float(std::max(count, 1)));
  while (int(pts.size()) < count) {
    bool placed = false;
    for (int attempt = 0; attempt < 2000 && !placed; ++attempt) {
      const glm::vec2 p(rnd() * 2 - 1, rnd() * 2 - 1);
      if (glm::dot(p, p) > 1.0f) continue;
      placed = std::all_of(pts.begin(), pts.end(), [&](const glm::vec2& q) { return glm::distance(p, q) >= minDist; });
      if (placed) pts.push_back(p);
    }
    if (!placed) minDist *= 0.95f;
  }
  return pts;
}

}  // namespace shadelab
