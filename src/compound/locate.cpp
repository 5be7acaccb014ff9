// The compounds' point location (locate.hpp).
#include "compound/locate.hpp"

#include "numeric/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace scalecert::internal {

namespace {

// Grid lines over [lo, hi]: G + 1 increasing doubles from the largest double <= lo to the smallest
// double >= hi (equal neighbours dropped).
std::vector<double> lines(const Q& lo, const Q& hi, int G) {
    double a = lo.get_d(), b = hi.get_d();  // get_d truncates towards 0: a <= lo (lo > 0)
    if (Q(a) > lo) a = std::nextafter(a, -INFINITY);
    if (Q(b) < hi) b = std::nextafter(b, INFINITY);
    std::vector<double> v{a};
    for (int k = 1; k < G; ++k) {
        const double x = a + (b - a) * k / G;
        if (x > v.back() && x < b) v.push_back(x);
    }
    v.push_back(b);
    return v;
}
}  // namespace

CompoundLocator::CompoundLocator(const CompoundRegion& r, const Q lo[2], const Q hi[2], int G) : r_(r) {
    G = std::max(1, G);
    for (int i = 0; i < 2; ++i) {
        lo_[i] = lo[i], hi_[i] = hi[i];
        double a = lo[i].get_d(), b = hi[i].get_d();
        if (Q(a) < lo[i]) a = std::nextafter(a, INFINITY);
        if (Q(b) > hi[i]) b = std::nextafter(b, -INFINITY);
        lo_up_[i] = a, hi_down_[i] = b;
    }
    x_ = lines(lo[0], hi[0], G);
    y_ = lines(lo[1], hi[1], G);
    const size_t nx = x_.size() - 1, ny = y_.size() - 1;
    cells_.assign(nx * ny, Cell{});
    std::vector<std::vector<std::uint32_t>> lists(nx * ny);
    filter::PredicateStats st;
    // Cells strictly inside the rectangle (a covered cell must be: see locate.hpp).
    auto inner = [&](size_t i, size_t j) {
        return Q(x_[i]) > lo[0] && Q(x_[i + 1]) < hi[0] && Q(y_[j]) > lo[1] && Q(y_[j + 1]) < hi[1];
    };
    only_touches_.assign(r.pairs.size(), false);
    for (size_t k = 0; k < r.pairs.size(); ++k) {
        const CompoundRegion::Pair& p = r.pairs[k];
        for (const HalfPlane& h : p.constraints)
            if (!sgn(h.a) && !sgn(h.b) && !sgn(h.c)) only_touches_[k] = true;
        if (p.polygon.empty()) continue;  // apart in the whole rectangle: never a candidate
        Q x0 = p.polygon[0][0], x1 = x0, y0 = p.polygon[0][1], y1 = y0;
        for (const Point2q& v : p.polygon)
            x0 = std::min(x0, v[0]), x1 = std::max(x1, v[0]), y0 = std::min(y0, v[1]), y1 = std::max(y1, v[1]);
        // The cells a query in the polygon's box can land in: a query x goes to the cell i with
        // g[i] <= x < g[i + 1] (the last cell also takes x = g.back()), so i from the last line
        // <= x0 to the line before the first line > x1 (exact comparisons).
        auto range = [](const std::vector<double>& g, const Q& a, const Q& b) {
            size_t i0 = 0, i1 = g.size() - 1;
            while (i0 + 1 < g.size() - 1 && Q(g[i0 + 1]) <= a) ++i0;
            while (i1 > i0 + 1 && Q(g[i1 - 1]) > b) --i1;
            return std::pair<size_t, size_t>{i0, i1};  // cells i0 .. i1 − 1
        };
        const auto [i0, i1] = range(x_, x0, x1);
        const auto [j0, j1] = range(y_, y0, y1);
        // Each fence constraint's sign at every corner of those cells.
        const size_t cw = i1 - i0 + 1, ch = j1 - j0 + 1, nf = p.fence.size();
        std::vector<std::int8_t> sg(cw * ch * nf);
        for (size_t j = 0; j < ch; ++j)
            for (size_t i = 0; i < cw; ++i)
                for (size_t f = 0; f < nf; ++f) {
                    const HalfPlane& h = p.constraints[p.fence[f]];
                    const double x = x_[i0 + i], y = y_[j0 + j];
                    sg[(j * cw + i) * nf + f] = static_cast<std::int8_t>(filter::half_plane_side(
                        h.ad, h.bd, h.cd, x, y, [&] { return sgn(Q(h.a * Q(x) + h.b * Q(y) - h.c)); }, st));
                }
        for (size_t j = j0; j < j1; ++j)
            for (size_t i = i0; i < i1; ++i) {
                const size_t c[4] = {(j - j0) * cw + (i - i0), (j - j0) * cw + (i - i0 + 1),
                                     (j - j0 + 1) * cw + (i - i0), (j - j0 + 1) * cw + (i - i0 + 1)};
                bool all_inside = true, clear = false;
                for (size_t f = 0; f < nf && !clear; ++f) {
                    int neg = 0;
                    for (size_t q : c) {
                        const int s = sg[q * nf + f];
                        if (s <= 0) all_inside = false;
                        neg += s < 0;
                    }
                    clear = neg == 4;
                }
                if (clear) continue;
                Cell& cell = cells_[j * nx + i];
                if (all_inside && !only_touches_[k] && inner(i, j))
                    cell.covered = true;
                else
                    lists[j * nx + i].push_back(static_cast<std::uint32_t>(k));
            }
    }
    for (size_t c = 0; c < cells_.size(); ++c) {
        if (cells_[c].covered) continue;  // overlapping wherever queried: no candidate needed
        cells_[c].first = static_cast<std::uint32_t>(cand_.size());
        cells_[c].count = static_cast<std::uint32_t>(lists[c].size());
        cand_.insert(cand_.end(), lists[c].begin(), lists[c].end());
    }
}

