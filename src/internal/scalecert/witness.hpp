// Exact witnesses by linear programming (CGAL's exact LP solver), kept in one translation unit.
#pragma once
#include "scalecert/exact.hpp"

#include <optional>
#include <vector>

namespace scalecert::internal {

// Finds λ ≥ 0 (Σλ = 1) on A and μ ≥ 0 (Σμ = 1) on B with Σ λ_i A_i = Σ μ_j B_j: a common point of
// conv(A) and conv(B). None when they do not meet.
struct CommonPoint { std::vector<Q> lambda, mu; };
std::optional<CommonPoint> common_point(const std::vector<Vec3q>& A, const std::vector<Vec3q>& B);

}  // namespace scalecert::internal
