// The exact distance between two scaled polyhedra: CGAL's polytope distance (an exact QP). One of
// the few translation units that include CGAL.
#include "geometry/measures.hpp"
#include "geometry/gjk.hpp"

#include <algorithm>

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
std::vector<K::Point_3> scaled_vertices(const HullModel& m, int i, const Q& rho) {
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
std::vector<K::Point_3> scaled_subset(const HullModel& m, int i, const Q& rho, const std::vector<int>& idx) {
    std::vector<K::Point_3> out;
    for (int v : idx) {
        const Vec3q p = scaled_point(m, i, rho, m.P[i].points[static_cast<size_t>(v)]);
        Z w;
        const Vec3z z = over_common_denominator(p, w);
        out.emplace_back(gz(z[0]), gz(z[1]), gz(z[2]), gz(w));
    }
    return out;
}
}  // namespace

ProvedDistance proved_distance(const HullModel& m, const Q& rho1, const Q& rho2) {
    ProvedDistance r;
    const GjkGuess g = gjk_guess(m, to_double_rn(rho1), to_double_rn(rho2));
    std::vector<int> S[2] = {g.v1, g.v2};
    for (r.rounds = 1; r.rounds <= kProvedDistanceRounds; ++r.rounds) {
        const std::vector<K::Point_3> A = scaled_subset(m, 0, rho1, S[0]), B = scaled_subset(m, 1, rho2, S[1]);
        Distance pd(A.begin(), A.end(), B.begin(), B.end());
        ExactDistance d;
        d.squared = Q(zg(pd.squared_distance_numerator()), zg(pd.squared_distance_denominator()));
        d.squared.canonicalize();
        d.p1 = point_of(pd.realizing_point_p_coordinates_begin());
        d.p2 = point_of(pd.realizing_point_q_coordinates_begin());
        if (sgn(d.squared) == 0) {  // a common point of the two bodies
            r.d = d;
            return r;
        }
        // The slab: every vertex of P1(ρ1) at or below p along u = q − p, every vertex of P2(ρ2)
        // at or above q; a vertex beyond it joins its set, and the closest points are found again.
        const Vec3q u = sub(d.p2, d.p1);
        const Vec3z n = primitive(u);
        const int i = m.P[0].argmax(n).front(), j = m.P[1].argmax(neg(n)).front();
        const bool ok1 = dot(u, scaled_point(m, 0, rho1, m.P[0].points[static_cast<size_t>(i)])) <= dot(u, d.p1);
        const bool ok2 = dot(u, scaled_point(m, 1, rho2, m.P[1].points[static_cast<size_t>(j)])) >= dot(u, d.p2);
        if (ok1 && ok2) {
            r.d = d;
            return r;
        }
        bool grew = false;
        for (int k : {0, 1}) {
            if (k == 0 ? ok1 : ok2) continue;
            const int v = k == 0 ? i : j;
            if (std::find(S[k].begin(), S[k].end(), v) == S[k].end()) S[k].push_back(v), grew = true;
        }
        if (!grew) break;  // cannot happen: a vertex beyond the slab is not in the set
    }
    r.d = exact_distance(m, rho1, rho2);
    r.fallback = true;
    return r;
}

ExactDistance exact_distance(const HullModel& m, const Q& rho1, const Q& rho2) {
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
