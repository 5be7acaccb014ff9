// A double-precision GJK between P1(ρ1) and P2(ρ2): a guess only. It finds the few vertices on
// which the closest points (or an enclosing simplex) rest; the exact stages prove or correct them
// (distance_cgal.cpp, proved_distance), and never decide on a double.
#pragma once
#include "geometry/point_sets.hpp"

#include <utility>
#include <vector>

namespace scalecert::internal {

struct GjkGuess {
    std::vector<int> v1, v2;  // vertices of P1 and of P2 in the final simplex (input indices, distinct, sorted)
    double distance = 0;      // the doubles' distance (0 when the simplex holds the origin)
    D3 closest{0, 0, 0};      // the doubles' point of P1(ρ1) − P2(ρ2) nearest the origin (0 when it holds it)
    // The final simplex: its points of P1(ρ1) − P2(ρ2) as pairs (vertex of P1, vertex of P2).
    std::vector<std::pair<int, int>> simplex;
    int iterations = 0;
};
GjkGuess gjk_guess(const PointSets& S, double rho1, double rho2);
GjkGuess gjk_guess(const Bodies& m, double rho1, double rho2);  // on its vertices

}  // namespace scalecert::internal
