// The touching curve over a range of ρ1: a partition's over I1, a judgement's curve proof over its
// window (certificates/FORMAT.md, "Fields of a partition file": `pieces`, `switch_points` and
// `curve_ends`, "Below ρ2 = 0 the curve is one line", "The contact at a switch point", "The
// contact along a piece"; "Why a file that passes proves the partition", 3 and 6).
//
// Each piece's line, from a normal's support values, is a lower bound of the curve f everywhere
// (below it that normal separates); the witnesses at the switch points and ends (common points)
// bound f above there, and the set of meeting pairs is convex, so f is each piece's line over the
// piece's range. Where a piece falls to rho2 = 0 a witness there (s2 in P1(x0)) shows f <= 0 from
// x0 on. Slopes increase from piece to piece, so every switch point listed is a break of f, and
// there is no other in (lo, hi).
#pragma once
#include "context.hpp"
#include "polygon.hpp"

#include <array>
#include <string>
#include <vector>

namespace scalecert_check {
struct Scene;

// What a verified curve proves: its pieces (lines, normals, ranges, contacts), its switch points
// and the value at its two ends.
struct CurveFacts {
    std::vector<Line> lines;
    std::vector<V3> normals;
    std::vector<std::array<Q, 2>> ranges;
    std::vector<std::string> contacts;  // each piece's contact label; empty where rho2 <= 0 all along it
    struct Switch {
        Q x, y;
        std::string contact;
    };
    std::vector<Switch> switches;  // in increasing rho1, all with rho2 > 0
    Q end_rho2[2];
    // The piece holding x in [lo, hi] (at a switch point, the one to its right).
    size_t piece_at(Context& cx, const Q& x) const {
        // the first piece whose range ends beyond x (the last one if none does)
        size_t lo = 0, hi = ranges.size() - 1;
        while (lo < hi) {
            const size_t mid = (lo + hi) / 2;
            cx.spend_ops(1, qsize(x) + qsize(ranges[mid][1]));
            if (x >= ranges[mid][1])
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo;
    }
    // f(x) for x in [lo, hi].
    Q at(Context& cx, const Q& x) const {
        const Line& L = lines[piece_at(cx, x)];
        cx.spend_ops(2, qsize(x) + qsize(L.a) + qsize(L.b));
        return L.at(x);
    }
};

// The "pieces", "switch_points" and "curve_ends" of c over [lo, hi]. `pre` prefixes the
// messages; range_name names [lo, hi] in them.
CurveFacts check_curve(Context& cx, const Scene& sc, const J& c, const Q& lo, const Q& hi, const std::string& pre,
                       const std::string& range_name);
}  // namespace scalecert_check
