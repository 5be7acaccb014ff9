// The double-precision GJK of gjk.hpp: supports by a scan of the hull vertices, and the closest
// point of the simplex by trying every face of it (at most 15): the one whose affine projection
// of the origin lies inside it and is nearest.
#include "geometry/gjk.hpp"
#include "numeric/double3.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace scalecert::internal {

namespace {

// P_i(ρ) in doubles: supports by the point set's guess, each point scaled as it is named.
struct Body {
    const PointSets& S;
    int i;
    double rho;
    D3 s;
    std::vector<int> idx;  // the points named so far (positions index this)
    std::vector<D3> x;     // their scaled doubles
    Body(const PointSets& sets, int poly, double r) : S(sets), i(poly), rho(r) {
        const Vec3q& q = S.seed(i);
        s = {to_double_rn(q[0]), to_double_rn(q[1]), to_double_rn(q[2])};
    }
    // The position of the point maximising d·x.
    size_t support(const D3& d) {
        const int k = S.dargmax(i, d);
        for (size_t t = 0; t < idx.size(); ++t)
            if (idx[t] == k) return t;
        const D3 p = S.dpoint(i, k);
        idx.push_back(k);
        x.push_back({s[0] + rho * (p[0] - s[0]), s[1] + rho * (p[1] - s[1]), s[2] + rho * (p[2] - s[2])});
        return idx.size() - 1;
    }
};

struct Vert {
    size_t a, b;  // positions in the bodies
    D3 z;         // a − b
};

// The point of the affine hull of the subset nearest the origin, if it lies strictly inside the
// subset's simplex (all its barycentric weights > 0).
bool project(const std::vector<Vert>& s, unsigned mask, D3& x) {
    size_t ids[4] = {}, m = 0;
    for (size_t k = 0; k < s.size(); ++k)
        if (mask >> k & 1) ids[m++] = k;
    const D3& y0 = s[ids[0]].z;
    const size_t n = m - 1;
    double G[3][3] = {}, r[3] = {};
    D3 e[3];
    for (size_t i = 0; i < n; ++i) e[i] = subd(s[ids[i + 1]].z, y0);
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = 0; j < n; ++j) G[i][j] = dotd(e[i], e[j]);
        r[i] = -dotd(e[i], y0);
    }
    double l[3] = {};
    if (n == 1) {
        if (!(G[0][0] > 0)) return false;
        l[0] = r[0] / G[0][0];
    } else if (n == 2) {
        const double det = G[0][0] * G[1][1] - G[0][1] * G[1][0];
        if (!(std::fabs(det) > 1e-300)) return false;
        l[0] = (r[0] * G[1][1] - G[0][1] * r[1]) / det;
        l[1] = (G[0][0] * r[1] - r[0] * G[1][0]) / det;
    } else if (n == 3) {
        const double det = G[0][0] * (G[1][1] * G[2][2] - G[1][2] * G[2][1]) -
                           G[0][1] * (G[1][0] * G[2][2] - G[1][2] * G[2][0]) +
                           G[0][2] * (G[1][0] * G[2][1] - G[1][1] * G[2][0]);
        if (!(std::fabs(det) > 1e-300)) return false;
        for (int c = 0; c < 3; ++c) {
            double M[3][3];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) M[i][j] = j == c ? r[i] : G[i][j];
            l[c] =
                (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                 M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
                det;
        }
    }
    double l0 = 1;
    for (size_t i = 0; i < n; ++i) l0 -= l[i];
    if (!(l0 > 0)) return false;
    for (size_t i = 0; i < n; ++i)
        if (!(l[i] > 0)) return false;
    x = y0;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) x[c] += l[i] * e[i][c];
    return true;
}
}  // namespace

GjkGuess gjk_guess(const Bodies& m, double rho1, double rho2) { return gjk_guess(HullPoints(m), rho1, rho2); }

GjkGuess gjk_guess(const PointSets& S, double rho1, double rho2) {
    Body A(S, 0, rho1), B(S, 1, rho2);
    auto support = [&](const D3& d) {  // the point of M = A − B maximising d·z
        const size_t a = A.support(d), b = B.support({-d[0], -d[1], -d[2]});
        return Vert{a, b, subd(A.x[a], B.x[b])};
    };
    std::vector<Vert> s{support(D3{1, 0, 0})};
    D3 v = s[0].z;
    GjkGuess g;
    for (g.iterations = 0; g.iterations < 64; ++g.iterations) {
        const double vv = dotd(v, v);
        if (!(vv > 0)) break;
        const Vert w = support({-v[0], -v[1], -v[2]});
        // No point of M is nearer than v's plane allows: converged (relative 1e-12).
        if (vv - dotd(v, w.z) <= 1e-12 * vv) break;
        bool known = false;
        for (const Vert& t : s) known = known || (t.a == w.a && t.b == w.b);
        if (known) break;
        s.push_back(w);
        double best = INFINITY;
        unsigned best_mask = 0;
        D3 nv = v;
        for (unsigned mask = 1; mask < (1u << s.size()); ++mask) {
            D3 x;
            if (!project(s, mask, x)) continue;
            const double d = dotd(x, x);
            if (d < best) best = d, nv = x, best_mask = mask;
        }
        if (!best_mask) break;  // degenerate in doubles: keep what there is
        std::vector<Vert> next;
        for (size_t k = 0; k < s.size(); ++k)
            if (best_mask >> k & 1) next.push_back(s[k]);
        s = std::move(next);
        v = nv;
        if (s.size() == 4) {  // the origin inside the tetrahedron (to doubles)
            v = {0, 0, 0};
            break;
        }
    }
    for (const Vert& t : s) {
        g.v1.push_back(A.idx[t.a]), g.v2.push_back(B.idx[t.b]);
        g.simplex.push_back({A.idx[t.a], B.idx[t.b]});
    }
    for (auto* vv : {&g.v1, &g.v2}) {
        std::sort(vv->begin(), vv->end());
        vv->erase(std::unique(vv->begin(), vv->end()), vv->end());
    }
    g.closest = v;
    g.distance = std::sqrt(dotd(v, v));
    return g;
}

}  // namespace scalecert::internal
