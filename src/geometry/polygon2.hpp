// Exact convex polygons in the plane of scalings (ρ1, ρ2): the partition's regions and the
// compounds' part-pair regions share these.
#pragma once
#include "numeric/exact.hpp"

#include <array>
#include <vector>

namespace scalecert::internal {

using Pt2 = std::array<Q, 2>;

// A convex polygon's one written form: repeats and collinear vertices dropped (cyclically), from
// its lowest, then leftmost, corner; two distinct points sorted; one point as itself.
std::vector<Pt2> normalize_polygon(std::vector<Pt2> poly);
// The convex polygon p (counter-clockwise) cut to a ρ1 + b ρ2 >= c, normalized.
std::vector<Pt2> cut_polygon(const std::vector<Pt2>& p, const Q& a, const Q& b, const Q& c);

}  // namespace scalecert::internal
