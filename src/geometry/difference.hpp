// The points of the Minkowski difference M = P1(ρ1) − P2(ρ2) that the exact GJK and the exact
// EPA name (measures.cpp, distance_cgal.cpp), as integer vectors over one common denominator
//   D = lcm(den ρ1 · lcm(scale1, den s1), den ρ2 · lcm(scale2, den s2)),
// so that their decisions are integer products. With x = X / scale_i (X integral, point_sets.hpp):
//   D·(s + ρ(x − s)) = D(1 − ρ)s + (Dρ / scale_i)·X,
// and both terms are integral: D is a multiple of den ρ · lcm(scale_i, den s).
#pragma once
#include "geometry/point_sets.hpp"

namespace scalecert::internal {

class DifferenceGrid {
  public:
    DifferenceGrid(const PointSets& S, const Q& rho1, const Q& rho2);
    const PointSets& sets() const { return S_; }
    const Q& rho(int i) const { return rho_[i]; }
    const Z& D() const { return D_; }
    // D·x for point k of P_i(ρ_i).
    Vec3z body(int i, int k) const;
    // D·(v_i(ρ1) − w_j(ρ2)).
    Vec3z point(int i, int j) const {
        const Vec3z a = body(0, i), b = body(1, j);
        return {Z(a[0] - b[0]), Z(a[1] - b[1]), Z(a[2] - b[2])};
    }
    // Point k of P_i(ρ_i), exactly.
    Vec3q scaled(int i, int k) const;

  private:
    const PointSets& S_;
    Q rho_[2];
    Z D_;
    Vec3z shift_[2];  // D(1 − ρ_i)s_i
    Z factor_[2];     // Dρ_i / scale_i
};

}  // namespace scalecert::internal
