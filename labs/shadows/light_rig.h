// Where a shadow-casting light is and what its shadow map sees: pure CPU math, unit-tested.
// Every length the student sets is in scene radii, so a scene at scale 1e-3 or 1e4 behaves alike.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"

namespace shadelab {

enum class LightType { Directional, Spot, Point };

struct LightSetup {
  LightType type = LightType::Directional;
  float azimuthDeg = 35.0f;
  float elevationDeg = 50.0f;   // above the horizon; near 0 the light grazes the ground
  float distance = 3.0f;        // spot/point: from the scene centre, in scene radii
  float spotAngleDeg = 60.0f;   // spot: full cone angle
  float radius = 0.0f;          // area-light radius in scene radii (0 = point-like, hard shadows)
  bool autoFit = true;          // fit extent and near/far to the scene bounds
  float orthoExtent = 1.0f;     // directional, !autoFit: half-width of the box, in scene radii
  float nearPlane = 0.5f;       // !autoFit: in scene radii
  float farPlane = 5.0f;        // !autoFit: in scene radii
};

struct LightFrame {
  LightType type = LightType::Directional;
  glm::vec3 position{0.0f};  // spot/point (directional: the eye of the ortho box)
  glm::vec3 direction{0, -1, 0};  // unit, from the light into the scene (directional/spot axis)
  glm::mat4 view{1.0f}, proj{1.0f}, viewProj{1.0f};
  glm::mat4 faceViewProj[6];  // point: +X -X +Y -Y +Z -Z, GL cube-map face order
  float nearPlane = 0.1f, farPlane = 10.0f;
  float orthoHalfExtent = 1.0f;  // directional
  float tanHalfFov = 1.0f;       // spot (point faces: 1)
  float radiusWorld = 0.0f;      // area-light radius (directional: tangent of the angular radius)

  // World size of one shadow-map texel at `depth` (distance along the light's axis, or from a
  // point light), for a map of `resolution` texels across.
  float texelWorld(float depth, int resolution) const;
};

// Builds the light for `bounds`. Adds a line to `warnings` for configurations that cannot work
// well (the scene outside the light's frustum, near/far ratio beyond depth precision, ...).
LightFrame buildLight(const LightSetup& setup, const Bounds& bounds, std::vector<std::string>& warnings);

// Deterministic Poisson-disk samples in the unit disk (dart throwing, fixed seed): well spread,
// so few samples hide the grid of a PCF kernel.
std::vector<glm::vec2> poissonDisk(int count);

}  // namespace shadelab
