// The exact distance between two scaled polyhedra: CGAL's polytope distance (an exact QP). One of
// the few translation units that include CGAL.
#include "geometry/measures.hpp"
#include "geometry/gjk.hpp"

#include <algorithm>
#include <stdexcept>

#include <CGAL/Gmpz.h>
#include <CGAL/Homogeneous.h>
#include <CGAL/Polytope_distance_d.h>
#include <CGAL/Polytope_distance_d_traits_3.h>

namespace scalecert::internal {

namespace {
using K = CGAL::Homogeneous<CGAL::Gmpz>;
using Traits = CGAL::Polytope_distance_d_traits_3<K>;
using Distance = CGAL::Polytope_distance_d<Traits>;

CGAL::Gmpz gz(const Z& z) { return CGAL::Gmpz(z.get_mpz_t()); }
Z zg(const CGAL::Gmpz& g) { return Z(g.mpz()); }

// The vertices of P_i(ρ) as homogeneous integer points (x, y, z, w).
std::vector<K::Point_3> scaled_vertices(const Bodies& m, int i, const Q& rho) {
    std::vector<K::Point_3> out;
    for (int v : m.P[i].vertices) {
        const Vec3q p = scaled_point(m, i, rho, m.P[i].points[static_cast<size_t>(v)]);
        Z w;
        const Vec3z z = over_common_denominator(p, w);
        out.emplace_back(gz(z[0]), gz(z[1]), gz(z[2]), gz(w));
    }
    return out;
}

template <class It>
Vec3q point_of(It it) {
    Z c[4];
    for (int k = 0; k < 4; ++k, ++it) c[k] = zg(*it);
    Vec3q p;
    for (int k = 0; k < 3; ++k) {
        p[k] = Q(c[k], c[3]);
        p[k].canonicalize();
    }
    return p;
}
}  // namespace

namespace {
K::Point_3 homogeneous(const Vec3q& p) {
    Z w;
    const Vec3z z = over_common_denominator(p, w);
    return K::Point_3(gz(z[0]), gz(z[1]), gz(z[2]), gz(w));
}
Vec3q scaled(const PointSets& S, int i, const Q& rho, int k) { return scaled_about(S.seed(i), rho, S.point(i, k)); }

// Weights > 0 summing to 1 on some of the points `pts` (indices `idx`) that combine to x, which
// lies in their convex hull: Carathéodory on the QP's support points (at most four a side), each
// subset solved exactly, largest first.
std::vector<std::pair<int, Q>> convex_weights(const std::vector<Vec3q>& pts, const std::vector<int>& idx,
                                              const Vec3q& x) {
    const size_t n = pts.size();
    for (size_t size = std::min<size_t>(n, 4); size >= 1; --size)
        for (unsigned mask = 1; mask < (1u << n); ++mask) {
            if (static_cast<size_t>(__builtin_popcount(mask)) != size) continue;
            std::vector<size_t> sel;
            for (size_t k = 0; k < n; ++k)
                if (mask >> k & 1) sel.push_back(k);
            // x − a0 = Σ_{k≥1} λ_k (a_k − a0): the normal equations G λ = r, solved exactly.
            const size_t m = size - 1;
            std::vector<Vec3q> e;
            for (size_t k = 1; k < size; ++k) e.push_back(sub(pts[sel[k]], pts[sel[0]]));
            const Vec3q t = sub(x, pts[sel[0]]);
            std::vector<std::vector<Q>> G(m, std::vector<Q>(m + 1));
            for (size_t r = 0; r < m; ++r) {
                for (size_t c = 0; c < m; ++c) G[r][c] = dot(e[r], e[c]);
                G[r][m] = dot(e[r], t);
            }
            bool singular = false;
            for (size_t c = 0; c < m && !singular; ++c) {
                size_t piv = c;
                while (piv < m && sgn(G[piv][c]) == 0) ++piv;
                if (piv == m) {
                    singular = true;
                    break;
                }
                std::swap(G[c], G[piv]);
                for (size_t r = 0; r < m; ++r) {
                    if (r == c || sgn(G[r][c]) == 0) continue;
                    const Q f = G[r][c] / G[c][c];
                    for (size_t k = c; k <= m; ++k) G[r][k] -= f * G[c][k];
                }
            }
            if (singular) continue;
            std::vector<Q> lam(size);
            Q l0 = 1;
            for (size_t c = 0; c < m; ++c) lam[c + 1] = G[c][m] / G[c][c], l0 -= lam[c + 1];
            lam[0] = l0;
            Vec3q y{Q(0), Q(0), Q(0)};
            bool positive = true;
            for (size_t k = 0; k < size; ++k) {
                positive = positive && sgn(lam[k]) > 0;
                for (int c = 0; c < 3; ++c) y[c] += lam[k] * pts[sel[k]][c];
            }
            if (!positive || y != x) continue;
            std::vector<std::pair<int, Q>> w;
            for (size_t k = 0; k < size; ++k) w.push_back({idx[sel[k]], lam[k]});
            std::sort(w.begin(), w.end());
            return w;
        }
    throw std::logic_error("convex_weights: the point is not in the hull of the support points");
}
}  // namespace

std::optional<ProvedDistance> proved_distance(const PointSets& S, const Q& rho1, const Q& rho2, int max_rounds) {
    const GjkGuess g = gjk_guess(S, to_double_rn(rho1), to_double_rn(rho2));
    if (std::optional<ProvedDistance> e = exact_gjk(S, rho1, rho2, g.simplex, kExactGjkRounds)) return e;
    return proved_distance_by_qp(S, rho1, rho2, g, max_rounds);
}

std::optional<ProvedDistance> proved_distance_by_qp(const PointSets& S, const Q& rho1, const Q& rho2, int max_rounds) {
    return proved_distance_by_qp(S, rho1, rho2, gjk_guess(S, to_double_rn(rho1), to_double_rn(rho2)), max_rounds);
}

std::optional<ProvedDistance> proved_distance_by_qp(const PointSets& S, const Q& rho1, const Q& rho2, const GjkGuess& g,
                                                    int max_rounds) {
    // The closest points of the vertices the double GJK names, then the slab.
    ProvedDistance r;
    r.by_qp = true;
    std::vector<int> idx[2] = {g.v1, g.v2};
    const Q* rho[2] = {&rho1, &rho2};
    for (r.rounds = 1; r.rounds <= max_rounds; ++r.rounds) {
        std::vector<Vec3q> X[2];
        std::vector<K::Point_3> H[2];
        for (int i = 0; i < 2; ++i)
            for (int k : idx[i]) X[i].push_back(scaled(S, i, *rho[i], k)), H[i].push_back(homogeneous(X[i].back()));
        Distance pd(H[0].begin(), H[0].end(), H[1].begin(), H[1].end());
        ExactDistance d;
        d.squared = Q(zg(pd.squared_distance_numerator()), zg(pd.squared_distance_denominator()));
        d.squared.canonicalize();
        d.p1 = point_of(pd.realizing_point_p_coordinates_begin());
        d.p2 = point_of(pd.realizing_point_q_coordinates_begin());
        auto weights = [&](int i, auto b, auto e) {
            std::vector<Vec3q> pts;
            std::vector<int> ids;
            for (auto it = b; it != e; ++it)
                pts.push_back(X[i][static_cast<size_t>(*it)]), ids.push_back(idx[i][static_cast<size_t>(*it)]);
            return convex_weights(pts, ids, i == 0 ? d.p1 : d.p2);
        };
        d.w1 = weights(0, pd.support_points_p_indices_begin(), pd.support_points_p_indices_end());
        d.w2 = weights(1, pd.support_points_q_indices_begin(), pd.support_points_q_indices_end());
        if (sgn(d.squared) == 0) {  // a common point of the two bodies
            r.d = d;
            return r;
        }
        // The slab: every point of P1(ρ1) at or below p along u = q − p, every point of P2(ρ2)
        // at or above q; a point beyond it joins its set, and the closest points are found again.
        const Vec3q u = sub(d.p2, d.p1);
        const Vec3z n = primitive(u);
        const int i = S.argmax(0, n), j = S.argmax(1, neg(n));
        const bool ok1 = dot(u, scaled(S, 0, rho1, i)) <= dot(u, d.p1);
        const bool ok2 = dot(u, scaled(S, 1, rho2, j)) >= dot(u, d.p2);
        if (ok1 && ok2) {
            r.d = d;
            return r;
        }
        bool grew = false;
        for (int k : {0, 1}) {
            if (k == 0 ? ok1 : ok2) continue;
            const int v = k == 0 ? i : j;
            if (std::find(idx[k].begin(), idx[k].end(), v) == idx[k].end()) idx[k].push_back(v), grew = true;
        }
        if (!grew) break;  // cannot happen: a point beyond the slab is not in the set
    }
    return std::nullopt;
}

ProvedDistance proved_distance(const Bodies& m, const Q& rho1, const Q& rho2) {
    if (std::optional<ProvedDistance> r = proved_distance(HullPoints(m), rho1, rho2)) return *r;
    ProvedDistance r;
    r.d = exact_distance(m, rho1, rho2);
    r.rounds = kProvedDistanceRounds + 1;
    r.fallback = true;
    return r;
}

ExactDistance exact_distance(const Bodies& m, const Q& rho1, const Q& rho2) {
    const std::vector<K::Point_3> A = scaled_vertices(m, 0, rho1), B = scaled_vertices(m, 1, rho2);
    Distance pd(A.begin(), A.end(), B.begin(), B.end());
    ExactDistance r;
    r.squared = Q(zg(pd.squared_distance_numerator()), zg(pd.squared_distance_denominator()));
    r.squared.canonicalize();
    r.p1 = point_of(pd.realizing_point_p_coordinates_begin());
    r.p2 = point_of(pd.realizing_point_q_coordinates_begin());
    return r;
}

}  // namespace scalecert::internal
