#include "app/scene/camera.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "app/util/format.h"

namespace shadelab {

glm::vec3 OrbitCamera::eye() const {
  const float yaw = glm::radians(yawDeg), pitch = glm::radians(pitchDeg);
  const glm::vec3 dir(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  return target + dir * distance;
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), target, glm::vec3(0, 1, 0)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
  // fov spans the *smaller* side of the image, so a framed scene stays framed in a tall viewport.
  float fovY = glm::radians(fovYDeg);
  if (aspect < 1.0f) fovY = 2.0f * std::atan(std::tan(fovY * 0.5f) / aspect);
  return glm::perspective(fovY, aspect, nearPlane, farPlane);
}

void OrbitCamera::frame(const glm::vec3& center, float radius) {
  target = center;
  radius = std::max(radius, 1e-4f);
  distance = radius / std::sin(glm::radians(fovYDeg) * 0.5f);  // the sphere just fits
  fitDepthRange(center, radius);
}

void OrbitCamera::fitDepthRange(const glm::vec3& center, float radius) {
  const float d = glm::length(eye() - center);
  radius = std::max(radius, 1e-4f);
  nearPlane = std::max(d - radius * 1.5f, radius * 1e-3f);
  farPlane = d + radius * 1.5f;
}

void OrbitCamera::orbit(float dYaw, float dPitch) {
  yawDeg = std::fmod(yawDeg + dYaw, 360.0f);
  pitchDeg = glm::clamp(pitchDeg + dPitch, -89.0f, 89.0f);
}

void OrbitCamera::pan(float dx, float dy) {
  const glm::mat4 v = view();
  const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
  const float scale = 2.0f * distance * std::tan(glm::radians(fovYDeg) * 0.5f);
  target += (-dx * right + dy * up) * scale;
}

void OrbitCamera::zoom(float factor) {
  const float old = distance;
  distance = glm::clamp(distance * factor, 1e-4f, 1e6f);
  // Keep the depth range around the target as we move.
  nearPlane *= distance / old;
  farPlane *= distance / old;
}

std::string OrbitCamera::toString() const {
  auto f = [](float v) { return formatNumber(v); };
  return "yaw=" + f(yawDeg) + ",pitch=" + f(pitchDeg) + ",distance=" + f(distance) + ",target=" + f(target.x) + ";" +
         f(target.y) + ";" + f(target.z) + ",fov=" + f(fovYDeg) + ",near=" + f(nearPlane) + ",far=" + f(farPlane);
}

std::string OrbitCamera::parse(const std::string& text) {
  static const char* kValid = "yaw, pitch, distance, target=x;y;z, fov, near, far";
  std::stringstream ss(text);
  std::string item;
  OrbitCamera c = *this;
  while (std::getline(ss, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) return "--camera: '" + item + "' is not key=value (valid keys: " + kValid + ")";
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    auto number = [&](float& out) {
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      if (value.empty() || *end || !std::isfinite(v)) return false;
      out = float(v);
      return true;
    };
    bool ok = true;
    if (key == "yaw")
      ok = number(c.yawDeg);
    else if (key == "pitch")
      ok = number(c.pitchDeg) && std::abs(c.pitchDeg) < 90.0f;
    else if (key == "distance")
      ok = number(c.distance) && c.distance > 0;
    else if (key == "fov")
      ok = number(c.fovYDeg) && c.fovYDeg > 1 && c.fovYDeg < 179;
    else if (key == "near")
      ok = number(c.nearPlane) && c.nearPlane > 0;
    else if (key == "far")
      ok = number(c.farPlane) && c.farPlane > 0;
    else if (key == "target") {
      float xyz[3];
      std::stringstream vs(value);
      std::string part;
      int n = 0;
      while (ok && std::getline(vs, part, ';')) {
        char* end = nullptr;
        xyz[n < 3 ? n : 2] = float(std::strtod(part.c_str(), &end));
        ok = !part.empty() && !*end && ++n <= 3;
      }
      ok = ok && n == 3;
      if (ok) c.target = {xyz[0], xyz[1], xyz[2]};
    } else {
      return "--camera: unknown key '" + key + "' (valid keys: " + kValid + ")";
    }
    if (!ok) return "--camera: bad value for " + key + ": '" + value + "'";
  }
  if (c.nearPlane >= c.farPlane) return "--camera: near must be smaller than far";
  *this = c;
  return {};
}

}  // namespace shadelab
