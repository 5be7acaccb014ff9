// Separating planes (CLAIMS.md, "Claims": `separating_plane`): the rule on two convex objects, on objects
// made of parts, and the report.
#include "certify/report.hpp"
#include "certify/rules_impl.hpp"

namespace scalecert::internal {

using namespace report_parts;

bool plane_separates(const Q& c1, const Q& c2, const std::optional<Q>& offset) {
    return c1 < c2 && (!offset || (c1 < *offset && *offset < c2));
}

namespace {
// A plane claim's rule (CLAIMS.md): c1 = max over P1(ρ1) of n·x, c2 = min over P2(ρ2). Exact: the
// plane separates strictly (plane_separates). Within abs: each body lies within abs of its side,
// c1 − o ≤ abs·|n| and o − c2 ≤ abs·|n| (with no offset, for some o: c1 − c2 ≤ 2·abs·|n|).
bool plane_right(const Tolerance& tol, const Q& c1, const Q& c2, const Vec3q& n, const std::optional<Q>& offset) {
    if (sgn(tol.abs) == 0) return plane_separates(c1, c2, offset);
    const Q N = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (!offset) return tol.within_abs(c1 - c2, 4 * N);
    return tol.within_abs(c1 - *offset, N) && tol.within_abs(*offset - c2, N);
}
}  // namespace

void ConvexRules::Impl::plane(const TypedClaim& c, Judged& g, Proof* proof) {
    auto& d = g.set<PlaneJudged>();
    std::tie(d.c1, d.c2) = plane_extents(points(), c.normal, c.rho1, c.rho2);
    g.right = plane_right(tol, d.c1, d.c2, c.normal, c.offset);
    if (proof) proof->proof = Json::object();
}

void PartsRules::judge_plane(const TypedClaim& c, Judged& g, Json* p) {
    auto& d = g.set<PlaneJudged>();
    std::tie(d.c1, d.c2) = judge_.plane_extents(c.normal, c.rho1, c.rho2);
    g.right = plane_right(tol_, d.c1, d.c2, c.normal, c.offset);
    if (p) *p = Json::object();
}

void describe(const TypedClaim& c, const PlaneJudged& d, const Judged& g, const ExactScene*, Json& o,
              std::string& text) {
    put_rhos(o, c);
    if (g.radii) {
        // The hulls' extents; the objects reach ρr·|n| past them (|n| = √N).
        const Q N = c.normal[0] * c.normal[0] + c.normal[1] * c.normal[1] + c.normal[2] * c.normal[2];
        put_exact(o, "hulls_max_over_P1", d.c1);
        put_exact(o, "hulls_min_over_P2", d.c2);
        const double r1 = sqrt_minus_rn((*g.radii)[0] * (*g.radii)[0] * N, Q(0)),
                     r2 = sqrt_minus_rn((*g.radii)[1] * (*g.radii)[1] * N, Q(0));
        o["P1_beyond_hull_double"] = r1;
        o["P2_beyond_hull_double"] = r2;
        text = "plane at " + at(c) + ": P1 reaches " + num(d.c1) + " + ~" + dbl(r1) + ", P2 starts at " + num(d.c2) +
               " - ~" + dbl(r2) + " (" + radii_text(g) + " times |n|)";
        if (c.offset) text += ", offset " + num(*c.offset);
        return;
    }
    put_exact(o, "max_over_P1", d.c1);  // P1(ρ1) ⊆ {n·x ≤ c1}
    put_exact(o, "min_over_P2", d.c2);  // P2(ρ2) ⊆ {n·x ≥ c2}
    put_exact(o, "gap", d.c2 - d.c1);
    text = "plane at " + at(c) + ": P1 reaches " + num(d.c1) + ", P2 starts at " + num(d.c2);
    if (c.offset) {
        put_exact(o, "offset_minus_P1", *c.offset - d.c1);
        put_exact(o, "P2_minus_offset", d.c2 - *c.offset);
        text += ", offset " + num(*c.offset);
    }
}

}  // namespace scalecert::internal
