#include "labs/denoise/laplacian.h"

#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace shadelab {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

constexpr double kDivergedEnergy = 100.0;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Where j sits in i's sorted ring, or -1.
ptrdiff_t slot(const Adjacency& a, uint32_t i, uint32_t j) {
  const auto begin = a.ring.begin() + a.offsets[i], end = a.ring.begin() + a.offsets[i + 1];
  const auto it = std::lower_bound(begin, end, j);
  return it != end && *it == j ? it - a.ring.begin() : -1;
}

// Area-weighted unit vertex normals in double; +Z where no face gives a direction.
std::vector<glm::dvec3> normalsOf(std::span<const glm::dvec3> p, std::span<const uint32_t> idx) {
  std::vector<glm::dvec3> n(p.size(), glm::dvec3(0.0));
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    const glm::dvec3 c = glm::cross(p[idx[t + 1]] - p[idx[t]], p[idx[t + 2]] - p[idx[t]]);
    if (!finite(c)) continue;
    n[idx[t]] += c;
    n[idx[t + 1]] += c;
    n[idx[t + 2]] += c;
  }
  for (auto& v : n) {
    const double len = glm::length(v);
    v = len > 1e-300 && std::isfinite(len) ? v / len : glm::dvec3(0, 0, 1);
  }
  return n;
}

double energyOf(std::span<const glm::dvec3> delta, const std::vector<glm::dvec3>* normals) {
  double e = 0.0;
  for (size_t i = 0; i < delta.size(); ++i) {
    const double d = normals ? glm::dot(delta[i], (*normals)[i]) : 0.0;
    e += normals ? d * d : glm::dot(delta[i], delta[i]);
  }
  return e;
}

}  // namespace

EdgeWeights edgeWeights(std::span<const glm::dvec3> p, std::span<const uint32_t> idx, const Adjacency& a,
                        LaplacianWeights kind, bool clampNegative) {
  EdgeWeights w;
  const size_t n = a.offsets.size() - 1;
  w.weight.assign(a.ring.size(), kind == LaplacianWeights::Uniform ? 1.0 : 0.0);
  if (kind == LaplacianWeights::Cotangent) {
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
      for (int k = 0; k < 3; ++k) {
        const uint32_t o = idx[t + size_t(k)], i = idx[t + size_t((k + 1) % 3)], j = idx[t + size_t((k + 2) % 3)];
        if (i == j || o == i || o == j) continue;
        const glm::dvec3 e1 = p[i] - p[o], e2 = p[j] - p[o];
        const double area2 = glm::length(glm::cross(e1, e2)), scale = glm::length(e1) * glm::length(e2);
        if (!(area2 > 1e-12 * scale) || !std::isfinite(area2)) {  // no angle to speak of
          ++w.degenerateCorners;
          continue;
        }
        const double half = 0.5 * glm::dot(e1, e2) / area2;  // cot of the angle at o, halved
        const ptrdiff_t ij = slot(a, i, j), ji = slot(a, j, i);
        if (ij >= 0) w.weight[size_t(ij)] += half;
        if (ji >= 0) w.weight[size_t(ji)] += half;
      }
    }
    if (clampNegative)
      for (size_t v = 0; v < n; ++v)
        for (uint32_t k = a.offsets[v]; k < a.offsets[v + 1]; ++k)
          if (w.weight[k] < 0.0) {
            w.negativeClamped += a.ring[k] > v;  // each edge once
            w.weight[k] = 0.0;
          }
  }
  w.rowSum.assign(n, 0.0);
  for (size_t v = 0; v < n; ++v) {
    double sum = 0.0, magnitude = 0.0;
    for (uint32_t k = a.offsets[v]; k < a.offsets[v + 1]; ++k) {
      sum += w.weight[k];
      magnitude += std::abs(w.weight[k]);
    }
    if (a.degree(uint32_t(v)) > 0 && !(std::abs(sum) > 1e-9 * std::max(magnitude, 1e-300))) {
      // Every neighbour weighted ~0 (a vertex amid slivers): no direction to move in. Uniform.
      for (uint32_t k = a.offsets[v]; k < a.offsets[v + 1]; ++k) w.weight[k] = 1.0;
      sum = double(a.degree(uint32_t(v)));
      ++w.uniformFallbacks;
    }
    w.rowSum[v] = sum;
  }
  return w;
}

