// Convex polygons in the plane of scaling pairs (ρ1, ρ2), in their one written form
// (certificates/FORMAT.md, "Fields of a partition file", below the table: counter-clockwise,
// from the lowest then leftmost vertex, no repeated or collinear vertices; a polygon without area
// as its one or two distinct points), cut by half-planes, and read from a file.
#pragma once
#include "context.hpp"

#include <string>
#include <vector>

namespace scalecert_check {
struct Scene;

// The line ρ2 = a ρ1 + b.
struct Line {
    Q a, b;
    Q at(const Q& x) const { return a * x + b; }
};

// A convex polygon given counter-clockwise, whose vertices may repeat or lie inside an edge, in
// its one written form.
std::vector<P2> normalize(const std::vector<P2>& p);
// The convex polygon p cut to a x + b y >= c (not counted: the callers count it).
std::vector<P2> half_plane_cut(const std::vector<P2>& p, const Q& a, const Q& b, const Q& c);
// p cut to ρ2 >= L(ρ1) (above) or ρ2 <= L(ρ1).
std::vector<P2> clip(const std::vector<P2>& p, const Line& L, bool above);
// half_plane_cut, counted before it runs.
std::vector<P2> cut(Context& cx, const std::vector<P2>& p, const Q& a, const Q& b, const Q& c);
// The rectangle I1 × I2 (lo[0] <= ρ1 <= hi[0], lo[1] <= ρ2 <= hi[1]), written as above.
std::vector<P2> rectangle(const Q (&lo)[2], const Q (&hi)[2]);

// The polygon `vertices` of j, with `vertices_double` the nearest doubles of its coordinates.
std::vector<P2> polygon(Context& cx, const J& j, const std::string& where);
}  // namespace scalecert_check
