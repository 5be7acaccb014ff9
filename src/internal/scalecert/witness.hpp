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
// The same with every weight strictly positive: a point of relint conv(A) ∩ relint conv(B) (it
// maximises the smallest weight). None when the relative interiors do not meet.
std::optional<CommonPoint> interior_common_point(const std::vector<Vec3q>& A, const std::vector<Vec3q>& B);

// Maximises c·x over free x ∈ Q^k subject to A_i·x ≤ b_i, exactly: a basic optimal solution, or
// none when the program is infeasible or unbounded.
std::optional<std::vector<Q>> maximise_free(const std::vector<std::vector<Q>>& A, const std::vector<Q>& b,
                                            const std::vector<Q>& c);

}  // namespace scalecert::internal
