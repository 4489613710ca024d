// Where a shadow-casting light is and what its shadow map sees: pure CPU math, unit-tested.
// Every length the student sets is in scene radii, so a scene at scale 1e-3 or 1e4 behaves alike.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/scene/mesh.h"

namespace shadelab {

enum class LightType { Directional, Spot, Point, Count };

// Where a light is and how large: the shadows lab's key-light parameters.
struct LightPlacement {
  LightType type = LightType::Directional;
  float elevationDeg = 40.0f;  // above the horizon; near 0 the light grazes the ground
  float azimuthDeg = 35.0f;    // around the vertical axis
  float distance = 3.0f;       // spot/point: from the scene centre, in scene radii
  float spotAngleDeg = 70.0f;  // spot: full cone angle (and its map's field of view)
  float radius = 0.08f;        // area-light radius in scene radii (PCSS and its truth; 0: a point)
};

// What the light's map covers when it is not fitted to the scene.
struct LightFrustum {
  bool autoFit = true;       // fit extent and near/far to the scene bounds
  float orthoExtent = 1.0f;  // directional, !autoFit: half-width of the box, in scene radii
  float nearPlane = 0.5f;    // !autoFit: in scene radii
  float farPlane = 5.0f;     // !autoFit: in scene radii
};

struct LightSetup : LightPlacement, LightFrustum {
  glm::vec3 fromPoint{0.0f};  // nonzero: the light shines from this point towards the origin
                              // (overrides azimuth and elevation; a scene's own light)
};

struct LightFrame {
  LightType type = LightType::Directional;
  glm::vec3 position{0.0f};       // spot/point (directional: the eye of the ortho box)
  glm::vec3 direction{0, -1, 0};  // unit, from the light into the scene (directional/spot axis)
  glm::mat4 view{1.0f}, proj{1.0f}, viewProj{1.0f};
  // Point: +X -X +Y -Y +Z -Z, GL cube-map face order. Identity for the others (glm leaves a
  // default-constructed matrix uninitialised, which the sanitizer build caught being read).
  glm::mat4 faceViewProj[6]{glm::mat4(1.0f), glm::mat4(1.0f), glm::mat4(1.0f),
                            glm::mat4(1.0f), glm::mat4(1.0f), glm::mat4(1.0f)};
  float nearPlane = 0.1f, farPlane = 10.0f;
  float orthoHalfExtent = 1.0f;  // directional
  float tanHalfFov = 1.0f;       // spot (point faces: 1)
  float radiusWorld = 0.0f;      // area-light radius (directional: tangent of the angular radius)
  glm::vec2 orthoCentre{0.0f};   // directional: the box's centre in light view space (0: on the scene)

