// An orbit camera: the student drags around a target; headless runs fix it on the command line
// as --camera yaw=30,pitch=20,distance=4,target=0;0.5;0,fov=45.
#pragma once
#include <string>

#include <glm/glm.hpp>

namespace shadelab {

struct OrbitCamera {
  glm::vec3 target{0.0f};
  float distance = 4.0f;   // world units from target
  float yawDeg = 30.0f;    // around +Y, 0 = looking down -Z
  float pitchDeg = 25.0f;  // above the horizon; clamped to (-89, 89)
  float fovYDeg = 45.0f;   // across the smaller side of the image
  float nearPlane = 0.05f;
  float farPlane = 100.0f;

  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  // Frames a bounding sphere, keeping yaw and pitch; near/far hug the sphere so depth precision
  // is spent where the scene is.
  void frame(const glm::vec3& center, float radius);
  // near/far around a bounding sphere seen from the current eye.
  void fitDepthRange(const glm::vec3& center, float radius);
  void orbit(float dYawDeg, float dPitchDeg);
  void pan(float dx, float dy);  // in units of the view height at the target
  void zoom(float factor);       // distance *= factor

  std::string toString() const;
  // Parses "yaw=..,pitch=..,distance=..,target=x;y;z,fov=..,near=..,far=.." (any subset).
  // Returns "" or an error naming the bad key and the valid ones.
  std::string parse(const std::string& text);
};

}  // namespace shadelab
