// Exact measures at one scaling pair (ρ1, ρ2), for certifying what floating-point collision code
// outputs besides verdicts. Squares throughout: no root is ever taken.
#pragma once
#include "curve/contact_lines.hpp"

namespace scalecert::internal {

// P(ρ) = s + ρ(P − s) of polyhedron i of the model.
Vec3q scaled_point(const Model& m, int i, const Q& rho, const Vec3q& x);
// Is x in P_i(ρ)? Exact, against every face plane.
bool contains(const Model& m, int i, const Q& rho, const Vec3q& x);
// max over P1(ρ1) of n·x and min over P2(ρ2) of n·x (any nonzero rational n).
std::pair<Q, Q> plane_extents(const HullModel& m, const Vec3q& n, const Q& rho1, const Q& rho2);

// The squared Euclidean distance between P1(ρ1) and P2(ρ2) (0 when they meet), with a closest
// pair of points. CGAL's exact polytope-distance QP (distance_cgal.cpp).
struct ExactDistance {
    Q squared;
    Vec3q p1, p2;
};
ExactDistance exact_distance(const HullModel& m, const Q& rho1, const Q& rho2);

// The squared penetration depth of overlapping P1(ρ1), P2(ρ2): the squared distance from the
// origin to the boundary of P1(ρ1) ⊕ (−P2(ρ2)), attained at a facet of that sum, whose outward
// normals are the facet normals n of Q1 ⊕ (−Q2): min over n of (ρ1 h1(n) + ρ2 h2(n) − n·d)² / |n|².
// Zero when they touch; for separated pairs the depth is not defined (squared = −1).
struct ExactDepth {
    Q squared;
    Vec3z direction;  // a minimising facet normal (pointing from P1 towards P2)
};
ExactDepth exact_penetration_depth(const HullModel& m, const std::vector<Vec3z>& facet_normals, const Q& rho1, const Q& rho2);
// The squared directional depth along n: (ρ1 h1(n) + ρ2 h2(n) − n·d)² / |n|², signed negative
// when that plane separates (a translation along n of that length separates them exactly).
Q directional_depth_squared(const HullModel& m, const Vec3q& n, const Q& rho1, const Q& rho2);

// √square − c as the nearest double (MPFR at 256 bits, then rounded): for display and error
// statistics only, never for a decision.
double sqrt_minus_rn(const Q& square, const Q& c);

}  // namespace scalecert::internal
