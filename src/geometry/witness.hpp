// Exact witnesses by linear programming (CGAL's exact LP solver), kept in one translation unit.
#pragma once
#include "numeric/exact.hpp"

#include <optional>
#include <vector>

namespace scalecert::internal {

// Finds λ ≥ 0 (Σλ = 1) on A and μ ≥ 0 (Σμ = 1) on B with Σ λ_i A_i = Σ μ_j B_j: a common point of
// conv(A) and conv(B). None when they do not meet.
struct CommonPointWeights {
    std::vector<Q> lambda, mu;
};
std::optional<CommonPointWeights> common_point(const std::vector<Vec3q>& A, const std::vector<Vec3q>& B);
// The same with every weight strictly positive: a point of relint conv(A) ∩ relint conv(B) (it
// maximises the smallest weight). None when the relative interiors do not meet. Beyond
// kBoundEveryWeightUpTo points together, by interior_common_point_by_centroids.
std::optional<CommonPointWeights> interior_common_point(const std::vector<Vec3q>& A, const std::vector<Vec3q>& B);
// The same at a cost that grows with the points like common_point's: bounding every weight below
// needs a row per point, and the exact simplex then takes minutes on a 1,600-gon face. Instead
// each set's centroid c joins it as one more point and only the two centroids' weights are
// maximised. c lies in the relative interior of its polytope, and so does every point with
// positive weight on c (the segment from a relative-interior point to any point of the polytope,
// that point excluded, lies in the relative interior). Conversely, for p in both relative
// interiors, p + ε(p − c) stays in the polytope for a small ε > 0, so p = (that point + ε c)/(1 + ε)
// weighs c by ε/(1 + ε) > 0: the optimum is > 0 exactly when the relative interiors meet. The
// centroid's weight is then spread evenly over its set, so every weight is > 0.
std::optional<CommonPointWeights> interior_common_point_by_centroids(const std::vector<Vec3q>& A,
                                                                     const std::vector<Vec3q>& B);
constexpr size_t kBoundEveryWeightUpTo = 32;

// Maximises c·x over free x ∈ Q^k subject to A_i·x ≤ b_i, exactly: a basic optimal solution, or
// none when the program is infeasible or unbounded.
std::optional<std::vector<Q>> maximise_free(const std::vector<std::vector<Q>>& A, const std::vector<Q>& b,
                                            const std::vector<Q>& c);

}  // namespace scalecert::internal
