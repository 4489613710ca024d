#include "labs/denoise/displacement_bake.h"

#include <flann/flann.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>

namespace shadelab {
namespace {

using Clock = std::chrono::steady_clock;

// Offsets -> what the texture stores. Unorm maps spend their range on [min, max] of the offsets.
void encodeInto(DisplacementMap& map, std::vector<float> values) {
  if (map.format == MapFormat::Float32) {
    map.bias = 0.0f;
    map.scale = 1.0f;
    map.stored = std::move(values);
    return;
  }
  float lo = INFINITY, hi = -INFINITY;
  for (float v : values) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!std::isfinite(lo)) lo = hi = 0.0f;
  map.bias = lo;
  map.scale = hi > lo ? hi - lo : 1.0f;
  const float levels = map.format == MapFormat::Unorm8 ? 255.0f : 65535.0f;
  map.stored.resize(values.size());
  for (size_t i = 0; i < values.size(); ++i)
    map.stored[i] = std::round(std::clamp((values[i] - map.bias) / map.scale, 0.0f, 1.0f) * levels) / levels;
}

// The nearest vertex of every texel centre, by FLANN, in two threads.
template <typename Index>
bool nearestTexels(const Index& index, int res, std::vector<int>& nearest, const flann::SearchParams& params,
                   JobContext* job) {
  nearest.assign(size_t(res) * res, 0);
  const int threads = 2;
  std::atomic<bool> stop{false};
  std::atomic<int> rowsDone{0};
  auto work = [&](int y0, int y1) {
    std::vector<float> query(size_t(res) * 2), dist(static_cast<size_t>(res));
    for (int y = y0; y < y1 && !stop; ++y) {
      for (int x = 0; x < res; ++x) {
        query[size_t(2 * x)] = (float(x) + 0.5f) / float(res);
        query[size_t(2 * x + 1)] = (float(y) + 0.5f) / float(res);
      }
      flann::Matrix<float> q(query.data(), size_t(res), 2), d(dist.data(), size_t(res), 1);
      flann::Matrix<int> out(&nearest[size_t(y) * size_t(res)], size_t(res), 1);
      index.knnSearch(q, out, d, 1, params);
      const int done = ++rowsDone;
      if (job && y0 == 0 &&
          !job->progress(0.9f * float(done) / float(res), "nearest vertices, row " + std::to_string(done)))
        stop = true;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(work, res * t / threads, res * (t + 1) / threads);
  for (auto& th : pool) th.join();
  return !stop;
}

}  // namespace

bool uvsLeaveUnitSquare(std::span<const glm::vec2> uvs) {
  const float eps = 1e-6f;
  return std::any_of(uvs.begin(), uvs.end(), [&](const glm::vec2& uv) {
    return uv.x < -eps || uv.y < -eps || uv.x > 1.0f + eps || uv.y > 1.0f + eps;
  });
}

BakeResult bakeDisplacement(std::span<const glm::vec2> uvs, std::span<const uint32_t> idx,
                            std::span<const float> offsets, const BakeSettings& s, JobContext* job) {
  BakeResult r;
  r.map.repeat = s.repeat;
  const auto start = Clock::now();
  const int res = std::clamp(s.resolution, 1, 16384);
  r.map.size = {res, res};
  r.map.format = s.format;
  if (uvs.empty() || uvs.size() != offsets.size()) {
    r.error = "the mesh has no UVs: no map can be baked (the attribute path needs none)";
    return r;
  }
  std::vector<float> values(size_t(res) * res, 0.0f);
  if (s.method == BakeMethod::Raster) {
    std::vector<uint8_t> filled(values.size(), 0);
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
      glm::vec2 uv[3];
      for (int k = 0; k < 3; ++k) uv[k] = uvs[idx[t + size_t(k)]];
      const glm::vec2 lo = glm::min(uv[0], glm::min(uv[1], uv[2])), hi = glm::max(uv[0], glm::max(uv[1], uv[2]));
      if (!std::isfinite(lo.x + lo.y + hi.x + hi.y)) continue;
      // A repeating map: draw the triangle at every whole-number shift that lands in [0, 1)^2.
      const int sy0 = s.repeat ? -int(std::floor(hi.y)) : 0, sy1 = s.repeat ? -int(std::floor(lo.y)) : 0;
      const int sx0 = s.repeat ? -int(std::floor(hi.x)) : 0, sx1 = s.repeat ? -int(std::floor(lo.x)) : 0;
      for (int sy = sy0; sy <= sy1; ++sy)
        for (int sx = sx0; sx <= sx1; ++sx) {
          // Texel centres sit at integers in this space: x = u * res - 0.5.
          glm::vec2 q[3];
          for (int k = 0; k < 3; ++k) q[k] = (uv[k] + glm::vec2(float(sx), float(sy))) * float(res) - 0.5f;
          const float area = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
          if (!(std::abs(area) > 1e-12f)) continue;  // zero area in UV space: covers no texel centre
          const int x0 = std::max(0, int(std::ceil(std::min({q[0].x, q[1].x, q[2].x}))));
          const int x1 = std::min(res - 1, int(std::floor(std::max({q[0].x, q[1].x, q[2].x}))));
          const int y0 = std::max(0, int(std::ceil(std::min({q[0].y, q[1].y, q[2].y}))));
          const int y1 = std::min(res - 1, int(std::floor(std::max({q[0].y, q[1].y, q[2].y}))));
          for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
              const glm::vec2 p{float(x), float(y)};
              const float b1 = ((p.x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (p.y - q[0].y)) / area;
              const float b2 = ((q[1].x - q[0].x) * (p.y - q[0].y) - (p.x - q[0].x) * (q[1].y - q[0].y)) / area;
              const float b0 = 1.0f - b1 - b2;
              if (b0 < -1e-5f || b1 < -1e-5f || b2 < -1e-5f) continue;
              const size_t i = size_t(y) * size_t(res) + size_t(x);
              // A texel already claimed by another triangle (well inside this one, not on a shared
              // edge): the layout overlaps here, and the last triangle drawn wins.
              if (filled[i] && b0 > 1e-3f && b1 > 1e-3f && b2 > 1e-3f) ++r.overlapping;
              values[i] = b0 * offsets[idx[t]] + b1 * offsets[idx[t + 1]] + b2 * offsets[idx[t + 2]];
              filled[i] = 1;
            }
        }
      if (job && t % 3000 == 0 && !job->progress(0.7f * float(t) / float(idx.size()), "rasterising UV triangles"))
        return r;
    }
    r.map.covered = size_t(std::count(filled.begin(), filled.end(), 1));
    // Gutter: each pass gives every empty texel next to a filled one the mean of those neighbours.
    for (int pass = 0; pass < s.gutter; ++pass) {
      std::vector<float> next = values;
      std::vector<uint8_t> nextFilled = filled;
      for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
          const size_t i = size_t(y) * size_t(res) + size_t(x);
          if (filled[i]) continue;
          float sum = 0.0f;
          int count = 0;
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              int nx = x + dx, ny = y + dy;
              if (nx < 0 || ny < 0 || nx >= res || ny >= res) {  // off the edge: wrap, or no neighbour
                if (!s.repeat) continue;
                nx = nx < 0 ? nx + res : nx >= res ? nx - res : nx;
                ny = ny < 0 ? ny + res : ny >= res ? ny - res : ny;
              }
              const size_t j = size_t(ny) * size_t(res) + size_t(nx);
              if (filled[j]) {
                sum += values[j];
                ++count;
              }
            }
          if (count) {
            next[i] = sum / float(count);
            nextFilled[i] = 1;
          }
        }
      values.swap(next);
      filled.swap(nextFilled);
      if (job && !job->progress(0.7f + 0.2f * float(pass + 1) / float(std::max(s.gutter, 1)), "gutter dilation"))
        return r;
    }
  } else {
    // Every vertex at its UV; for a repeating map wrapped into [0, 1)^2, with ghost copies of those
    // near a border on the far side of it, so a texel finds its nearest vertex across the wrap too.
    std::vector<float> points;
    std::vector<uint32_t> owner;
    const float margin = 0.25f;
    const int ghosts = s.repeat ? 1 : 0;
    for (size_t v = 0; v < uvs.size(); ++v) {
      const glm::vec2 w = s.repeat ? uvs[v] - glm::floor(uvs[v]) : uvs[v];
      if (!std::isfinite(w.x + w.y)) continue;
      for (int dy = -ghosts; dy <= ghosts; ++dy)
        for (int dx = -ghosts; dx <= ghosts; ++dx) {
          const glm::vec2 g = w + glm::vec2(float(dx), float(dy));
          if (s.repeat && (g.x < -margin || g.y < -margin || g.x > 1.0f + margin || g.y > 1.0f + margin)) continue;
          points.push_back(g.x);
          points.push_back(g.y);
          owner.push_back(uint32_t(v));
        }
    }
    if (owner.empty()) {
      r.error = "no finite UVs to bake from";
      return r;
    }
    const flann::Matrix<float> data(points.data(), owner.size(), 2);
    std::vector<int> nearest;
    if (s.method == BakeMethod::NearestExact) {
      flann::Index<flann::L2_Simple<float>> index(data, flann::KDTreeSingleIndexParams(10));
      index.buildIndex();
      if (!nearestTexels(index, res, nearest, flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED), job)) return r;
    } else {
      flann::Index<flann::L2_Simple<float>> index(data, flann::KDTreeIndexParams(4));
      index.buildIndex();
      if (!nearestTexels(index, res, nearest, flann::SearchParams(std::max(s.checks, 1)), job)) return r;
    }
    for (auto& n : nearest) n = int(owner[size_t(n)]);  // a ghost stands for its vertex
    for (size_t i = 0; i < values.size(); ++i) values[i] = offsets[size_t(nearest[i])];
    r.map.covered = values.size();
    if (s.method == BakeMethod::NearestApprox) {
      // What the speed cost in accuracy: the exact search again, after the clock stopped.
      encodeInto(r.map, std::move(values));
      r.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      flann::Index<flann::L2_Simple<float>> exact(data, flann::KDTreeSingleIndexParams(10));
      exact.buildIndex();
      std::vector<int> truth;
      if (!nearestTexels(exact, res, truth, flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED), job)) return r;
      for (auto& n : truth) n = int(owner[size_t(n)]);
      for (size_t i = 0; i < truth.size(); ++i)
        r.wrongNeighbours += truth[i] != nearest[i] && uvs[size_t(truth[i])] != uvs[size_t(nearest[i])];
      return r;
    }
  }
  encodeInto(r.map, std::move(values));
  r.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return r;
}

