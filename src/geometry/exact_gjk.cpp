// The exact GJK of measures.hpp (exact_gjk): the double GJK's final simplex, then GJK rounds in
// integers over the difference grid (difference.hpp) until the slab proves the closest points.
#include "geometry/difference.hpp"
#include "geometry/measures.hpp"

#include <algorithm>
#include <map>

namespace scalecert::internal {

namespace {

struct Vertex {
    int i, j;  // a vertex of P1 and one of P2
    Vec3z z;   // D·(v_i(ρ1) − w_j(ρ2))
};

// The point of conv(simplex) nearest the origin, as X / det with det > 0 and barycentric
// numerators lam (Σ lam = det, each > 0) on the vertices `used`.
struct Nearest {
    std::vector<size_t> used;
    std::vector<Z> lam;
    Z det;
    Vec3z X;
    Z XX;  // |X|²
};

Z det3(const Z (&m)[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The projection of the origin onto the affine hull of the subset `mask`, when the subset is
// affinely independent and the projection lies strictly inside its simplex. With e_k = p_k − p_0,
// the normal equations G μ = r (G_kl = e_k·e_l, r_k = −e_k·p_0), by Cramer's rule: μ_k = num_k / det.
bool project(const std::vector<Vertex>& s, unsigned mask, Nearest& out) {
    std::vector<size_t> ids;
    for (size_t k = 0; k < s.size(); ++k)
        if (mask >> k & 1) ids.push_back(k);
    const Vec3z& p0 = s[ids[0]].z;
    const size_t n = ids.size() - 1;
    Vec3z e[3];
    for (size_t k = 0; k < n; ++k) e[k] = sub(s[ids[k + 1]].z, p0);
    Z G[3][3], r[3];
    for (size_t k = 0; k < n; ++k) {
        for (size_t l = k; l < n; ++l) G[k][l] = G[l][k] = dotz(e[k], e[l]);
        r[k] = -dotz(e[k], p0);
    }
    Z det, num[3];
    if (n == 0)
        det = 1;
    else if (n == 1)
        det = G[0][0], num[0] = r[0];
    else if (n == 2) {
        det = G[0][0] * G[1][1] - G[0][1] * G[1][0];
        num[0] = r[0] * G[1][1] - G[0][1] * r[1];
        num[1] = G[0][0] * r[1] - r[0] * G[1][0];
    } else {
        det = det3(G);
        for (size_t c = 0; c < 3; ++c) {
            Z M[3][3];
            for (size_t a = 0; a < 3; ++a)
                for (size_t b = 0; b < 3; ++b) M[a][b] = b == c ? r[a] : G[a][b];
            num[c] = det3(M);
        }
    }
    if (sgn(det) <= 0) return false;  // affinely dependent (a Gram determinant is never negative)
    Z l0 = det;
    for (size_t k = 0; k < n; ++k) {
        if (sgn(num[k]) <= 0) return false;
        l0 -= num[k];
    }
    if (sgn(l0) <= 0) return false;
    out.used = ids;
    out.lam.assign(1, l0);
    for (size_t k = 0; k < n; ++k) out.lam.push_back(num[k]);
    out.det = det;
    for (int c = 0; c < 3; ++c) {
        out.X[c] = det * p0[c];
        for (size_t k = 0; k < n; ++k) out.X[c] += num[k] * e[k][c];
    }
    out.XX = dotz(out.X, out.X);
    return true;
}

// The nearest point of conv(s): the nearest of the projections that lie inside their subsets
// (the nearest point lies inside the face it is in, and is that face's projection), fewest
// vertices first among equals.
Nearest nearest(const std::vector<Vertex>& s) {
    Nearest best;
    bool found = false;
    for (size_t size = 1; size <= s.size(); ++size)
        for (unsigned mask = 1; mask < (1u << s.size()); ++mask) {
            if (static_cast<size_t>(__builtin_popcount(mask)) != size) continue;
            Nearest c;
            if (!project(s, mask, c)) continue;
            // |X_c|² / det_c² < |X_b|² / det_b²
            if (!found || c.XX * best.det * best.det < best.XX * c.det * c.det) best = std::move(c), found = true;
        }
    return best;  // a single vertex always projects to itself
}

// The weights lam_k / det merged by index (> 0, summing to 1), and Σ lam_k·x_k / det as the
// point of body i: Σ lam_k·(D·x_k) over det·D, one integer combination.
void combine(const DifferenceGrid& grid, int body, const std::vector<std::pair<int, Z>>& lam, const Z& det,
             std::vector<std::pair<int, Q>>& w, Vec3q& p) {
    std::map<int, Z> sum;
    for (const auto& [k, l] : lam) sum[k] += l;
    Vec3z P{Z(0), Z(0), Z(0)};
    for (const auto& [k, l] : sum) {
        Q q(l, det);
        q.canonicalize();
        w.push_back({k, q});
        const Vec3z x = grid.body(body, k);
        for (int c = 0; c < 3; ++c) P[c] += l * x[c];
    }
    const Z den = det * grid.D();
    for (int c = 0; c < 3; ++c) {
        p[c] = Q(P[c], den);
        p[c].canonicalize();
    }
}

}  // namespace

std::optional<ProvedDistance> exact_gjk(const PointSets& S, const Q& rho1, const Q& rho2,
                                        const std::vector<std::pair<int, int>>& start, int max_rounds) {
    const DifferenceGrid grid(S, rho1, rho2);
    std::vector<Vertex> s;
    for (const auto& [i, j] : start) s.push_back({i, j, grid.point(i, j)});
    if (s.empty() || s.size() > 4) return std::nullopt;
    ProvedDistance r;
    for (r.rounds = 1; r.rounds <= max_rounds; ++r.rounds) {
        // The whole simplex's projection when it lies inside (then it is the nearest point of
        // the simplex: the double GJK hands over the face it ended on), else every face's.
        Nearest x;
        if (!project(s, (1u << s.size()) - 1, x)) x = nearest(s);
        std::vector<Vertex> kept;
        for (size_t k : x.used) kept.push_back(s[k]);
        bool proved = sgn(x.XX) == 0;  // the origin in the simplex: a common point
        if (!proved) {
            // The slab: with x = X / det, the support of M along −x at the origin's side of the
            // plane x·y = |x|² (X·z·det ≥ |X|²) proves x the nearest point of M.
            const int i = S.argmax(0, neg(x.X)), j = S.argmax(1, x.X);
            const Vec3z z = grid.point(i, j);
            if (dotz(x.X, z) * x.det >= x.XX)
                proved = true;
            else {
                for (const Vertex& v : kept)
                    if (v.i == i && v.j == j) return std::nullopt;  // cannot happen: it lies beyond
                kept.push_back({i, j, z});
            }
        }
        if (proved) {
            ExactDistance& d = r.d;
            d.squared = Q(x.XX, x.det * x.det * grid.D() * grid.D());
            d.squared.canonicalize();
            std::vector<std::pair<int, Z>> l1, l2;
            for (size_t k = 0; k < x.used.size(); ++k) {
                l1.push_back({s[x.used[k]].i, x.lam[k]});
                l2.push_back({s[x.used[k]].j, x.lam[k]});
            }
            combine(grid, 0, l1, x.det, d.w1, d.p1);
            combine(grid, 1, l2, x.det, d.w2, d.p2);
            return r;
        }
        s = std::move(kept);
    }
    return std::nullopt;
}

}  // namespace scalecert::internal
