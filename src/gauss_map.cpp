#include "scalecert/gauss_map.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace scalecert {

namespace {
using D3 = std::array<double, 3>;
D3 unit(const Vec3z& v) {
    D3 d{v[0].get_d(), v[1].get_d(), v[2].get_d()};
    double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    return {d[0] / l, d[1] / l, d[2] / l};
}
D3 crossd(const D3& a, const D3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dotd(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct Box { D3 lo, hi; };
constexpr double kPad = 1e-7;  // far above the rounding error of these few operations

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
    if (lp < 1e-300) {  // numerically degenerate: the whole sphere
        return {{-1 - kPad, -1 - kPad, -1 - kPad}, {1 + kPad, 1 + kPad, 1 + kPad}};
    }
    for (double& c : p) c /= lp;
    for (int k = 0; k < 3; ++k) {
        D3 u{-p[k] * p[0], -p[k] * p[1], -p[k] * p[2]};
        u[k] += 1;
        double lu = std::sqrt(dotd(u, u));
        if (lu < 1e-12) continue;
        for (double& c : u) c /= lu;
        for (int s : {1, -1}) {
            D3 x{s * u[0], s * u[1], s * u[2]};
            if (dotd(crossd(a, x), p) > -1e-9 && dotd(crossd(x, b), p) > -1e-9) {
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

std::vector<std::pair<int, int>> arc_candidates(const std::vector<Arc>& A, const std::vector<Arc>& B) {
    std::vector<Box> ba(A.size()), bb(B.size());
    double extent = 0;
    for (size_t i = 0; i < A.size(); ++i) {
        ba[i] = arc_box(A[i]);
        extent += ba[i].hi[0] - ba[i].lo[0] + ba[i].hi[1] - ba[i].lo[1] + ba[i].hi[2] - ba[i].lo[2];
    }
    for (size_t j = 0; j < B.size(); ++j) bb[j] = arc_box(B[j]);
    // Cells about the size of an average arc, at most 128 per axis.
    double mean = A.empty() ? 2.0 : extent / (3.0 * static_cast<double>(A.size()));
    int R = static_cast<int>(std::clamp(2.0 / std::max(mean, 1e-9), 1.0, 128.0));
    auto cell = [&](double x) { return std::clamp(static_cast<int>((x + 1.0) * 0.5 * R), 0, R - 1); };
    std::unordered_map<long, std::vector<int>> grid;
    auto key = [&](int x, int y, int z) { return (static_cast<long>(x) * R + y) * R + z; };
    for (size_t i = 0; i < A.size(); ++i)
        for (int x = cell(ba[i].lo[0]); x <= cell(ba[i].hi[0]); ++x)
            for (int y = cell(ba[i].lo[1]); y <= cell(ba[i].hi[1]); ++y)
                for (int z = cell(ba[i].lo[2]); z <= cell(ba[i].hi[2]); ++z) grid[key(x, y, z)].push_back(static_cast<int>(i));
    std::vector<std::pair<int, int>> out;
    std::vector<int> stamp(A.size(), -1);
    for (size_t j = 0; j < B.size(); ++j) {
        const Box& b = bb[j];
        for (int x = cell(b.lo[0]); x <= cell(b.hi[0]); ++x)
            for (int y = cell(b.lo[1]); y <= cell(b.hi[1]); ++y)
                for (int z = cell(b.lo[2]); z <= cell(b.hi[2]); ++z) {
                    auto it = grid.find(key(x, y, z));
                    if (it == grid.end()) continue;
                    for (int i : it->second) {
                        if (stamp[i] == static_cast<int>(j)) continue;
                        stamp[i] = static_cast<int>(j);
                        const Box& a = ba[i];
                        if (a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
                            a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2])
                            out.push_back({i, static_cast<int>(j)});
                    }
                }
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace scalecert
