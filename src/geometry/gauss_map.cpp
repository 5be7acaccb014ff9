#include "geometry/gauss_map.hpp"

#include "numeric/predicates.hpp"
#include "numeric/double3.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

namespace scalecert::internal {

namespace {
D3 unit(const D3& d) {
    double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    return {d[0] / l, d[1] / l, d[2] / l};
}

struct Box {
    D3 lo, hi;
};
constexpr double kPad = filter::kArcBoxPad;  // predicates.hpp, bound 6 (its other constants too)

// Bounding box of the arc on the unit sphere: its ends, plus each coordinate's extreme on the
// great circle where that extreme lies on the arc (tested with slack, so never missed).
Box arc_box(const Arc& arc) {
    D3 a = unit(arc.from), b = unit(arc.to);
    Box bx;
    for (int k = 0; k < 3; ++k) {
        bx.lo[k] = std::min(a[k], b[k]);
        bx.hi[k] = std::max(a[k], b[k]);
    }
    D3 p = crossd(a, b);
    double lp = std::sqrt(dotd(p, p));
    // Numerically degenerate, or near a half turn where a×b does not say which way the arc goes:
    // the whole sphere (predicates.hpp, bound 6).
    if (lp < filter::kArcDegenerate || (lp < filter::kArcIllConditioned && dotd(a, b) < 0)) {
        return {{-1 - kPad, -1 - kPad, -1 - kPad}, {1 + kPad, 1 + kPad, 1 + kPad}};
    }
    for (double& c : p) c /= lp;
    for (int k = 0; k < 3; ++k) {
        D3 u{-p[k] * p[0], -p[k] * p[1], -p[k] * p[2]};
        u[k] += 1;
        double lu = std::sqrt(dotd(u, u));
        if (lu < filter::kArcExtremeSkip) continue;
        for (double& c : u) c /= lu;
        for (int s : {1, -1}) {
            D3 x{s * u[0], s * u[1], s * u[2]};
            if (dotd(crossd(a, x), p) > -filter::kArcExtremeSlack &&
                dotd(crossd(x, b), p) > -filter::kArcExtremeSlack) {
                bx.lo[k] = std::min(bx.lo[k], x[k]);
                bx.hi[k] = std::max(bx.hi[k], x[k]);
            }
        }
    }
    for (int k = 0; k < 3; ++k) {
        bx.lo[k] -= kPad;
        bx.hi[k] += kPad;
    }
    return bx;
}
}  // namespace

std::array<double, 3> direction_d(const Vec3z& v) {
    long e[3], emax = LONG_MIN;
    double m[3];
    for (int k = 0; k < 3; ++k) {
        m[k] = mpz_get_d_2exp(&e[k], v[k].get_mpz_t());  // v_k = m·2^e, |m| in [1/2, 1) (0 for 0)
        if (m[k] != 0) emax = std::max(emax, e[k]);
    }
    D3 d{};
    for (int k = 0; k < 3; ++k)
        d[k] = m[k] == 0 ? 0.0 : std::ldexp(m[k], static_cast<int>(std::max(e[k] - emax, -2000L)));
    return d;
}

std::vector<std::pair<int, int>> arc_candidates(const std::vector<Arc>& A, const std::vector<Arc>& B) {
    std::vector<Box> ba(A.size()), bb(B.size());
    double extent = 0;
    for (size_t i = 0; i < A.size(); ++i) {
        ba[i] = arc_box(A[i]);
        extent += ba[i].hi[0] - ba[i].lo[0] + ba[i].hi[1] - ba[i].lo[1] + ba[i].hi[2] - ba[i].lo[2];
    }
    for (size_t j = 0; j < B.size(); ++j) bb[j] = arc_box(B[j]);
    auto overlap = [](const Box& a, const Box& b) {
        return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
               a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
    };
    std::vector<std::pair<int, int>> out;
    if (A.size() * B.size() <= filter::kArcBrutePairs) {  // few arcs: every pair's boxes, no grid
        for (size_t i = 0; i < A.size(); ++i)
            for (size_t j = 0; j < B.size(); ++j)
                if (overlap(ba[i], bb[j])) out.push_back({static_cast<int>(i), static_cast<int>(j)});
        return out;
    }
    // Cells about the size of an average arc, at most kArcGridMax per axis.
    double mean = A.empty() ? 2.0 : extent / (3.0 * static_cast<double>(A.size()));
    int R = static_cast<int>(std::clamp(2.0 / std::max(mean, filter::kArcGridMinMean), 1.0, filter::kArcGridMax));
    auto cell = [&](double x) { return std::clamp(static_cast<int>((x + 1.0) * 0.5 * R), 0, R - 1); };
    // (cell, arc) entries of both sets sorted by cell, then joined cell by cell: flat arrays, no
    // hashing. A pair met in several shared cells is kept once.
    using Entry = std::pair<std::uint32_t, int>;
    auto entries = [&](const std::vector<Box>& boxes) {
        std::vector<Entry> e;
        e.reserve(boxes.size() * 2);
        for (size_t i = 0; i < boxes.size(); ++i) {
            const Box& b = boxes[i];
            for (int x = cell(b.lo[0]); x <= cell(b.hi[0]); ++x)
                for (int y = cell(b.lo[1]); y <= cell(b.hi[1]); ++y)
                    for (int z = cell(b.lo[2]); z <= cell(b.hi[2]); ++z)
                        e.push_back({static_cast<std::uint32_t>((x * R + y) * R + z), static_cast<int>(i)});
        }
        std::sort(e.begin(), e.end());
        return e;
    };
    const std::vector<Entry> ea = entries(ba), eb = entries(bb);
    for (size_t p = 0, q = 0; p < ea.size() && q < eb.size();) {
        if (ea[p].first < eb[q].first) {
            ++p;
            continue;
        }
        if (eb[q].first < ea[p].first) {
            ++q;
            continue;
        }
        const std::uint32_t key = ea[p].first;
        size_t p1 = p, q1 = q;
        while (p1 < ea.size() && ea[p1].first == key) ++p1;
        while (q1 < eb.size() && eb[q1].first == key) ++q1;
        for (size_t u = p; u < p1; ++u)
            for (size_t v = q; v < q1; ++v) {
                if (overlap(ba[ea[u].second], bb[eb[v].second])) out.push_back({ea[u].second, eb[v].second});
            }
        p = p1, q = q1;
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace scalecert::internal
