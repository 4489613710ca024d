#include "labs/shadows/light_rig.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>

#include "app/lab/params.h"

namespace shadelab {

float LightFrame::texelWorld(float depth, int resolution) const {
  const float res = float(std::max(resolution, 1));
  switch (type) {
    case LightType::Directional:
      return 2.0f * orthoHalfExtent / res;
    case LightType::Spot:
      return 2.0f * std::max(depth, nearPlane) * tanHalfFov / res;
    case LightType::Point:
      return 2.0f * std::max(depth, nearPlane) / res;
    case LightType::Count:
      break;
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
  const glm::vec3 toLight = glm::dot(s.fromPoint, s.fromPoint) > 0.0f
                                ? glm::normalize(s.fromPoint)
                                : glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
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
  if (!s.autoFit && L.nearPlane >= L.farPlane)
    warnings.push_back("light near plane is beyond its far plane: no shadows");
  if (s.type != LightType::Point && glm::length(L.position - c) < R && s.type == LightType::Spot)
    warnings.push_back("the spot light is inside the scene bounds: geometry behind it casts no shadow");
  if (s.type == LightType::Directional && !s.autoFit && s.orthoExtent < 0.5f)
    warnings.push_back("ortho extent " + formatNumber(s.orthoExtent) + " radii: most of the scene is outside the map");
  return L;
}

std::vector<glm::vec3> frustumSlice(const ViewVolume& view, float nearDepth, float farDepth) {
  std::vector<glm::vec3> corners;
  for (float depth : {nearDepth, farDepth})
    for (int c = 0; c < 4; ++c) {
      const glm::vec4 far =
          view.inverseViewProj * glm::vec4((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, 1.0f, 1.0f);
      const glm::vec3 ray = glm::vec3(far) / far.w - view.eye;
      corners.push_back(view.eye + ray * (depth / glm::dot(ray, view.forward)));
    }
  return corners;
}

namespace {

struct Plane {
  glm::vec3 n;
  float d;  // inside: dot(n, p) + d >= 0
  float at(const glm::vec3& p) const { return glm::dot(n, p) + d; }
};

// Clips the segment a-b to the inside of every plane; appends what is left's end points.
void clipSegment(glm::vec3 a, glm::vec3 b, const std::vector<Plane>& planes, std::vector<glm::vec3>& out) {
  float t0 = 0.0f, t1 = 1.0f;
  for (const Plane& pl : planes) {
    const float da = pl.at(a), db = pl.at(b);
    if (da < 0 && db < 0) return;
    if (da < 0)
      t0 = std::max(t0, da / (da - db));
    else if (db < 0)
      t1 = std::min(t1, da / (da - db));
    if (t0 > t1) return;
  }
  out.push_back(a + (b - a) * t0);
  out.push_back(a + (b - a) * t1);
}

constexpr int kBoxEdges[24] = {0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7};

}  // namespace

std::vector<glm::vec3> clipToBounds(const std::vector<glm::vec3>& slice, const Bounds& bounds) {
  std::vector<glm::vec3> out;
  if (slice.size() != 8 || bounds.min.x > bounds.max.x) return out;
  // Both are hexahedra with corners indexed by bits (x, y, near/far): the same 12 edges.
  std::vector<Plane> box;
  for (int a = 0; a < 3; ++a) {  // a little slack: a floor's box is flat, and must still clip to itself
    glm::vec3 n(0.0f);
    n[a] = 1.0f;
    box.push_back({n, -bounds.min[a] + 1e-5f * (std::abs(bounds.min[a]) + 1.0f)});
    box.push_back({-n, bounds.max[a] + 1e-5f * (std::abs(bounds.max[a]) + 1.0f)});
  }
  const glm::vec3 centre = [&] {
    glm::vec3 c(0.0f);
    for (auto& p : slice) c += p;
    return c / 8.0f;
  }();
  std::vector<Plane> frustum;
  const int faces[6][3] = {{0, 1, 2}, {4, 5, 6}, {0, 1, 4}, {2, 3, 6}, {0, 2, 4}, {1, 3, 5}};
  for (auto& f : faces) {
    glm::vec3 n = glm::cross(slice[f[1]] - slice[f[0]], slice[f[2]] - slice[f[0]]);
    if (glm::dot(n, n) == 0.0f) continue;  // a degenerate face (near depth 0): the others bound it
    n = glm::normalize(n);
    Plane pl{n, -glm::dot(n, slice[f[0]])};
    if (pl.at(centre) < 0) pl = {-n, -pl.d};
    pl.d += 1e-5f * (std::abs(pl.d) + 1.0f);  // points on the face count as inside
    frustum.push_back(pl);
  }
  for (int e = 0; e < 24; e += 2) {
    clipSegment(slice[size_t(kBoxEdges[e])], slice[size_t(kBoxEdges[e + 1])], box, out);
    clipSegment(bounds.corner(kBoxEdges[e]), bounds.corner(kBoxEdges[e + 1]), frustum, out);
  }
  return out;
}

std::vector<glm::vec3> clipToParts(const std::vector<glm::vec3>& slice, const std::vector<Bounds>& parts) {
  std::vector<glm::vec3> out;
  for (const Bounds& part : parts) {
    const auto piece = clipToBounds(slice, part);
    out.insert(out.end(), piece.begin(), piece.end());
  }
  return out;
}

glm::vec2 visibleDepthRange(const ViewVolume& view, const std::vector<Bounds>& parts) {
  const auto pts = clipToParts(frustumSlice(view, view.nearPlane, view.farPlane), parts);
  if (pts.empty()) return glm::vec2(0.0f);
  glm::vec2 range(view.farPlane, view.nearPlane);
  for (auto& p : pts) {
    const float d = glm::dot(p - view.eye, view.forward);
    range = {std::min(range.x, d), std::max(range.y, d)};
  }
  return glm::clamp(range, glm::vec2(view.nearPlane), glm::vec2(view.farPlane));
}

std::vector<float> practicalSplits(int count, float n, float f, float lambda) {
  std::vector<float> splits;
  n = std::max(n, 1e-30f);
  for (int i = 0; i <= count; ++i) {
    const float t = float(i) / float(std::max(count, 1));
    splits.push_back(lambda * n * std::pow(f / n, t) + (1.0f - lambda) * (n + (f - n) * t));
  }
  splits.front() = n;
  splits.back() = f;  // exactly, whatever pow rounds to
  return splits;
}

LightFrame fitDirectional(const LightFrame& sceneFit, const std::vector<glm::vec3>& points, const Bounds& bounds,
                          int mapSize, bool snap, float marginTexels) {
  if (points.empty()) return sceneFit;
  LightFrame L = sceneFit;
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (auto& p : points) {
    const glm::vec3 v = glm::vec3(L.view * glm::vec4(p, 1.0f));
    lo = glm::min(lo, glm::vec2(v));
    hi = glm::max(hi, glm::vec2(v));
  }
  const float size = float(std::max(mapSize, 1));
  // Square texels: the larger side decides; a few texels of margin keep filter taps on the map.
  float half = 0.5f * std::max(hi.x - lo.x, hi.y - lo.y);
  half = std::max(half * size / (size - 2.0f * marginTexels), 1e-6f * bounds.radius());
  glm::vec2 centre = 0.5f * (lo + hi);
  if (snap) {
    half = std::exp2(std::ceil(std::log2(half) * 8.0f) / 8.0f);
    const float texel = 2.0f * half / size;
    centre = glm::round(centre / texel) * texel;
  }
  // Depth: every corner of the scene, so casters outside the camera's view still cast.
  float zNear = INFINITY, zFar = -INFINITY;
  for (int c = 0; c < 8; ++c) {
    const float z = -(L.view * glm::vec4(bounds.corner(c), 1.0f)).z;
    zNear = std::min(zNear, z);
    zFar = std::max(zFar, z);
  }
  const float pad = 1e-3f * std::max(zFar - zNear, 1e-30f);
  L.nearPlane = zNear - pad;
  L.farPlane = zFar + pad;
  L.orthoHalfExtent = half;
  L.orthoCentre = centre;
  L.proj = glm::ortho(centre.x - half, centre.x + half, centre.y - half, centre.y + half, L.nearPlane, L.farPlane);
  L.viewProj = L.proj * L.view;
  return L;
}

glm::vec4 cascadeBox(const LightFrame& first, const LightFrame& cascade) {
  const float h = std::max(cascade.orthoHalfExtent, 1e-30f);
  const glm::vec2 t = (first.orthoCentre - cascade.orthoCentre) / h;
  return {first.orthoHalfExtent / h, t.x, t.y, cascade.orthoHalfExtent};
}

std::vector<Cascade> buildCascades(const LightFrame& sceneFit, const CascadeSetup& setup, const ViewVolume& view,
                                   const Bounds& bounds, const std::vector<Bounds>& someParts,
                                   std::optional<glm::vec2> drawn) {
  const std::vector<Bounds> parts = someParts.empty() ? std::vector<Bounds>{bounds} : someParts;
  glm::vec2 range = visibleDepthRange(view, parts);
  // What was drawn lies inside what could be seen, but for rounding: a hair around it, kept inside.
  if (drawn && drawn->y >= drawn->x && range.y > range.x) {
    const float pad = 1e-3f * (drawn->y - drawn->x) + 1e-6f * drawn->y;
    const glm::vec2 both(std::max(range.x, drawn->x - pad), std::min(range.y, drawn->y + pad));
    if (both.y > both.x) range = both;
  }
  // What a map holds, in light depth: for the depth view, which stretches it over black..white.
  auto contentDepth = [&](const LightFrame& L, const std::vector<glm::vec3>& pts) {
    glm::vec2 r(INFINITY, -INFINITY);
    for (auto& p : pts) {
      const float d = glm::dot(p - L.position, L.direction);
      r = {std::min(r.x, d), std::max(r.y, d)};
    }
    return pts.empty() ? glm::vec2(L.nearPlane, L.farPlane) : r;
  };
  if (range.y <= range.x) {
    std::vector<glm::vec3> corners;
    for (int c = 0; c < 8; ++c) corners.push_back(bounds.corner(c));
    return {{sceneFit, view.farPlane, view.farPlane, contentDepth(sceneFit, corners)}};
  }
  const int count = std::clamp(setup.count, 1, 4);
  const std::vector<float> splits = practicalSplits(count, range.x, range.y, setup.lambda);
  std::vector<Cascade> cascades;
  float from = splits[0];  // where this cascade's slice starts: the previous one's blend band included
  for (int i = 0; i < count; ++i) {
    const float to = splits[size_t(i) + 1];
    const float band = i + 1 < count ? setup.blend * (to - splits[size_t(i)]) : 0.0f;
    const auto pts = clipToParts(frustumSlice(view, from, to), parts);
    const LightFrame fitted = fitDirectional(sceneFit, pts, bounds, setup.mapSize, setup.snap);
    cascades.push_back({fitted, to, to - band, contentDepth(fitted, pts), range});
    from = to - band;
  }
  cascades.back().splitFar = cascades.back().blendFrom = view.farPlane;  // the last one takes the rest
  return cascades;
}

float minimumSpacing(const std::vector<glm::vec2>& pts) {
  float best = INFINITY;
  for (size_t i = 0; i < pts.size(); ++i)
    for (size_t j = i + 1; j < pts.size(); ++j) best = std::min(best, glm::distance(pts[i], pts[j]));
  return best;
}

float spacingBound(int count) {
  // n (d/2)^2 <= (pi / sqrt 12) (1 + d/2)^2  =>  d <= 2 k / (sqrt n - k), k = sqrt(pi / sqrt 12).
  const float k = std::sqrt(3.14159265f / std::sqrt(12.0f));
  return 2.0f * k / (std::sqrt(float(count)) - k);
}

std::vector<glm::vec2> poissonDisk(int count) {
  std::vector<glm::vec2> best;
  for (uint32_t seed = 1; seed <= 16; ++seed) {
    std::vector<glm::vec2> pts;
    uint32_t state = 0x9E3779B9u * seed;
    auto rnd = [&] {  // xorshift32: the same disk on every machine
      state ^= state << 13;
      state ^= state >> 17;
      state ^= state << 5;
      return float(state) / 4294967296.0f;
    };
    // Start at the packing bound and relax slowly whenever a point cannot be placed.
    float minDist = spacingBound(std::max(count, 2));
    while (int(pts.size()) < count) {
      bool placed = false;
      for (int attempt = 0; attempt < 500 && !placed; ++attempt) {
        const glm::vec2 p(rnd() * 2 - 1, rnd() * 2 - 1);
        if (glm::dot(p, p) > 1.0f) continue;
        placed =
            std::all_of(pts.begin(), pts.end(), [&](const glm::vec2& q) { return glm::distance(p, q) >= minDist; });
        if (placed) pts.push_back(p);
      }
      if (!placed) minDist *= 0.98f;
    }
    if (best.empty() || minimumSpacing(pts) > minimumSpacing(best)) best = std::move(pts);
  }
  return best;
}

}  // namespace shadelab
