// Candidate edge pairs for the Gauss-map overlay: pairs whose Gauss arcs may cross, found by
// bucketing each arc's (padded, conservative) bounding box on the unit sphere in a uniform grid.
// Doubles only prune: every candidate is then decided by the exact integer arc test.
#pragma once
#include "numeric/exact.hpp"

#include <utility>
#include <vector>

namespace scalecert::internal {

// A great-circle arc shorter than π, between two face normals (their doubles: the overlay only
// prunes with them, with padding far above their rounding error).
struct Arc {
    std::array<double, 3> from, to;
};

// A positive multiple of v as doubles, scaled by a power of two so that the largest component has
// magnitude in [1/2, 1): finite for any size of integers, within 2^-53 relative per component.
std::array<double, 3> direction_d(const Vec3z& v);

// Every (i, j) with arcs A[i] and B[j] possibly crossing (a superset of the crossing pairs).
std::vector<std::pair<int, int>> arc_candidates(const std::vector<Arc>& A, const std::vector<Arc>& B);

}  // namespace scalecert::internal