  // World size of one shadow-map texel at `depth` (distance along the light's axis, or from a
  // point light), for a map of `resolution` texels across.
  float texelWorld(float depth, int resolution) const;
};

// A cascade as the lit shader reads it (shaders/shadows/lit.frag, cascadeLight): its box relative
// to the first cascade's, (s, t.x, t.y, half extent) with clip.xy = s * first's clip.xy + t. The
// cascades of one light share its view and its depth range (fitDirectional keeps both), so that
// is all that differs between their matrices.
glm::vec4 cascadeBox(const LightFrame& first, const LightFrame& cascade);

// Builds the light for `bounds`. Adds a line to `warnings` for configurations that cannot work
// well (the scene outside the light's frustum, near/far ratio beyond depth precision, ...).
LightFrame buildLight(const LightSetup& setup, const Bounds& bounds, std::vector<std::string>& warnings);

// The camera as a fitted shadow map sees it.
struct ViewVolume {
  glm::mat4 inverseViewProj{1.0f};  // NDC -> world
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit
  float nearPlane = 0.05f, farPlane = 100.0f;
};

// The eight corners of the camera frustum between view depths `nearDepth` and `farDepth`
// (distances along `forward`): near face then far face.
std::vector<glm::vec3> frustumSlice(const ViewVolume& view, float nearDepth, float farDepth);
// The vertices of the convex slice intersected with `bounds`: corners of either inside the
// other, and where edges of one cross faces of the other. Empty when they do not meet.
std::vector<glm::vec3> clipToBounds(const std::vector<glm::vec3>& slice, const Bounds& bounds);
// The view-depth range of the part of the scene the camera can see: (nearest, farthest), or
// (0, 0) when the frustum misses every box of `parts` (the instances' world boxes: tighter than
// the scene's one box, which includes the empty air above a floor).
glm::vec2 visibleDepthRange(const ViewVolume& view, const std::vector<Bounds>& parts);
// The slice's intersection with each part, every vertex of every piece.
std::vector<glm::vec3> clipToParts(const std::vector<glm::vec3>& slice, const std::vector<Bounds>& parts);
// Cascade boundaries by the practical split scheme (Zhang et al., "Parallel-split shadow maps",
// 2006): C_i = lambda n (f/n)^(i/N) + (1 - lambda) (n + (f - n) i/N), i = 0..N.
std::vector<float> practicalSplits(int count, float nearDepth, float farDepth, float lambda);
// A directional light refitted around `points`: the same light-view axes as `sceneFit` (so the
// texel grid is fixed in world space), x/y hugging the points with a margin of `marginTexels`,
// depth spanning the whole scene (every caster between the light and the points). `snap`
// quantises the half-width to 1/8 octaves and moves the centre by whole texels: a camera move
// smaller than a texel leaves the map unchanged, so its shadows do not shimmer.
LightFrame fitDirectional(const LightFrame& sceneFit, const std::vector<glm::vec3>& points, const Bounds& bounds,
                          int mapSize, bool snap, float marginTexels = 4.0f);

struct CascadeSetup {
  int count = 1;         // 1: one map fitted to everything the camera sees
  float lambda = 0.75f;  // split scheme: 0 uniform, 1 logarithmic
  float blend = 0.1f;    // fraction of each cascade's range blended into the next
  bool snap = true;
  int mapSize = 1024;
};

struct Cascade {
  LightFrame light;
  float splitFar = 0.0f;         // view depth where this cascade hands over to the next
  float blendFrom = 0.0f;        // view depth where blending into the next begins (= splitFar: none)
  glm::vec2 contentDepth{0.0f};  // light depth of what the cascade covers: (nearest, farthest)
  glm::vec2 splitRange{0.0f};    // the view depths the whole set was split over (the same in each)
};

// Directional cascades for what the camera sees of `parts` (each instance's world box; empty:
// the scene's box); depth always spans `bounds`, so every caster is drawn. Falls back to
// `sceneFit` (one cascade) when the camera sees none of the scene. `drawn`: the view depths the
// camera really drew (its depth buffer's nearest and farthest, DepthRange): the splits run over
// the part of the frustum's range inside it.
std::vector<Cascade> buildCascades(const LightFrame& sceneFit, const CascadeSetup& setup, const ViewVolume& view,
                                   const Bounds& bounds, const std::vector<Bounds>& parts = {},
                                   std::optional<glm::vec2> drawn = std::nullopt);

// Deterministic Poisson-disk samples in the unit disk, made for exactly `count` points (never a
// prefix of a larger set, whose first points are badly spread): dart throwing from a large
// minimum distance downwards, best of several seeds by minimum spacing.
std::vector<glm::vec2> poissonDisk(int count);
// The smallest distance between two points of `pts`.
float minimumSpacing(const std::vector<glm::vec2>& pts);
// An upper bound on the minimum spacing any `count` points in the unit disk can have: disks of
// radius d/2 around them fit inside a disk of radius 1 + d/2 at most at the hexagonal density
// pi / sqrt(12).
float spacingBound(int count);

}  // namespace shadelab