Verdict CompoundLocator::pair_verdict(std::uint32_t k, double r1, double r2, filter::PredicateStats& st) const {
    const CompoundRegion::Pair& p = r_.pairs[k];
    int least = 1;
    for (size_t f = 0; f < p.constraints.size() && least >= 0; ++f) {
        const HalfPlane& h = p.constraints[f];
        // (a double is a dyadic rational: its exact value, formed only when the filter cannot tell)
        least =
            std::min(least, filter::half_plane_side(
                                h.ad, h.bd, h.cd, r1, r2, [&] { return sgn(Q(h.a * Q(r1) + h.b * Q(r2) - h.c)); }, st));
    }
    return least < 0 ? Verdict::Separated : least == 0 ? Verdict::Touching : Verdict::Overlapping;
}

Verdict CompoundLocator::verdict(double rho1, double rho2, filter::PredicateStats& stats) const {
    if (!(rho1 >= lo_up_[0] && rho1 <= hi_down_[0] && rho2 >= lo_up_[1] && rho2 <= hi_down_[1]))  // NaN fails too
        throw InputError("(" + std::to_string(rho1) + ", " + std::to_string(rho2) + ") lies outside I1 x I2");
    const size_t nx = x_.size() - 1;
    const size_t i =
        std::min<size_t>(nx - 1, static_cast<size_t>(std::upper_bound(x_.begin(), x_.end(), rho1) - x_.begin()) - 1);
    const size_t j = std::min<size_t>(
        y_.size() - 2, static_cast<size_t>(std::upper_bound(y_.begin(), y_.end(), rho2) - y_.begin()) - 1);
    const Cell& c = cells_[j * nx + i];
    if (c.covered) return Verdict::Overlapping;
    Verdict v = Verdict::Separated;  // the most of the candidates' (Separated < Touching < Overlapping)
    for (std::uint32_t t = 0; t < c.count && v != Verdict::Overlapping; ++t)
        v = std::max(v, pair_verdict(cand_[c.first + t], rho1, rho2, stats));
    return v;
}

std::vector<Verdict> CompoundLocator::classify(const std::vector<double>& rho1, const std::vector<double>& rho2,
                                               unsigned threads, filter::PredicateStats* stats) const {
    if (rho1.size() != rho2.size()) throw InputError("classify: rho1 and rho2 differ in length");
    std::vector<Verdict> out(rho1.size());
    threads = std::max(1u, threads);
    std::vector<filter::PredicateStats> st(threads);
    const size_t chunk = 4096, n = (rho1.size() + chunk - 1) / chunk;
    parallel_tasks(n, threads, [&](unsigned t, size_t b) {
        for (size_t k = b * chunk; k < std::min(rho1.size(), (b + 1) * chunk); ++k)
            out[k] = verdict(rho1[k], rho2[k], st[t]);
    });
    if (stats)
        for (const auto& s : st) *stats += s;
    return out;
}

int CompoundLocator::grid_for(const CompoundRegion& r) {
    size_t corners = 0;
    for (const auto& p : r.pairs) corners += p.polygon.size();
    return static_cast<int>(std::clamp<double>(std::sqrt(2.0 * static_cast<double>(corners)), 16, 128));
}

CompoundLocator::Counts CompoundLocator::counts() const {
    Counts c;
    for (const Cell& x : cells_) {
        if (x.covered)
            ++c.covered;
        else if (x.count == 0)
            ++c.clear;
        else
            ++c.mixed;
        c.candidates += x.count;
    }
    return c;
}

}  // namespace scalecert::internal
