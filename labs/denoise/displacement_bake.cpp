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
      if (job && y0 == 0 && !job->progress(0.9f * float(done) / float(res), "nearest vertices, row " + std::to_string(done)))
        stop = true;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(work, res * t / threads, res * (t + 1) / threads);
  for (auto& th : pool) th.join();
  return !stop;
}

}  // namespace

BakeResult bakeDisplacement(std::span<const glm::vec2> uvs, std::span<const uint32_t> idx, std::span<const float> offsets,
                            const BakeSettings& s, JobContext* job) {
  BakeResult r;
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
      // Texel centres sit at integers in this space: x = u * res - 0.5.
      glm::vec2 q[3];
      for (int k = 0; k < 3; ++k) q[k] = uvs[idx[t + size_t(k)]] * float(res) - 0.5f;
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
          values[i] = b0 * offsets[idx[t]] + b1 * offsets[idx[t + 1]] + b2 * offsets[idx[t + 2]];
          filled[i] = 1;
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
              const int nx = x + dx, ny = y + dy;
              if (nx < 0 || ny < 0 || nx >= res || ny >= res) continue;
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
      if (job && !job->progress(0.7f + 0.2f * float(pass + 1) / float(std::max(s.gutter, 1)), "gutter dilation")) return r;
    }
  } else {
    std::vector<float> points(uvs.size() * 2);
    for (size_t v = 0; v < uvs.size(); ++v) {
      points[2 * v] = uvs[v].x;
      points[2 * v + 1] = uvs[v].y;
    }
    const flann::Matrix<float> data(points.data(), uvs.size(), 2);
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
  auto texel = [&](int x, int y) { return m.stored[size_t(std::clamp(y, 0, h - 1)) * size_t(w) + size_t(std::clamp(x, 0, w - 1))]; };
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
