// Integer points held compactly: the store of a polytope's scaled vertices X_k = D v_k that the
// support scans read (scan.hpp), and the form in which the reader keeps a scene's vertex list of
// integers straight from the text (json.hpp), never as a tree of strings or as rationals.
#pragma once
#include "context.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace scalecert_check {
// v as an mpz.
inline mpz_class z64(int64_t v) {
    if constexpr (sizeof(long) >= sizeof(int64_t)) {
        return mpz_class(static_cast<long>(v));
    } else {
        const uint64_t a = v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
        mpz_class r;
        mpz_import(r.get_mpz_t(), 1, 1, sizeof a, 0, 0, &a);
        if (v < 0) mpz_neg(r.get_mpz_t(), r.get_mpz_t());
        return r;
    }
}

// A point is small when each of its coordinates is below 2^62 in magnitude: held as int64, at the
// next position of x (positions follow the points' order). The others are big: held as mpz.
struct IntPoints {
    static constexpr int kSmallBits = 62;  // a small coordinate: |c| < 2^62
    size_t n = 0;                          // points in all
    std::vector<int64_t> x[3];             // the small points' coordinates, by position
    std::vector<int> orig;                 // position -> point, once some point is big (before: the identity)
    std::vector<int> big;                  // the big points, ascending
    std::vector<Z3> big_x;                 // their coordinates, in that order

    size_t small() const { return x[0].size(); }
    // Appends a small point (every |c[j]| < 2^62).
    void add_small(const int64_t c[3]) {
        if (!big.empty()) orig.push_back(static_cast<int>(n));
        for (int j = 0; j < 3; ++j) x[j].push_back(c[j]);
        ++n;
    }
    // Appends a big point.
    void add_big(Z3 c) {
        positions_written();
        big.push_back(static_cast<int>(n));
        big_x.push_back(std::move(c));
        ++n;
    }
    // Appends all of o's points after this one's (a compound object's parts, one list).
    void append(IntPoints&& o) {
        if (n == 0) {
            *this = std::move(o);
            return;
        }
        if (!big.empty() || !o.big.empty()) {
            positions_written();
            for (size_t p = 0; p < o.small(); ++p)
                orig.push_back(static_cast<int>(n) + (o.big.empty() ? static_cast<int>(p) : o.orig[p]));
        }
        for (int j = 0; j < 3; ++j) x[j].insert(x[j].end(), o.x[j].begin(), o.x[j].end());
        for (size_t b = 0; b < o.big.size(); ++b) {
            big.push_back(static_cast<int>(n) + o.big[b]);
            big_x.push_back(std::move(o.big_x[b]));
        }
        n += o.n;
        o = IntPoints();
    }
    // The point at each position: orig[p], or p while no point is big.
    int point_at(size_t p) const { return big.empty() ? static_cast<int>(p) : orig[p]; }
    // Every point, in order, as rationals (appended to out).
    void to_rationals(std::vector<V3>& out) const {
        const size_t base = out.size();
        out.resize(base + n);
        for (size_t p = 0; p < small(); ++p)
            out[base + static_cast<size_t>(point_at(p))] = {Q(z64(x[0][p])), Q(z64(x[1][p])), Q(z64(x[2][p]))};
        for (size_t b = 0; b < big.size(); ++b)
            out[base + static_cast<size_t>(big[b])] = {Q(big_x[b][0]), Q(big_x[b][1]), Q(big_x[b][2])};
    }

  private:
    // Before the first big point every point is small and its position is its index: written out
    // in orig, which from then on maps every position.
    void positions_written() {
        if (big.empty() && orig.empty())
            for (size_t p = 0; p < small(); ++p) orig.push_back(static_cast<int>(p));
    }
};
}  // namespace scalecert_check
