#include "app/lab/variants.h"

#include <cstddef>

namespace shadelab {

std::vector<std::vector<int>> pairwiseCover(const std::vector<int>& sizes) {
  const size_t n = sizes.size();
  // missing[a][b][i * sizes[b] + j]: the pair (dimension a = i, dimension b = j), a < b, not yet in a row.
  std::vector<std::vector<std::vector<char>>> missing(n, std::vector<std::vector<char>>(n));
  size_t left = 0;
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b) {
      missing[a][b].assign(size_t(sizes[a]) * size_t(sizes[b]), 1);
      left += missing[a][b].size();
    }
  auto isMissing = [&](size_t a, int i, size_t b, int j) {
    return a < b ? missing[a][b][size_t(i) * size_t(sizes[b]) + size_t(j)]
                 : missing[b][a][size_t(j) * size_t(sizes[a]) + size_t(i)];
  };
  std::vector<std::vector<int>> rows;
  if (n == 1) {
    for (int i = 0; i < sizes[0]; ++i) rows.push_back({i});
    return rows;
  }
  while (left > 0) {
    std::vector<int> row(n, -1);
    // Seed with the first missing pair.
    bool seeded = false;
    for (size_t a = 0; a < n && !seeded; ++a)
      for (size_t b = a + 1; b < n && !seeded; ++b)
        for (size_t k = 0; k < missing[a][b].size() && !seeded; ++k)
          if (missing[a][b][k]) {
            row[a] = int(k / size_t(sizes[b]));
            row[b] = int(k % size_t(sizes[b]));
            seeded = true;
          }
    // Every other dimension: the value that closes most missing pairs with those chosen so far.
    for (size_t d = 0; d < n; ++d) {
      if (row[d] >= 0) continue;
      int best = 0, bestGain = -1;
      for (int v = 0; v < sizes[d]; ++v) {
        int gain = 0;
        for (size_t e = 0; e < n; ++e)
          if (e != d && row[e] >= 0) gain += isMissing(d, v, e, row[e]);
        if (gain > bestGain) best = v, bestGain = gain;
      }
      row[d] = best;
    }
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a + 1; b < n; ++b) {
        char& m = missing[a][b][size_t(row[a]) * size_t(sizes[b]) + size_t(row[b])];
        left -= m;
        m = 0;
      }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace shadelab
