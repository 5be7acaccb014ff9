// Distances (CLAIMS.md, "Claims": `distance`): the rule on two convex objects, on objects made of parts (the
// least over the part pairs), and the report.
#include "certify/report.hpp"
#include "certify/rules_impl.hpp"

namespace scalecert::internal {

using namespace report_parts;

void ConvexRules::Impl::distance(const TypedClaim& c, Judged& g, Proof* proof) {
    auto& d = g.set<DistanceJudged>();
    const ExactDistance e = exact_distance_of(c.rho1, c.rho2);
    d.exact_squared = e.squared;
    d.exact_p1 = e.p1;
    d.exact_p2 = e.p2;
    d.value_right = tol.close_sq(c.value, e.squared);
    g.right = d.value_right;
    if (proof) proof->proof = distance_proof(nullptr, e, c.rho1, c.rho2);
    if (c.closest) {
        const auto& [p, q] = *c.closest;
        const Vec3q pq = diff(q, p);
        d.closest_squared = dot3(pq, pq);
        Json mp;
        members(c.rho1, c.rho2, p, q, d, proof ? &mp : nullptr, &e);
        d.closest_right = d.in1 && d.in2 && tol.within_above(d.closest_squared, e.squared, 2);
        g.right = g.right && *d.closest_right;
        if (proof) proof->proof["closest"] = std::move(mp);
    }
}

void PartsRules::judge_distance(const TypedClaim& c, Judged& g, Json* p) {
    auto& jd = g.set<DistanceJudged>();
    Json pp;
    const CompoundJudge::Distance e = judge_.distance(c.rho1, c.rho2, p ? &pp : nullptr);
    jd.exact_squared = e.squared;
    jd.exact_p1 = e.p1;
    jd.exact_p2 = e.p2;
    g.part1 = e.part1;
    g.part2 = e.part2;
    jd.value_right = tol_.close_sq(c.value, e.squared);
    g.right = jd.value_right;
    if (c.closest) {
        const auto& [a, b] = *c.closest;
        const Vec3q ab = diff(b, a);
        jd.closest_squared = dot3(ab, ab);
        Json m1, m2;
        // At an absolute tolerance, a claimed point within it of the exact closest point of its
        // object (in part k, with its weights in the distance's proof) is near at once.
        auto at = [&](int i, const Vec3q& x, Json* pj, bool* near) {
            const Vec3q d = diff(x, i == 0 ? e.p1 : e.p2);
            const int k = i == 0 ? e.part1 : e.part2;
            const Q& rho = i == 0 ? c.rho1 : c.rho2;
            if (sgn(tol_.abs) > 0 && k >= 0 && dot3(d, d) <= tol_.abs * tol_.abs) {
                if (pj) *pj = Json{{"part", k}, {"near", pp[i == 0 ? "P1" : "P2"]}};
                *near = judge_.locate(i, rho, x) < 0;  // in some part, it is said to be in it
                return k;
            }
            return place(i, rho, x, pj, near);
        };
        jd.in_part1 = at(0, a, p ? &m1 : nullptr, &jd.near1);
        jd.in_part2 = at(1, b, p ? &m2 : nullptr, &jd.near2);
        jd.in1 = jd.in_part1 >= 0;
        jd.in2 = jd.in_part2 >= 0;
        jd.closest_right = jd.in1 && jd.in2 && tol_.within_above(jd.closest_squared, e.squared, 2);
        g.right = g.right && *jd.closest_right;
        if (p) pp["closest"] = Json{{"P1", std::move(m1)}, {"P2", std::move(m2)}};
    }
    if (p) *p = std::move(pp);
}

void describe(const TypedClaim& c, const DistanceJudged& d, const Judged& g, const ExactScene* parts, Json& o,
              std::string& text) {
    put_rhos(o, c);
    if (g.radii) {
        // √E − R apart (E the hulls' squared distance), else 0.
        const Q R = (*g.radii)[0] + (*g.radii)[1];
        const bool apart = d.exact_squared > R * R;
        errors_surd(o, c.value, apart ? 1 : 0, d.exact_squared, apart ? Q(-R) : Q(0), R, "hulls_squared_distance");
        put_point(o, "hulls_closest_P1", d.exact_p1);
        put_point(o, "hulls_closest_P2", d.exact_p2);
        text = "distance at " + at(c) + ": claimed " + num(c.value) + ", exact ~" +
               dbl(surd_rn(apart ? 1 : 0, d.exact_squared, apart ? Q(-R) : Q(0)), 17) +
               " (the hulls' distance, the square root of " + num(d.exact_squared) + ", less the " + radii_text(g) +
               ")";
    } else {
        errors_sq(o, c.value, d.exact_squared);
        put_point(o, "exact_closest_P1", d.exact_p1);
        put_point(o, "exact_closest_P2", d.exact_p2);
        text = "distance at " + at(c) + ": claimed " + num(c.value) + ", exact squared " + num(d.exact_squared) +
               " (distance ~" + dbl(sqrt_minus_rn(d.exact_squared, Q(0))) +
               (parts ? ", " + parts_named(*parts, g.part1, g.part2) : std::string()) + ")";
    }
    if (parts) put_part_pair(o, "exact_pair", *parts, g.part1, g.part2);
    o["value_right"] = d.value_right;
    if (c.closest) {
        if (parts) {
            o["closest_in_P1_part"] = part_or_false(d.in_part1);
            put_part_name(o, "closest_in_P1_part", parts->P[0], d.in_part1);
            o["closest_in_P2_part"] = part_or_false(d.in_part2);
            put_part_name(o, "closest_in_P2_part", parts->P[1], d.in_part2);
        } else {
            o["closest_in_P1"] = d.in1;
            o["closest_in_P2"] = d.in2;
        }
        put_near(o, "closest_near_P1", d.near1);
        put_near(o, "closest_near_P2", d.near2);
        if (d.near1 || d.near2) text += ", closest points within LEN of their bodies";
        put_exact(o, "closest_squared_distance", d.closest_squared);
        o["closest_right"] = *d.closest_right;
        // Wrong points: the line says so, and why (CLAIMS.md, "a closest pair").
        if (!*d.closest_right) {
            std::string why;
            if (!d.in1) why = "the first point is not in P1";
            if (!d.in2) why += std::string(why.empty() ? "" : "; ") + "the second point is not in P2";
            if (why.empty())
                why = d.near1 || d.near2 ? "each is in or within LEN of its body, but they lie farther apart than "
                                           "the distance allows"
                                         : "each is in its body, but they lie farther apart than the distance";
            text += std::string(d.value_right ? ", but" : ", and") + " the closest points are wrong (" + why + ")";
        }
    }
}

}  // namespace scalecert::internal