float sampleDisplacement(const DisplacementMap& m, glm::vec2 uv, bool bilinear) {
  const int w = m.size.x, h = m.size.y;
  if (w <= 0 || h <= 0) return 0.0f;
  auto wrap = [&](int i, int n) { return m.repeat ? ((i % n) + n) % n : std::clamp(i, 0, n - 1); };
  auto texel = [&](int x, int y) { return m.stored[size_t(wrap(y, h)) * size_t(w) + size_t(wrap(x, w))]; };
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
  if (!bilinear) return m.decode(texel(int(std::floor(uv.x * float(w))), int(std::floor(uv.y * float(h)))));
  const float sx = uv.x * float(w) - 0.5f, sy = uv.y * float(h) - 0.5f;
  const int x0 = int(std::floor(sx)), y0 = int(std::floor(sy));
  const float fx = sx - float(x0), fy = sy - float(y0);
  const float top = texel(x0, y0) * (1 - fx) + texel(x0 + 1, y0) * fx;
  const float bottom = texel(x0, y0 + 1) * (1 - fx) + texel(x0 + 1, y0 + 1) * fx;
  return m.decode(top * (1 - fy) + bottom * fy);
}

std::vector<uint8_t> encodeMap(const DisplacementMap& m, bool topDown) {
  const size_t texels = size_t(m.size.x) * size_t(m.size.y);
  const size_t bytes = m.format == MapFormat::Unorm8 ? 1 : m.format == MapFormat::Unorm16 ? 2 : 4;
  std::vector<uint8_t> out(texels * bytes);
  for (int y = 0; y < m.size.y; ++y)
    for (int x = 0; x < m.size.x; ++x) {
      const size_t from = size_t(y) * size_t(m.size.x) + size_t(x);
      const size_t to = size_t(topDown ? m.size.y - 1 - y : y) * size_t(m.size.x) + size_t(x);
      const float v = m.stored[from];
      if (m.format == MapFormat::Unorm8) {
        out[to] = uint8_t(std::lround(v * 255.0f));
      } else if (m.format == MapFormat::Unorm16) {
        const uint16_t q = uint16_t(std::lround(v * 65535.0f));
        out[2 * to] = uint8_t(q & 0xff);
        out[2 * to + 1] = uint8_t(q >> 8);
      } else {
        std::memcpy(&out[4 * to], &v, 4);
      }
    }
  return out;
}

}  // namespace shadelab
