// Candidate edge pairs for the Gauss-map overlay: pairs whose Gauss arcs may cross, found by
// bucketing each arc's (padded, conservative) bounding box on the unit sphere in a uniform grid.
// Doubles only prune: every candidate is then decided by the exact integer arc test.
#pragma once
#include "scalecert/exact.hpp"

#include <utility>
#include <vector>

namespace scalecert {

struct Arc { Vec3z from, to; };  // a great-circle arc shorter than π, between two face normals

// Every (i, j) with arcs A[i] and B[j] possibly crossing (a superset of the crossing pairs).
std::vector<std::pair<int, int>> arc_candidates(const std::vector<Arc>& A, const std::vector<Arc>& B);

}  // namespace scalecert
