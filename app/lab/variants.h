// Covering the variant space of a lab's programs. A program's #defines come from a handful of
// parameters (light type, filter, view, ...) whose full product runs to tens of thousands of
// programs; compiling every pair of values instead catches what interacts (a filter that breaks
// only in one view, a view that needs a define only one light sets) in a few hundred.
#pragma once
#include <vector>

namespace shadelab {

// Rows of values, one per dimension (value i of dimension d is 0 <= i < sizes[d]), such that for
// any two dimensions every pair of their values appears in some row: a covering array of
// strength 2, built greedily (each row takes the first pair still missing, then for every other
// dimension the value that covers most missing pairs). Deterministic.
std::vector<std::vector<int>> pairwiseCover(const std::vector<int>& sizes);

}  // namespace shadelab
