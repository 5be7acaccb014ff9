// The exact distance between two scaled polyhedra: CGAL's polytope distance (an exact QP). One of
// the few translation units that include CGAL.
#include "geometry/measures.hpp"

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
