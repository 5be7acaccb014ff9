#include "polygon.hpp"

#include "json.hpp"
#include "numbers.hpp"
#include "scene.hpp"

#include <algorithm>

namespace scalecert_check {
// Its corners only (no repeated or collinear vertices), from the lowest (then leftmost) one; a
// polygon of two distinct points as the two sorted, of one as that point. One pass with a stack
// drops every vertex collinear with its neighbours, then the same at the wrap-around: linear.
// Every polygon the checker builds is such a list (the rectangle, the boxes, their clips by one
// line, the overlap region); for them this is what removing collinear vertices one at a time, in
// any order, gives: the corners of a convex polygon are the vertices at which it turns, and
// dropping a vertex where it does not turn changes no other turn. (tests/checker/test_polygon.cpp
// compares it with that removal on random polygons.)
std::vector<P2> normalize(const std::vector<P2>& p) {
    auto turn = [](const P2& o, const P2& a, const P2& b) {
        return sgn((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]));
    };
    std::vector<P2> d;
    for (const P2& v : p)
        if (d.empty() || d.back() != v) d.push_back(v);
    while (d.size() > 1 && d.front() == d.back()) d.pop_back();
    std::vector<P2> q;
    if (d.size() <= 2)
        q = std::move(d);
    else {
        for (P2& v : d) {
            while (q.size() >= 2 && turn(q[q.size() - 2], q.back(), v) == 0) q.pop_back();
            q.push_back(std::move(v));
        }
        size_t b = 0;  // the polygon is q[b..]: the wrap-around, last against first and first against last
        while (q.size() - b > 2) {
            if (q.back() == q[b] || turn(q[q.size() - 2], q.back(), q[b]) == 0)
                q.pop_back();
            else if (turn(q.back(), q[b], q[b + 1]) == 0)
                ++b;
            else
                break;
        }
        q.erase(q.begin(), q.begin() + static_cast<long>(b));
    }
    if (q.size() == 2 && q[1] < q[0]) std::swap(q[0], q[1]);
    if (q.size() > 2) {
        auto lowest = [](const P2& a, const P2& b) { return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0]; };
        std::rotate(q.begin(), std::min_element(q.begin(), q.end(), lowest), q.end());
    }
    return q;
}

std::vector<P2> half_plane_cut(const std::vector<P2>& p, const Q& a, const Q& b, const Q& c) {
    std::vector<Q> f(p.size());  // a x + b y − c at each vertex
    for (size_t i = 0; i < p.size(); ++i) f[i] = a * p[i][0] + b * p[i][1] - c;
    std::vector<P2> out;
    out.reserve(p.size() + 1);
    for (size_t i = 0; i < p.size(); ++i) {
        const size_t j = (i + 1) % p.size();
        const P2 &u = p[i], &v = p[j];
        const Q &fu = f[i], &fv = f[j];
        if (sgn(fu) >= 0) out.push_back(u);
        if (sgn(fu) * sgn(fv) < 0) {
            Q t = fu / (fu - fv);
            out.push_back({u[0] + t * (v[0] - u[0]), u[1] + t * (v[1] - u[1])});
        }
    }
    return normalize(out);
}

std::vector<P2> clip(const std::vector<P2>& p, const Line& L, bool above) {
    return above ? half_plane_cut(p, -L.a, Q(1), L.b) : half_plane_cut(p, L.a, Q(-1), -L.b);
}

// Each vertex's value (3 operations) and each crossing (about 8), every operation on the line's
// numbers and the largest vertex (counting the first vertex only would let a polygon with huge
// corners be cut by 40,000 small normals for 97 s).
std::vector<P2> cut(Context& cx, const std::vector<P2>& p, const Q& a, const Q& b, const Q& c) {
    double big = 0;
    for (const P2& v : p) big = std::max(big, qsize(v[0]) + qsize(v[1]));
    cx.spend_ops(11.0 * static_cast<double>(p.size() + 1), qsize(a) + qsize(b) + qsize(c) + big);
    return half_plane_cut(p, a, b, c);
}

std::vector<P2> rectangle(const Q (&lo)[2], const Q (&hi)[2]) {
    return normalize({{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}});
}

std::vector<P2> polygon(Context& cx, const J& j, const std::string& where) {
    const J& vs = at(j, "vertices");
    const J& ds = at(j, "vertices_double");
    cx.claim_lazy(vs.is_array() && ds.is_array() && ds.size() == vs.size(),
                  [&] { return where + ".vertices and vertices_double are lists of one length"; });
    std::vector<P2> out;
    for (size_t k = 0; k < vs.size(); ++k) {
        auto w = [&] { return where + ".vertices[" + std::to_string(k) + "]"; };
        cx.claim_lazy(vs[k].is_array() && vs[k].size() == 2 && ds[k].is_array() && ds[k].size() == 2,
                      [&] { return w() + " is a point"; });
        P2 p{num_at(cx, vs[k][0], w), num_at(cx, vs[k][1], w)};
        cx.claim_lazy(is_nearest(ds[k][0], p[0]) && is_nearest(ds[k][1], p[1]),
                      [&] { return w() + "_double is the nearest double"; });
        out.push_back(p);
    }
    return out;
}
}  // namespace scalecert_check
