// Exact verdicts of two compounds at scaling pairs given as doubles, after one build:
// a grid over I1 × I2 whose lines are doubles, each cell labelled once — inside some
// pair's overlap polygon, clear of every polygon, or the few pairs whose polygons cross it.
//
// Within the rectangle a part pair meets exactly on its polygon (region.hpp), so a query point
// (exact: a double is a dyadic rational) is
//   - overlapping when its cell lies strictly inside the rectangle and strictly inside a pair's
//     fence half-planes at all four corners (the closed cell then lies in the polygon's interior,
//     where every facet normal's constraint is > 0), unless the pair has a constraint that is 0
//     everywhere (then it only touches);
//   - else decided by the cell's candidate pairs alone: every other pair's polygon misses the
//     cell (its bounding box does, or one fence constraint is < 0 at all four corners), so that
//     pair is separated at every point of the cell inside the rectangle. A candidate is decided
//     as compound_verdict decides a pair: its facet normals' constraints, each sign by filter 8
//     (predicates.hpp) and exactly when the filter cannot tell.
// The cell is found by binary search on the grid lines (exact comparisons of doubles).
#pragma once
#include "compound/region.hpp"

#include <cstdint>
#include <vector>

namespace scalecert::internal {

class CompoundLocator {
  public:
    // G × G cells (G >= 1). The region r must outlive the locator.
    CompoundLocator(const CompoundRegion& r, const Q lo[2], const Q hi[2], int G);
    // The grid the command and the bench use: about twice as many cells as the polygons' corners,
    // from 16 x 16 to 128 x 128.
    static int grid_for(const CompoundRegion& r);
    // 0 separated, 1 touching, 2 overlapping at (ρ1, ρ2), which must lie in I1 × I2 (InputError
    // otherwise). Safe to call from several threads at once (statistics go to `stats`).
    Verdict verdict(double rho1, double rho2, filter::PredicateStats& stats) const;
    // The verdicts of many pairs on `threads` threads; the half-plane statistics summed.
    std::vector<Verdict> classify(const std::vector<double>& rho1, const std::vector<double>& rho2, unsigned threads,
                                  filter::PredicateStats* stats = nullptr) const;
    struct Counts {
        long covered = 0, clear = 0, mixed = 0, candidates = 0;
    };
    Counts counts() const;

  private:
    struct Cell {
        std::uint32_t first = 0, count = 0;  // candidate pairs in cand_
        bool covered = false;
    };

    const CompoundRegion& r_;
    Q lo_[2], hi_[2];
    double lo_up_[2], hi_down_[2];  // the smallest double >= lo, the largest <= hi: a double x lies
                                    // in [lo, hi] iff lo_up <= x <= hi_down
    std::vector<double> x_, y_;     // grid lines, increasing: x_[0] <= lo1, x_.back() >= hi1
    std::vector<Cell> cells_;       // row-major: cell (i, j) at j * (x_.size() - 1) + i
    std::vector<std::uint32_t> cand_;
    std::vector<bool> only_touches_;  // per pair: some constraint is 0 >= 0 everywhere (never overlapping)
    Verdict pair_verdict(std::uint32_t k, double r1, double r2, filter::PredicateStats& st) const;
};

}  // namespace scalecert::internal
