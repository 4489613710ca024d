#include "app/scene/procedural.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace shadelab {

// A (cols+1) x (rows+1) vertex grid, parameterised over [0,1]^2 by `at`, wound counter-clockwise
// when seen from where `at`'s normal points.
template <typename F>
static MeshData grid(int cols, int rows, F at) {
  MeshData m;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i) {
      const glm::vec2 uv(float(i) / cols, float(j) / rows);
      glm::vec3 p, n;
      at(uv, p, n);
      m.positions.push_back(p);
      m.normals.push_back(n);
      m.uvs.push_back(uv);
    }
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const uint32_t a = uint32_t(j * (cols + 1) + i), b = a + 1, c = a + uint32_t(cols + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  return m;
}

// sin and cos of 2 pi t, exact at the seam: t = 1 gives what t = 0 gives, so copies of a seam
// vertex have bit-identical positions (and weld), which sin(2 pi) = -1.7e-7 in float would break.
static glm::vec2 cosSinTurn(float t) {
  if (t == 0.0f || t == 1.0f) return {1.0f, 0.0f};
  const float a = t * glm::two_pi<float>();
  return {std::cos(a), std::sin(a)};
}

MeshData makeUvSphere(float radius, int segments) {
  segments = std::max(segments, 3);
  MeshData m = grid(segments, std::max(segments / 2, 2), [&](glm::vec2 uv, glm::vec3& p, glm::vec3& n) {
    const glm::vec2 phi = cosSinTurn(uv.x);
    // The poles are single points: sin(theta) exactly 0 there.
    const float theta = uv.y * glm::pi<float>();
    const float st = uv.y == 0.0f || uv.y == 1.0f ? 0.0f : std::sin(theta);
    const float ct = uv.y == 0.0f ? 1.0f : uv.y == 1.0f ? -1.0f : std::cos(theta);
    n = glm::vec3(st * phi.y, ct, st * phi.x);
    p = n * radius;
  });
  m.name = "sphere";
  return m;
}

MeshData makeTorus(float major, float minor, int segments) {
  segments = std::max(segments, 3);
  MeshData m = grid(segments, std::max(segments / 2, 3), [&](glm::vec2 uv, glm::vec3& p, glm::vec3& n) {
    const glm::vec2 u = cosSinTurn(uv.x), v = cosSinTurn(uv.y);
    const glm::vec3 ring(u.y, 0.0f, u.x);
    n = ring * -v.x + glm::vec3(0, v.y, 0);
    p = ring * major + n * minor;
  });
  m.name = "torus";
  return m;
}

MeshData makeBox(glm::vec3 h) {
  MeshData m;
  m.name = "box";
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a = 0; a < 3; ++a)
    for (float s : {1.0f, -1.0f}) {
      const glm::vec3 n = axes[a] * s, u = axes[(a + 1) % 3] * s, v = axes[(a + 2) % 3];
      const uint32_t base = uint32_t(m.positions.size());
      for (int k = 0; k < 4; ++k) {
        const float du = (k & 1) ? 1.0f : -1.0f, dv = (k & 2) ? 1.0f : -1.0f;
        m.positions.push_back((n + u * du + v * dv) * h);
        m.normals.push_back(n);
        m.uvs.emplace_back((du + 1) * 0.5f, (dv + 1) * 0.5f);
      }
      m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base + 2, base + 1, base + 3});
    }
  return m;
}

MeshData makePlane(float size, int cells, float uvRepeat) {
  cells = std::max(cells, 1);
  MeshData m = grid(cells, cells, [&](glm::vec2 uv, glm::vec3& p, glm::vec3& n) {
    p = glm::vec3((uv.x - 0.5f) * size, 0.0f, (uv.y - 0.5f) * size);
    n = glm::vec3(0, 1, 0);
  });
  for (auto& uv : m.uvs) uv *= uvRepeat;
  m.name = "plane";
  return m;
}

ImageSource makeCheckerImage(int size, int checks) {
  ImageSource img;
  img.name = "procedural checker";
  img.size = {size, size};
  img.rgba.resize(size_t(size) * size * 4);
  const int cell = std::max(size / checks, 1);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const unsigned char v = ((x / cell + y / cell) & 1) ? 235 : 30;
      unsigned char* p = &img.rgba[(size_t(y) * size + x) * 4];
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
    }
  img.sampler.maxAnisotropy = 1.0f;
  return img;
}

}  // namespace shadelab
