// Exact measures at one scaling pair (ρ1, ρ2), for certifying what floating-point collision code
// outputs besides verdicts. Squares throughout: no root is ever taken.
#pragma once
#include "geometry/gjk.hpp"
#include "geometry/point_sets.hpp"

#include <array>
#include <optional>

namespace scalecert::internal {

// P(ρ) = s + ρ(P − s) of polyhedron i of the bodies.
Vec3q scaled_point(const Bodies& m, int i, const Q& rho, const Vec3q& x);
// Is x in P_i(ρ)? Exact, against every face plane.
bool contains(const Bodies& m, int i, const Q& rho, const Vec3q& x);
// max over P1(ρ1) of n·x and min over P2(ρ2) of n·x (any nonzero rational n).
std::pair<Q, Q> plane_extents(const Bodies& m, const Vec3q& n, const Q& rho1, const Q& rho2);
std::pair<Q, Q> plane_extents(const PointSets& S, const Vec3q& n, const Q& rho1, const Q& rho2);

// The squared Euclidean distance between P1(ρ1) and P2(ρ2) (0 when they meet), with a closest
// pair of points. CGAL's exact polytope-distance QP (distance_cgal.cpp).
struct ExactDistance {
    Q squared;
    Vec3q p1, p2;
    // p1, p2 as convex combinations of points (index, weight > 0), when known (proved_distance):
    // the judgements certificate's closest points.
    std::vector<std::pair<int, Q>> w1, w2;
};
// (m: a hull model's bodies, or build_hulls's.)
ExactDistance exact_distance(const Bodies& m, const Q& rho1, const Q& rho2);
// The same, found at floating-point speed and proved: a double GJK (gjk.hpp) names a few vertices,
// CGAL's QP gives the exact closest points of those, and exact supports over all vertices check
// the slab between them (max over P1(ρ1) of u·x = u·p, min over P2(ρ2) of u·y = u·q, u = q − p),
// which proves them closest. A vertex beyond the slab joins the few and the round repeats; after
// kProvedDistanceRounds rounds, exact_distance over all vertices (fallback = true).
struct ProvedDistance {
    ExactDistance d;
    bool fallback = false;
    bool by_qp = false;  // proved by the QP's rounds, exact_gjk's having run out
    int rounds = 0;
};
ProvedDistance proved_distance(const Bodies& m, const Q& rho1, const Q& rho2);
constexpr int kProvedDistanceRounds = 24;
// The same on any point set (a hull's vertices, or a cloud's points with no hull): none when
// max_rounds rounds run out (the caller then asks the hull model's exact_distance). Each round
// adds a point, so with max_rounds past the points' count it always closes. It tries exact_gjk
// first, then the QP rounds.
std::optional<ProvedDistance> proved_distance(const PointSets& S, const Q& rho1, const Q& rho2,
                                              int max_rounds = kProvedDistanceRounds);
// GJK in integers (exact_gjk.cpp) from a simplex of M = P1(ρ1) − P2(ρ2) given as vertex pairs
// (the double GJK's final one, 1 to 4 pairs): each round finds the point of the simplex nearest
// the origin exactly (every face's projection, Cramer's rule) and proves it nearest in M by the
// slab, or adds M's support point beyond it. Each round brings the point strictly nearer, so it
// closes; none after max_rounds rounds.
std::optional<ProvedDistance> exact_gjk(const PointSets& S, const Q& rho1, const Q& rho2,
                                        const std::vector<std::pair<int, int>>& start, int max_rounds);
constexpr int kExactGjkRounds = 32;
// proved_distance's second stage: CGAL's QP on the vertices of the double GJK's guess g, then the
// slab; without g, the stage alone (its own guess).
std::optional<ProvedDistance> proved_distance_by_qp(const PointSets& S, const Q& rho1, const Q& rho2, const GjkGuess& g,
                                                    int max_rounds = kProvedDistanceRounds);
std::optional<ProvedDistance> proved_distance_by_qp(const PointSets& S, const Q& rho1, const Q& rho2,
                                                    int max_rounds = kProvedDistanceRounds);

// The squared penetration depth of overlapping P1(ρ1), P2(ρ2): the squared distance from the
// origin to the boundary of P1(ρ1) ⊕ (−P2(ρ2)), attained at a facet of that sum, whose outward
// normals are the facet normals n of Q1 ⊕ (−Q2): min over n of (ρ1 h1(n) + ρ2 h2(n) − n·d)² / |n|².
// Zero when they touch; for separated pairs the depth is not defined (squared = −1).
struct ExactDepth {
    Q squared;
    Vec3z direction;  // a minimising facet normal (pointing from P1 towards P2)
};
ExactDepth exact_penetration_depth(const Bodies& m, const std::vector<Vec3z>& facet_normals, const Q& rho1,
                                   const Q& rho2);
// The squared penetration depth of an overlapping pair, proved by an exact EPA (expanding
// polytope) on support points of M = P1(ρ1) − P2(ρ2): a polytope K ⊆ M grown from a tetrahedron
// until its face nearest the origin lies on a face of M. Then every face of K is at least that
// far from the origin (the lower bound: FORMAT.md, "A judgements file") and translating P2 that
// far along the face's normal separates (the upper bound). The points of K as [vertex of P1,
// vertex of P2] and its triangles (outward); none unless the origin is strictly inside M.
struct ProvedDepth {
    Q squared;
    Vec3z direction;
    std::vector<std::pair<int, int>> points;
    std::vector<std::array<int, 3>> triangles;
    int iterations = 0;
    bool from_doubles = false;  // the surface of an EPA in doubles, checked exactly (below)
};
// First an EPA in doubles from the double GJK's tetrahedron around the origin, whose final surface
// is then checked exactly as the checker does (a closed oriented surface of points of M, the
// origin strictly inside every triangle's plane, the nearest plane supporting M); when it is not
// a proof, the exact EPA (exact_epa) decides.
std::optional<ProvedDepth> proved_depth(const Bodies& m, const Q& rho1, const Q& rho2);
std::optional<ProvedDepth> proved_depth(const PointSets& S, const Q& rho1, const Q& rho2);
std::optional<ProvedDepth> exact_epa(const PointSets& S, const Q& rho1, const Q& rho2);

// The depth at (ρ1, ρ2) and what proves it, from support queries alone (any point set, no curve):
// the proved distance first — apart, its slab's direction u = q − p separates (h_M(u) = −|u|² < 0);
// meeting, its closest point is a common point (weights w1, w2) — then, for a meeting pair, the
// exact EPA: its nearest plane strictly beyond the origin gives the depth (Overlapping), through
// the origin a supporting plane of M (Touching: depth 0). None when the distance's rounds run out.
struct MeasuredDepth {
    Verdict state = Verdict::Separated;
    Vec3z normal;                      // separating, supporting, or the depth's direction
    ExactDistance distance;            // the proved distance (weights of its closest points)
    std::optional<ProvedDepth> depth;  // Overlapping
};
// (max_rounds: the proved distance's, as proved_distance's; past the points' count it always closes.)
std::optional<MeasuredDepth> measured_depth(const PointSets& S, const Q& rho1, const Q& rho2,
                                            int max_rounds = kProvedDistanceRounds);
// The verdict alone, when the double GJK's answer proves itself with a few exact support queries:
// apart, the support of M = P1(ρ1) − P2(ρ2) along n = −(the doubles' nearest point of M, in
// integers) lies strictly below 0 (n separates: Separated); meeting, the origin lies strictly
// inside the final tetrahedron of points of M (exact orientation signs: inside M's interior,
// Overlapping). None otherwise (touching, or too near it for the doubles): measured_depth decides.
std::optional<Verdict> proved_verdict(const PointSets& S, const Q& rho1, const Q& rho2);
// Its second half, from an exact distance found otherwise.
MeasuredDepth depth_from_distance(const PointSets& S, const ExactDistance& dist, const Q& rho1, const Q& rho2);
// The squared directional depth along n: (ρ1 h1(n) + ρ2 h2(n) − n·d)² / |n|², signed negative
// when that plane separates (a translation along n of that length separates them exactly).
Q directional_depth_squared(const Bodies& m, const Vec3q& n, const Q& rho1, const Q& rho2);
Q directional_depth_squared(const PointSets& S, const Vec3q& n, const Q& rho1, const Q& rho2);

// √square − c as the nearest double (MPFR at 256 bits, then rounded): for display and error
// statistics only, never for a decision.
double sqrt_minus_rn(const Q& square, const Q& c);
// |c − √square| / √square (square > 0) as the nearest double, likewise (infinite beyond the doubles).
double relative_sqrt_error_rn(const Q& square, const Q& c);

}  // namespace scalecert::internal