namespace {

// delta into `delta` (resized, reused across iterations). Uniform weights skip the multiplies.
void umbrellaInto(std::span<const glm::dvec3> p, const Adjacency& a, const EdgeWeights& w, bool uniform,
                  std::vector<glm::dvec3>& delta) {
  delta.resize(p.size());
  for (size_t v = 0; v < p.size(); ++v) {
    const uint32_t begin = a.offsets[v], end = a.offsets[v + 1];
    if (begin == end) {  // isolated: stays where it is
      delta[v] = glm::dvec3(0.0);
      continue;
    }
    glm::dvec3 sum(0.0);
    if (uniform)
      for (uint32_t k = begin; k < end; ++k) sum += p[a.ring[k]];
    else
      for (uint32_t k = begin; k < end; ++k) sum += w.weight[k] * p[a.ring[k]];
    delta[v] = p[v] - sum / w.rowSum[v];
  }
}

}  // namespace

std::vector<glm::dvec3> umbrella(std::span<const glm::dvec3> p, const Adjacency& a, const EdgeWeights& w) {
  std::vector<glm::dvec3> delta;
  umbrellaInto(p, a, w, false, delta);
  return delta;
}

namespace {

// One explicit (Jacobi) step of size `step` (negative for Taubin's mu): every delta was computed
// from the old positions already. The new positions go to `next` in one pass, checked as they are
// made, and are swapped in only when all are finite: a step that would leave a non-finite position
// returns false and changes nothing. `next` is the caller's scratch, reused across steps.
bool explicitStep(std::vector<glm::dvec3>& p, std::vector<glm::dvec3>& next, std::span<const glm::dvec3> delta,
                  const std::vector<glm::dvec3>* normals, double step) {
  next.resize(p.size());
  bool allFinite = true;
  if (normals)
    for (size_t i = 0; i < p.size(); ++i) {
      next[i] = p[i] - step * (glm::dot(delta[i], (*normals)[i]) * (*normals)[i]);
      allFinite &= finite(next[i]);
    }
  else
    for (size_t i = 0; i < p.size(); ++i) {
      next[i] = p[i] - step * delta[i];
      allFinite &= finite(next[i]);
    }
  if (!allFinite) return false;
  p.swap(next);
  return true;
}

void runExplicit(SmoothingResult& r, std::span<const uint32_t> idx, const Adjacency& a, const SmoothingSettings& s,
                 JobContext* job) {
  std::vector<glm::dvec3>& p = r.positions;
  const bool cot = s.weights == LaplacianWeights::Cotangent;
  const double mu = taubinMu(s);
  // Cotangent weights follow the geometry, so they are recomputed every step; uniform ones are
  // the ones smooth() made, used in place.
  EdgeWeights cotWeights;
  auto measure = [&](std::vector<glm::dvec3>& delta, std::vector<glm::dvec3>& normals) {
    if (cot) cotWeights = edgeWeights(p, idx, a, s.weights, s.clampNegative);
    const EdgeWeights& w = cot ? cotWeights : r.weightsUsed;
    umbrellaInto(p, a, w, !cot && w.uniformFallbacks == 0, delta);
    if (s.alongNormal) normals = normalsOf(p, idx);
    return energyOf(delta, s.alongNormal ? &normals : nullptr);
  };
  std::vector<glm::dvec3> delta, normals, next;
  for (int it = 0; it < s.iterations; ++it) {
    const double e = measure(delta, normals);
    r.energy.push_back(e);
    if (it > 0 && r.grewAt == 0 && e > r.energy[size_t(it) - 1] * (1.0 + 1e-9)) r.grewAt = it;
    // Diverged for good (or NaN): stop with this mesh, spiky but bounded, rather than draw an
    // explosion. 100x the starting energy is about 10x the noise's amplitude.
    if (!(e <= kDivergedEnergy * std::max(r.energy.front(), 1e-300))) {
      r.stoppedAt = it;
      return;
    }
    if (job && !job->progress(float(it) / float(s.iterations),
                              "iteration " + std::to_string(it + 1) + " of " + std::to_string(s.iterations)))
      return;
    bool ok = explicitStep(p, next, delta, s.alongNormal ? &normals : nullptr, s.lambda);
    if (ok && s.method == SmoothingMethod::Taubin) {
      measure(delta, normals);
      ok = explicitStep(p, next, delta, s.alongNormal ? &normals : nullptr, mu);
    }
    if (!ok) {
      r.stoppedAt = it;
      return;
    }
  }
  const double last = measure(delta, normals);
  r.energy.push_back(last);
  if (r.grewAt == 0 && r.energy.size() >= 2 && last > r.energy[r.energy.size() - 2] * (1.0 + 1e-9))
    r.grewAt = int(r.energy.size()) - 1;
}

void runImplicit(SmoothingResult& r, const Adjacency& a, const SmoothingSettings& s, JobContext* job) {
  const EdgeWeights& w = r.weightsUsed;
  const int n = int(r.positions.size());
  // (D + lambda (D - W)) x' = D x with W symmetrised: w_ij and w_ji differ only where a row fell
  // back to uniform weights.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(a.ring.size() + size_t(n));
  Eigen::VectorXd d(n);
  for (int v = 0; v < n; ++v) {
    double diag = 0.0;
    for (uint32_t k = a.offsets[size_t(v)]; k < a.offsets[size_t(v) + 1]; ++k) {
      const uint32_t j = a.ring[k];
      const ptrdiff_t back = slot(a, j, uint32_t(v));
      const double wij = 0.5 * (w.weight[k] + (back >= 0 ? w.weight[size_t(back)] : w.weight[k]));
      diag += wij;
      triplets.emplace_back(v, int(j), -s.lambda * wij);
    }
    d[v] = diag > 0.0 ? diag : 1.0;  // an isolated vertex: x' = x
    triplets.emplace_back(v, v, (1.0 + s.lambda) * d[v] - (diag > 0.0 ? 0.0 : s.lambda * d[v]));
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const auto t0 = Clock::now();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  solver.compute(A);
  r.factorMs = msSince(t0);
  if (solver.info() != Eigen::Success) {
    r.error = "the implicit system could not be factorised (Eigen: numerical issue); try clamping cotangent weights";
    return;
  }
  Eigen::MatrixX3d x(n, 3);
  for (int v = 0; v < n; ++v) x.row(v) << r.positions[size_t(v)].x, r.positions[size_t(v)].y, r.positions[size_t(v)].z;
  auto energy = [&] { return energyOf(umbrella(r.positions, a, w), nullptr); };
  r.energy.push_back(energy());
  const auto t1 = Clock::now();
  for (int it = 0; it < s.iterations; ++it) {
    if (job && !job->progress(float(it) / float(s.iterations),
                              "solve " + std::to_string(it + 1) + " of " + std::to_string(s.iterations)))
      return;
    const Eigen::MatrixX3d next = solver.solve(d.asDiagonal() * x);
    if (!next.allFinite()) {
      r.stoppedAt = it;
      break;
    }
    x = next;
    for (int v = 0; v < n; ++v) r.positions[size_t(v)] = glm::dvec3(x(v, 0), x(v, 1), x(v, 2));
    r.energy.push_back(energy());
    if (r.grewAt == 0 && r.energy.back() > r.energy[r.energy.size() - 2] * (1.0 + 1e-9)) r.grewAt = it + 1;
  }
  r.solveMs = msSince(t1);
}

}  // namespace

double taubinMu(const SmoothingSettings& s) {
  return s.method == SmoothingMethod::Taubin ? 1.0 / (double(s.passBand) - 1.0 / double(s.lambda)) : 0.0;
}

SmoothingResult smooth(std::span<const glm::dvec3> start, std::span<const uint32_t> indices, const Adjacency& adjacency,
                       const SmoothingSettings& settings, JobContext* job) {
  SmoothingResult r;
  r.positions.assign(start.begin(), start.end());
  r.weightsUsed = edgeWeights(start, indices, adjacency, settings.weights, settings.clampNegative);
  const SmoothingMethodRow& method = methodRow(settings.method);
  if (!method.laplacian) {
    r.error = std::string(method.name) + " is not a Laplacian step: it has a filter of its own";
    return r;
  }
  if (method.anyLambda)
    runImplicit(r, adjacency, settings, job);
  else
    runExplicit(r, indices, adjacency, settings, job);
  return r;
}

double stabilityLimit(const Adjacency& a, const EdgeWeights& w, int iterations) {
  // Power iteration on S = I - D^-1/2 W D^-1/2, similar to the normalised Laplacian I - D^-1 W:
  // its largest eigenvalue mu_max bounds the explicit step, lambda < 2 / mu_max.
  const size_t n = a.offsets.size() - 1;
  std::vector<double> x(n), y(n), inv(n);
  for (size_t v = 0; v < n; ++v) {
    inv[v] = w.rowSum[v] > 0.0 ? 1.0 / std::sqrt(w.rowSum[v]) : 0.0;
    x[v] = (v * 2654435761u % 1000) / 1000.0 - 0.5;  // a fixed, rough start vector
  }
  double mu = 0.0;
  for (int it = 0; it < iterations; ++it) {
    double norm = 0.0;
    for (double v : x) norm += v * v;
    norm = std::sqrt(norm);
    if (!(norm > 0.0)) return 0.0;
    for (double& v : x) v /= norm;
    double rayleigh = 0.0;
    for (size_t v = 0; v < n; ++v) {
      double wx = 0.0;
      for (uint32_t k = a.offsets[v]; k < a.offsets[v + 1]; ++k) wx += w.weight[k] * inv[a.ring[k]] * x[a.ring[k]];
      y[v] = inv[v] > 0.0 ? x[v] - inv[v] * wx : 0.0;
      rayleigh += x[v] * y[v];
    }
    mu = rayleigh;
    std::swap(x, y);
  }
  return mu > 0.0 ? 2.0 / mu : 0.0;
}

}  // namespace shadelab
