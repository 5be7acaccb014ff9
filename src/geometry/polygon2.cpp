// Exact convex polygons in the plane of scalings (polygon2.hpp).
#include "geometry/polygon2.hpp"

#include <algorithm>

namespace scalecert::internal {

namespace {
Q cross2(const Pt2& o, const Pt2& a, const Pt2& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}
}  // namespace

std::vector<Pt2> normalize_polygon(std::vector<Pt2> p) {
    // Remove repeats (cyclically), then collinear middle vertices.
    std::vector<Pt2> q;
    q.reserve(p.size());  // (mpq's move may throw: a reallocation would copy every point)
    for (Pt2& v : p)
        if (q.empty() || q.back() != v) q.push_back(std::move(v));
    while (q.size() > 1 && q.front() == q.back()) q.pop_back();
    for (bool changed = true; changed && q.size() > 2;) {
        changed = false;
        for (size_t i = 0; i < q.size() && q.size() > 2; ++i) {
            const Pt2& a = q[(i + q.size() - 1) % q.size()];
            const Pt2& c = q[(i + 1) % q.size()];
            if (sgn(cross2(a, q[i], c)) == 0) {
                q.erase(q.begin() + static_cast<long>(i));
                changed = true;
                break;
            }
        }
    }
    if (q.size() == 2 && q[1] < q[0]) std::swap(q[0], q[1]);
    if (q.size() > 2) {
        auto low = std::min_element(
            q.begin(), q.end(), [](const Pt2& a, const Pt2& b) { return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0]; });
        std::rotate(q.begin(), low, q.end());
    }
    return q;
}

std::vector<Pt2> cut_polygon(const std::vector<Pt2>& p, const Q& a, const Q& b, const Q& c) {
    std::vector<Q> f(p.size());  // a x + b y − c at each corner: >= 0 inside
    for (size_t i = 0; i < p.size(); ++i) f[i] = a * p[i][0] + b * p[i][1] - c;
    std::vector<Pt2> out;
    out.reserve(p.size() + 1);  // a cut adds at most one corner
    for (size_t i = 0; i < p.size(); ++i) {
        const size_t j = (i + 1) % p.size();
        const Pt2 &x = p[i], &y = p[j];
        const int sx = sgn(f[i]), sy = sgn(f[j]);
        if (sx >= 0) out.push_back(x);
        if ((sx > 0 && sy < 0) || (sx < 0 && sy > 0)) {
            const Q t = f[i] / (f[i] - f[j]);
            out.push_back({x[0] + t * (y[0] - x[0]), x[1] + t * (y[1] - x[1])});
        }
    }
    return normalize_polygon(std::move(out));
}

}  // namespace scalecert::internal
