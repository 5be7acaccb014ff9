#include "geometry/measures.hpp"

#include <mpfr.h>

namespace scalecert::internal {

Vec3q scaled_point(const Model& m, int i, const Q& rho, const Vec3q& x) {
    const Vec3q& s = m.s[i];
    return {s[0] + rho * (x[0] - s[0]), s[1] + rho * (x[1] - s[1]), s[2] + rho * (x[2] - s[2])};
}

bool contains(const Model& m, int i, const Q& rho, const Vec3q& x) {
    const Vec3q& s = m.s[i];
    const Vec3q y{s[0] + (x[0] - s[0]) / rho, s[1] + (x[1] - s[1]) / rho, s[2] + (x[2] - s[2]) / rho};  // x = s + ρ(y − s)
    const Polyhedron& P = m.P[i];
    for (const Face& f : P.faces)
        if (dot(f.normal, y) > dot(f.normal, P.points[static_cast<size_t>(f.verts.front())])) return false;
    return true;
}

std::pair<Q, Q> plane_extents(const HullModel& m, const Vec3q& n, const Q& rho1, const Q& rho2) {
    // n = k·p with p primitive and k > 0: max over P1 of n·x is k·support(p), min over P2 is
    // −k·support(−p); scaling about the seed maps a value t to n·s + ρ(t − n·s).
    const Vec3z p = primitive(n);
    Q k;
    for (int i = 0; i < 3; ++i)
        if (sgn(p[i]) != 0) {
            k = n[i] / Q(p[i]);
            break;
        }
    const Q ns1 = dot(n, m.s[0]), ns2 = dot(n, m.s[1]);
    const Q max1 = k * m.P[0].support(p), min2 = -k * m.P[1].support(neg(p));
    return {ns1 + rho1 * (max1 - ns1), ns2 + rho2 * (min2 - ns2)};
}

Q directional_depth_squared(const HullModel& m, const Vec3q& n, const Q& rho1, const Q& rho2) {
    const auto [c1, c2] = plane_extents(m, n, rho1, rho2);
    const Q h = c1 - c2;  // max over P1(ρ1) − P2(ρ2) of n·x
    const Q sq = h * h / dot(n, n);
    return sgn(h) < 0 ? Q(-sq) : sq;
}

ExactDepth exact_penetration_depth(const HullModel& m, const std::vector<Vec3z>& normals, const Q& rho1, const Q& rho2) {
    ExactDepth best{Q(-1), {}};
    for (const Vec3z& n : normals) {
        const Q h1 = m.P[0].support(n) - dot(n, m.s[0]);
        const Q h2 = m.P[1].support(neg(n)) + dot(n, m.s[1]);
        const Q h = rho1 * h1 + rho2 * h2 - dot(n, m.d);
        if (sgn(h) < 0) return {Q(-1), n};  // this plane separates: no depth
        const Q sq = h * h / Q(dotz(n, n));
        if (sgn(best.squared) < 0 || sq < best.squared) best = {sq, n};
    }
    return best;
}

double sqrt_minus_rn(const Q& square, const Q& c) {
    mpfr_t a, b;
    mpfr_init2(a, 256);
    mpfr_init2(b, 256);
    mpfr_set_q(a, square.get_mpq_t(), MPFR_RNDN);
    mpfr_sqrt(a, a, MPFR_RNDN);
    mpfr_set_q(b, c.get_mpq_t(), MPFR_RNDN);
    mpfr_sub(a, a, b, MPFR_RNDN);
    const double d = mpfr_get_d(a, MPFR_RNDN);
    mpfr_clear(a);
    mpfr_clear(b);
    return d;
}

}  // namespace scalecert::internal
