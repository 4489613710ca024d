#include "labs/surface/brick_textures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "app/lab/host_batch.h"

namespace shadelab {
namespace {

float hash(int x, int y, int seed) {
  uint32_t h = uint32_t(x) * 374761393u + uint32_t(y) * 668265263u + uint32_t(seed) * 2246822519u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return float((h ^ (h >> 16)) & 0xffffff) / float(0xffffff);
}

// Smooth value noise in [0, 1], one lattice cell per `cell` pixels, periodic over `period` pixels.
float noise(float x, float y, float cell, int period, int seed) {
  const int cells = std::max(1, int(float(period) / cell));
  const float fx = x / cell, fy = y / cell;
  const int ix = int(std::floor(fx)), iy = int(std::floor(fy));
  const float tx = fx - float(ix), ty = fy - float(iy);
  auto at = [&](int i, int j) { return hash(((i % cells) + cells) % cells, ((j % cells) + cells) % cells, seed); };
  const float sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
  return (at(ix, iy) * (1 - sx) + at(ix + 1, iy) * sx) * (1 - sy) +
         (at(ix, iy + 1) * (1 - sx) + at(ix + 1, iy + 1) * sx) * sy;
}

ImageSource blank(const char* name, int size) {
  ImageSource img;
  img.name = name;
  img.size = {size, size};
  img.rgba.assign(size_t(size) * size_t(size) * 4, 255);
  return img;
}

}  // namespace

ImageSource normalMapFromHeight(const ImageSource& height, float depthPerUv) {
  const int w = height.size.x, h = height.size.y;
  ImageSource out = blank("normal map from height", w);
  out.size = height.size;
  out.rgba.assign(size_t(w) * size_t(h) * 4, 255);
  auto at = [&](int x, int y) {
    return float(height.rgba[(size_t((y + h) % h) * size_t(w) + size_t((x + w) % w)) * 4]) / 255.0f;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Central differences, periodic (the textures repeat). Rows run top-down and v runs up.
      const float dhdu = (at(x + 1, y) - at(x - 1, y)) * 0.5f * float(w);
      const float dhdv = -(at(x, y + 1) - at(x, y - 1)) * 0.5f * float(h);
      const float nx = -depthPerUv * dhdu, ny = -depthPerUv * dhdv;
      const float len = std::sqrt(nx * nx + ny * ny + 1.0f);
      unsigned char* p = &out.rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
      p[0] = uint8_t(std::lround((nx / len * 0.5f + 0.5f) * 255.0f));
      p[1] = uint8_t(std::lround((ny / len * 0.5f + 0.5f) * 255.0f));
      p[2] = uint8_t(std::lround((1.0f / len * 0.5f + 0.5f) * 255.0f));
    }
  return out;
}

namespace {

BrickTextures drawBrickTextures(int size, float depthPerUv) {
  BrickTextures t{blank("procedural brick colour", size), blank("procedural brick height", size), {}};
  // Running bond: 4 bricks across, 8 courses, every other course shifted half a brick.
  const float brickW = float(size) / 4.0f, brickH = float(size) / 8.0f, mortar = float(size) / 110.0f,
              bevel = float(size) / 70.0f;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const int course = int(float(y) / brickH);
      const float shift = course % 2 ? brickW * 0.5f : 0.0f;
      const float bx = std::fmod(float(x) + 0.5f + shift, float(size));
      const int brick = int(bx / brickW);
      const float lx = bx - float(brick) * brickW, ly = float(y) + 0.5f - float(course) * brickH;
      const float edge = std::min({lx, brickW - lx, ly, brickH - ly}) - mortar;  // < 0: in the mortar
      const float grain = noise(float(x), float(y), float(size) / 64.0f, size, 7) - 0.5f;
      const float floorH = 0.08f + 0.06f * grain;
      // Each brick its own height and tilt, and a rough face.
      const float own = hash(brick, course, 3), tiltX = hash(brick, course, 4) - 0.5f,
                  tiltY = hash(brick, course, 5) - 0.5f;
      const float face = 0.82f + 0.1f * own + 0.05f * tiltX * (lx / brickW - 0.5f) * 2.0f +
                         0.05f * tiltY * (ly / brickH - 0.5f) * 2.0f + 0.03f * grain +
                         0.02f * (noise(float(x), float(y), float(size) / 160.0f, size, 9) - 0.5f);
      const float rise = std::clamp(edge / bevel, 0.0f, 1.0f), smooth = rise * rise * (3 - 2 * rise);
      const float height = edge < 0.0f ? floorH : floorH + (face - floorH) * smooth;
      unsigned char* hp = &t.height.rgba[(size_t(y) * size_t(size) + size_t(x)) * 4];
      hp[0] = hp[1] = hp[2] = uint8_t(std::lround(std::clamp(height, 0.0f, 1.0f) * 255.0f));
      // Colour: brick reds varying per brick, mortar a warm grey.
      const float shade = 0.85f + 0.3f * own + 0.15f * grain;
      const float r = edge < 0.0f ? 0.62f + 0.08f * grain : 0.55f * shade,
                  g = edge < 0.0f ? 0.6f + 0.08f * grain : 0.24f * shade,
                  b = edge < 0.0f ? 0.56f + 0.08f * grain : 0.17f * shade;
      unsigned char* cp = &t.color.rgba[(size_t(y) * size_t(size) + size_t(x)) * 4];
      cp[0] = uint8_t(std::clamp(r, 0.0f, 1.0f) * 255.0f);
      cp[1] = uint8_t(std::clamp(g, 0.0f, 1.0f) * 255.0f);
      cp[2] = uint8_t(std::clamp(b, 0.0f, 1.0f) * 255.0f);
    }
  t.normal = normalMapFromHeight(t.height, depthPerUv);
  t.normal.name = "procedural brick normal map";
  return t;
}

}  // namespace

BrickTextures makeBrickTextures(int size, float depthPerUv) {
  // A grading child builds its scene once per host (the solution, each listed mistake, each slip,
  // the trace's rounds), and the bricks are the same every time: made once a batch.
  static BatchMemo<std::pair<int, float>, BrickTextures> kept;
  return kept.get({size, depthPerUv}, [&] { return drawBrickTextures(size, depthPerUv); });
}

}  // namespace shadelab
